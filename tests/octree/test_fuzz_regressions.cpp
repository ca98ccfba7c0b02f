// Inputs that found defects of the octree (most by fuzz_vertices, tests/fuzz), kept in tests/data/regression
// and run through the normal build: the octree must give the brute force's diagram on each.
#include <doctest/doctest.h>

#include <cstdint>
#include <limits>
#include <string>

#include "reference/brute_force_diagram.h"
#include "support/diagram_checks.h"
#include "io/read_sites.h"
#include "octree/octree_diagram.h"
#include "predicates/predicate_counter.h"
#include "support/time_limit.h"

using namespace apollonius;
using namespace apollonius::testing;

namespace {

void check_same(const Diagram& octree, const Diagram& reference) {
  REQUIRE(octree.vertices.size() == reference.vertices.size());
  for (std::size_t i = 0; i < octree.vertices.size(); ++i) {
    CAPTURE(i);
    CHECK(octree.vertices[i].tie_set == reference.vertices[i].tie_set);
    CHECK(octree.vertices[i].rounded == reference.vertices[i].rounded);
  }
  CHECK(octree.sites_without_vertex == reference.sites_without_vertex);
}

// The octree with no box budget and never straight to step 5 (so that its own rules are what the
// regression tests), and with the defaults (octree_diagram.h, step 5: the lifted triangulation at once
// for at most 256 active sites, else past the automatic budget), both against the brute force. Returns
// the statistics of the first, for the regressions that were about the octree's amount of work.
Octree_statistics check_octree_equals_brute_force(const std::string& name, const std::string& folder = "regression") {
  CAPTURE(name);
  const std::vector<Site> sites = read_sites(std::string(APOLLONIUS_TEST_DATA) + "/" + folder + "/" + name, {}).sites;
  const Diagram reference = brute_force_diagram(sites);
  validate_diagram(reference, sites);
  Octree_statistics statistics;
  Octree_options unlimited;
  unlimited.statistics = &statistics;
  unlimited.octree_alone();
  check_same(octree_diagram(sites, unlimited), reference);
  CHECK_FALSE(statistics.lifted_fallback);
  check_same(octree_diagram(sites), reference);
  return statistics;
}

// For the regressions about the octree's boxes: equal to the brute force within `seconds` (or
// APOLLONIUS_REGRESSION_TIME_LIMIT), with fewer than `boxes` boxes.
void check_octree_boxes_below(const std::string& name, std::size_t boxes, double seconds) {
  Input_time_limit limit(seconds_from_environment("APOLLONIUS_REGRESSION_TIME_LIMIT", seconds), name);
  const Octree_statistics statistics = check_octree_equals_brute_force(name);
  CHECK(statistics.boxes < boxes);
  MESSAGE(name << ": " << statistics.boxes << " boxes, " << limit.stop() << " s");
}

}  // namespace

// Fixed by running the octree on sites scaled to a moderate extent (scale_normalization.h).
TEST_CASE("regression: octree_far_field_stalls_beyond_2e154") {
  check_octree_equals_brute_force("octree_far_field_stalls_beyond_2e154.balls");
}

// Fixed by deciding each quadruple of the far field once, and by stopping patches that stagnate.
TEST_CASE("regression: octree_far_field_slow_for_far_vertices") {
  check_octree_equals_brute_force("octree_far_field_slow_for_far_vertices.balls");
}

// The octree's root box would exceed the double range; scaled down by 2^1023 it does not.
TEST_CASE("regression: octree_root_box_beyond_double_range") {
  check_octree_equals_brute_force("octree_root_box_beyond_double_range.balls");
}

// fuzz_vertices, with CGAL's assertions on: sites 1e207 (or 5e289) and 1e-323 apart made the far field's
// bound q_j overflow to inf, and Interval(inf) breaks Interval_nt's precondition. Such a bound now removes
// nothing.
TEST_CASE("regression: far_field_spread_overflow") {
  check_octree_equals_brute_force("far_field_spread_overflow_at_1e207.balls");
  check_octree_equals_brute_force("far_field_spread_overflow_at_5e289.balls");
}

// A few small balls and one far away: the removal tests could not tell the small balls apart in boxes far
// from them, and the octree refined hundreds of thousands of boxes (minutes for the fuzz input). They now
// take about a thousand boxes, as the same balls without the far one do.
TEST_CASE("regression: octree_boxes_explode_for_far_balls") {
  for (const char* name : {"octree_boxes_explode_for_ball_at_1e168.balls", "octree_boxes_explode_for_cluster_and_ball_1e20_away.balls",
                           "octree_boxes_explode_for_cluster_and_ball_1e300_away.balls"}) {
    const Octree_statistics statistics = check_octree_equals_brute_force(name);
    CAPTURE(name);
    CHECK(statistics.boxes < 5000);
  }
}

// 20 small balls and two balls 1e9 away: the far field measured its bound from the centre O of the site
// box, which could not tell the small balls apart seen from O, so its patches refined to the last depth and
// enumerated 5,985 distinct quadruples (12 s, 1.7 GB). It now bounds from the witness's own centre and tries more
// than one witness: 61 quadruples.
TEST_CASE("regression: far_field_slow_for_cluster_and_two_balls_1e9_away") {
  const Octree_statistics statistics = check_octree_equals_brute_force("far_field_slow_for_cluster_and_two_balls_1e9_away.balls");
  CHECK(statistics.far_field_quadruples < 1000);
}

// Balls on one circle with mixed weights (the differential test's circle-mixed family, seed 270): ties
// at infinity that no patch separates, so the patches enumerated 212,499 quadruples (2 s, 184 MB). The
// far field now takes the 3-faces of the escaping sites' lifted triangulation (lifted_triangulation.h).
TEST_CASE("regression: far_field_enumerated_quadruples_of_circle_mixed_55_270") {
  const Octree_statistics statistics =
      check_octree_equals_brute_force("far_field_enumerated_quadruples_of_circle_mixed_55_270.balls");
  CHECK(statistics.far_field_quadruples < 2000);
}

// Balls on one circle with three weights (the 1,000-seed run's circle-mixed, seed 579): the heaviest tie
// along the circle's axis, and boxes beside the axis halved down to about 0.25 (1.6 million boxes, 1 s).
// A tiny box whose candidates' lifts span a plane is now settled at once, and one whose lifts and power
// lifts span a 3-space (every tie on one line) once its count stops dropping (box_refinement.cpp): 533,428.
TEST_CASE("regression: octree_axis_boxes_circle_mixed_50_579") {
  const Octree_statistics statistics = check_octree_equals_brute_force("octree_axis_boxes_circle_mixed_50_579.balls");
  CHECK(statistics.boxes < 800000);
}

// 49 equal balls on one circle (and two others): 1.8 million boxes beside the axis where the 49 tie, each
// waiting for its count to stop dropping before its lifts were found to span a plane; now 82,168.
TEST_CASE("regression: octree_axis_boxes_circle_51_506") {
  const Octree_statistics statistics = check_octree_equals_brute_force("octree_axis_boxes_circle_51_506.balls");
  CHECK(statistics.boxes < 200000);
}

// Too large for the brute force (C(300, 4) quadruples): every vertex is validated exactly against every
// site, and Voronota finds the same 870 (bench/README.md, certify on Ext_I_Congruent_300).
TEST_CASE("regression: octree_stagnation_enumerated_300_cospherical_sites") {
  const std::vector<Site> sites =
      read_sites(std::string(APOLLONIUS_TEST_DATA) + "/regression/octree_stagnation_enumerated_300_cospherical_sites.balls", {})
          .sites;
  const Diagram octree = octree_diagram(sites);
  validate_diagram(octree, sites);
  CHECK(octree.vertices.size() == 870);
}

// fuzz_vertices: seven small balls with x_i - w_i = 0 for all of them tie to first order seen from far
// along -x, and one ball 1e240 away makes the root box that large. The test that settles stagnant boxes tiny
// against their candidates squared box sizes beyond 1e152 to inf, so those boxes never settled and refined
// for more than ten minutes. About 500 boxes per level of the 800 from 1e240 down to the balls remained
// (397,218) until boxes huge against their candidates were settled (octree_depth_1e6_boxes, below): 746.
TEST_CASE("regression: octree_tiny_box_test_overflowed_beyond_1e152") {
  const Octree_statistics statistics = check_octree_equals_brute_force("octree_tiny_box_test_overflowed_beyond_1e152.balls");
  CHECK(statistics.boxes < 5000);
}

// fuzz_vertices: seven small balls tie to first order seen along -z (z_i - w_i within 5e-16 of 0, two 5e-324
// apart), so their cells run side by side down the -z axis at every scale, and a ball 4e266 away makes the
// root box that large: every level between, 885 of them, refined about 1,800 boxes along the axis (1.6
// million, 1.8 s; 24 s under the sanitizers). A box huge against its candidates' lifts is now settled once
// its count stops dropping (box_refinement.cpp): 7,352. The same for the other input of the depth
// limitation, 8 sites from 5e-324 to 3e180: 1.09 million boxes, now 3,900.
TEST_CASE("regression: octree_depth_1e6_boxes") {
  for (const char* name : {"octree_depth_1e6_boxes_for_7_balls_tied_along_an_axis_and_ball_at_4e266.balls",
                           "octree_depth_1e6_boxes_for_8_sites_from_5e-324_to_3e180.balls"}) {
    Input_time_limit limit(seconds_from_environment("APOLLONIUS_REGRESSION_TIME_LIMIT", 20), name);
    const Octree_statistics statistics = check_octree_equals_brute_force(name);
    CAPTURE(name);
    CHECK(statistics.boxes < 20000);
    MESSAGE(std::string(name) << ": " << statistics.boxes << " boxes, " << limit.stop() << " s");
  }
}

// fuzz_vertices: a dozen sites with subnormal coordinates and some near 1e50. The intervals could not place
// their vertices against the many small boxes near them, and vertex_in_box's exact stage compared in
// Q(sqrt d) each time: 5.5 s and 6.6 s. It now compares the correctly rounded coordinates first (0.7 s, 1.2 s).
TEST_CASE("regression: octree_exact_in_box_slow_for_subnormal_sites") {
  check_octree_equals_brute_force("octree_exact_in_box_slow_for_subnormal_sites.balls");
  check_octree_equals_brute_force("octree_exact_in_box_slow_for_subnormal_sites_2.balls");
}

// fuzz_vertices: sites from 1e-158 to 4e291 refine 1.8 million boxes, and the vertices' intervals, wide
// against the small boxes, failed vertex_in_box 7.7 million times: an exception and an exact stage each,
// 14 s. Once a vertex's rounded point is known, vertex_in_box's static filter decides by it (1.4 s).
// Settling boxes huge against their candidates (octree_depth_1e6_boxes above) took it to 8,122 boxes.
TEST_CASE("regression: octree_in_box_exceptions_for_sites_from_1e-158_to_4e291") {
  const Octree_statistics statistics =
      check_octree_equals_brute_force("octree_in_box_exceptions_for_sites_from_1e-158_to_4e291.balls");
  CHECK(statistics.boxes < 20000);
}

// Issue 21: 13 sites tied at one point (every ball tangent to one sphere; coplanar balls tangent to one
// circle). No box about the tie point ever had 12 or fewer candidates, so none settled, and refinement went
// on to the last binade about the origin: more than 100 s. Such a box is now a tie-point leaf
// (box_refinement.cpp, classify_tie). The time limit makes the old behaviour a failure, not a hang.
TEST_CASE("regression: octree_tie_of_13_sites_never_settled") {
  for (const char* name : {"octree_tie_of_13_sites_never_settled_tangent_to_one_sphere.balls",
                           "octree_tie_of_13_sites_never_settled_coplanar_tangent_to_one_circle.balls"}) {
    Input_time_limit limit(seconds_from_environment("APOLLONIUS_REGRESSION_TIME_LIMIT", 20), name);
    check_octree_equals_brute_force(name);
    MESSAGE(std::string(name) << ": " << limit.stop() << " s");
  }
}

// fuzz_vertices with the 2 s limit, second 30-minute run of 2026-11-28 (after the depth fix): sites from
// 5e-324 to 2e289, a cluster of ten small ones with others at 1e120, 4e159 and 2e289. Exact, but 84,224
// boxes (0.4 s release, over 2 s with sanitizers), most of them between G and a root box 32 times larger.
// With the root box at twice G (octree_diagram.cpp, kFarFieldScale): 6,192.
TEST_CASE("regression: octree_boxes_84k_for_sites_from_5e-324_to_2e289") {
  const Octree_statistics statistics =
      check_octree_equals_brute_force("octree_boxes_84k_for_sites_from_5e-324_to_2e289.balls");
  CHECK(statistics.boxes < 20000);
}

// fuzz_vertices with the 2 s limit, 2026-11-28 (third stop): 11 sites from 5e-324 to 9e303, whose far field
// failed the lifted triangulation's condition of then, so its patches recorded quadruples: C(k, 4) copies
// at every patch of the depth limit, sorted at the end (0.69 s release, 79 MB; over 2 s with the
// sanitizers). Then recorded once per run of equal patches (0.21 s, 12 MB); since 2026-11-30 the lifts'
// 3-faces for any weights (lifted_triangulation.h).
// fuzz_vertices, 2026-11-28 (fourth stop): the octree and the brute force disagreed on a root near 9.7e90.
// The brute force was wrong: enclosing_interval had lost the caller's upward rounding (number_types.cpp),
// so an exact-built vertex's box excluded the vertex (test_vertices_of has the predicate-level tests).
TEST_CASE("regression: brute_force_vertex_at_9e90_from_lost_rounding") {
  check_octree_equals_brute_force("brute_force_vertex_at_9e90_from_lost_rounding.balls");
}

TEST_CASE("regression: octree_far_field_sorts_copies_for_11_sites_from_5e-324_to_9e303") {
  const char* name = "octree_far_field_sorts_copies_for_11_sites_from_5e-324_to_9e303.balls";
  Input_time_limit limit(seconds_from_environment("APOLLONIUS_REGRESSION_TIME_LIMIT", 20), name);
  const Octree_statistics statistics = check_octree_equals_brute_force(name);
  CHECK(statistics.far_field_quadruples < 210);  // 70 of the C(10, 4) quadruples of the 10 escaping sites
  MESSAGE(std::string(name) << ": " << statistics.far_field_quadruples << " far-field quadruples, " << limit.stop() << " s");
}

// fuzz_vertices with the 2 s limit, 2026-11-28 (fifth stop): a ball far away whose weight nearly equals
// its distance, so that its sphere passes near a cluster of small balls (or whose squares leave the double
// tests' range), kept up to 1.7 million boxes for 10 to 12 sites (0.45 to 24 s in release). The plain
// centre values could neither remove it near the cluster nor use it as a witness there, and the cells
// along one axis repeat at every scale. Fixed by the sharp centre value (sharp_centre_value.h) and by
// settling stagnant boxes of at most 12 candidates at any size (box_refinement.cpp): 72 to 984 boxes.
TEST_CASE("regression: octree_boxes_explode_for_huge_sphere_near_cluster") {
  for (int k = 1; k <= 6; ++k)
    check_octree_boxes_below("octree_boxes_explode_for_huge_sphere_near_cluster_" + std::to_string(k) + ".balls", 20000, 20);
}

// fuzz_vertices with the 2 s limit, 2026-11-28 (sixth stop): 11 sites, two of them 1.2e268 away. The far
// field's sibling patches alternate between a few sets of kept sites, and each change recomputed their
// lifts' span and power-lift test: 1,895 exact power_lift_outside_span calls (4.6 s under the sanitizers).
// Each set's span is now remembered (far_field.cpp, span_dimension). Since 2026-11-30 the patches run only
// for the whole diagram's regions, and test the span only (lift_outside_span).
TEST_CASE("regression: far_field_span_recomputed_for_alternating_patches") {
  const char* name = "far_field_span_recomputed_for_alternating_patches.balls";
  check_octree_equals_brute_force(name);
  const std::vector<Site> sites = read_sites(std::string(APOLLONIUS_TEST_DATA) + "/regression/" + name, {}).sites;
  Octree_regions regions;
  Octree_options options;
  options.regions = &regions;
  reset_predicate_statistics();
  octree_diagram(sites, options);
  std::uint64_t span_tests = 0;
  for (const Predicate_statistics& p : predicate_statistics())
    if (p.name == "lift_outside_span" || p.name == "power_lift_outside_span") span_tests += p.evaluations;
  CHECK_FALSE(regions.far_sets.empty());  // the patches ran
  CHECK(span_tests < 1000);  // 163; 4,978 without the remembered spans
  MESSAGE(std::string(name) << ": " << span_tests << " lift-span tests with the regions");
  reset_predicate_statistics();
}

// fuzz_vertices with the 2 s limit, 2026-11-28 (sixth stop, second run): a cluster of sites at 1e-323 to
// 1e-18 and a few balls of size 4 to 5. Along the bisector surface between them the cluster's sites tie to
// first order, and the boxes refined 4 stagnant levels before settling: 27,000 to 31,000 boxes (0.25 to
// 0.3 s in release, up to 4 s under the sanitizers). Settling after 2 levels: 1,286 to 2,061.
TEST_CASE("regression: octree_stagnant_boxes_along_bisector_of_subnormal_cluster") {
  for (const char* name : {"octree_stagnant_boxes_along_bisector_of_subnormal_cluster_1.balls",
                           "octree_stagnant_boxes_along_bisector_of_subnormal_cluster_2.balls"})
    check_octree_boxes_below(name, 5000, 20);
}

// Open (issues 20 and 21; tests/data/open): 12 sites from 5e-324 to 1.6e266, whose exact stages work on
// numbers of about 2,000 bits: 0.31 s in release (header of the file). Checked for its answers only, within
// a limit against hangs.
TEST_CASE("open: exact_stages_on_2000_bit_numbers_for_sites_from_5e-324_to_2e266") {
  const char* name = "exact_stages_on_2000_bit_numbers_for_sites_from_5e-324_to_2e266.balls";
  Input_time_limit limit(seconds_from_environment("APOLLONIUS_REGRESSION_TIME_LIMIT", 60), name);
  const Octree_statistics statistics = check_octree_equals_brute_force(name, "open");
  MESSAGE(std::string(name) << ": " << statistics.boxes << " boxes, " << limit.stop() << " s");
}

// A differential run with the 1 s limit, 2026-11-30 (tenth stop): 34 sites from 7e-260 to 4.5e265, all
// escaping. Where t + w_j >= 0 could not be certified outside the root box, the far field enumerated the
// quadruples of the sites its patches could not separate: 39,557 of the 46,376, 3.0 of 3.2 s in release.
// The lifted triangulation's 3-faces cover the far vertices for any weights (lifted_triangulation.h).
TEST_CASE("regression: far_field_enumerated_39k_quadruples_of_34_escaping_sites_to_4e265") {
  const char* name = "far_field_enumerated_39k_quadruples_of_34_escaping_sites_to_4e265.balls";
  Input_time_limit limit(seconds_from_environment("APOLLONIUS_REGRESSION_TIME_LIMIT", 60), name);
  const Octree_statistics statistics = check_octree_equals_brute_force(name);
  CHECK(statistics.escaping_sites == 34);
  CHECK(statistics.far_field_quadruples < 4000);  // 2,115: the lifts' 3-faces
  MESSAGE(std::string(name) << ": " << statistics.far_field_quadruples << " far-field quadruples, " << limit.stop() << " s");
}

// Differential runs with the 2 s limit (2026-11-28, eighth stop) and the 1 s limit (2026-11-30, tenth
// stop): about a cluster of 19 balls, or of 37, far smaller than the root box (sites to 1e267), the
// refinement repeated one pattern of boxes at every binade, because a box of more than 12 candidates was
// never settled: 244,340 and 439,772 boxes (0.5 and 1.0 s in release). A huge stagnant box of up to 64
// candidates is now decided from their lifted triangulation (box_refinement.cpp): 1,783 and 3,468 boxes.
TEST_CASE("regression: octree boxes about a cluster of more than 12 candidates far smaller than the root") {
  for (const char* name : {"octree_244k_boxes_for_cluster_of_19_and_balls_to_1e267.balls",
                           "octree_440k_boxes_about_cluster_of_37_to_3e266.balls"})
    check_octree_boxes_below(name, 20000, 60);
}

// bench/scaling.sh's tangent families at 1,000 sites (2026-11-30, twelfth stop): balls tangent to one
// circle, all tied at its centre, made the octree's boxes grow far faster than the sites (beside the
// circle): 533,580 boxes for 100 balls, 1.4 million for 200, 11.3 million for these 400 (16.8 s), past
// 120 s for 1,000. Too large for the brute force; the answer is known by construction: the one vertex,
// the circle's centre (3, -2, 3) at distance 1, with all 400 tied. The octree now stops at its budget
// (512 boxes per site) and takes the vertices from the lifted triangulation's 3-faces (octree_diagram.h,
// step 5): 2,968 of them.
TEST_CASE("regression: octree_11m_boxes_for_400_balls_tangent_to_one_circle") {
  const char* name = "octree_11m_boxes_for_400_balls_tangent_to_one_circle.balls";
  Input_time_limit limit(seconds_from_environment("APOLLONIUS_REGRESSION_TIME_LIMIT", 60), name);
  const std::vector<Site> sites = read_sites(std::string(APOLLONIUS_TEST_DATA) + "/regression/" + name, {}).sites;
  REQUIRE(sites.size() == 400);
  for (int threads : {1, 2}) {
    CAPTURE(threads);
    Octree_statistics statistics;
    const Diagram diagram = octree_diagram(sites, Octree_options{threads, &statistics});
    validate_diagram(diagram, sites);
    CHECK(statistics.lifted_fallback);
    CHECK(statistics.boxes <= 512 * 400 + 16384 + 2 * 1024);
    REQUIRE(diagram.vertices.size() == 1);
    CHECK(diagram.vertices[0].tie_set.size() == 400);
    CHECK(diagram.vertices[0].rounded == std::array<double, 4>{3, -2, 3, 1});
  }
  MESSAGE(std::string(name) << ": " << limit.stop() << " s");
}

// bench/scaling.sh (2026-11-30, twelfth stop): balls on concentric shells, hundreds tied at the common
// centre. A tie-point leaf whose star gave up enumerated C(k, 4) quadruples of its tied candidates in one
// box, unseen by the box budget and by the cancellation: past 100 s. Each such quadruple now counts like a
// box, and the lifted fallback takes over. Too large for the brute force: every vertex is validated
// exactly against every site, and the same diagram comes from the lifted triangulation alone.
// The octree alone (`diagram`, which keeps it without a budget) still enumerated C(k, 4) there: past 60 s
// (2026-12-02). Such a leaf is now decided from its candidates' lifted triangulation (box_refinement.cpp),
// and the octree finishes within its budget: `diagram` 2.2 s.
TEST_CASE("regression: octree_tie_point_leaf_enumerates_quadruples_of_2000_balls_in_concentric_shells") {
  const char* name = "octree_tie_point_leaf_enumerates_quadruples_of_2000_balls_in_concentric_shells.balls";
  Input_time_limit limit(seconds_from_environment("APOLLONIUS_REGRESSION_TIME_LIMIT", 120), name);
  const std::vector<Site> sites = read_sites(std::string(APOLLONIUS_TEST_DATA) + "/regression/" + name, {}).sites;
  Octree_statistics statistics;
  const Diagram diagram = octree_diagram(sites, Octree_options{1, &statistics});
  validate_diagram(diagram, sites);
  CHECK_FALSE(statistics.lifted_fallback);
  CHECK(statistics.lifted_leaves > 0);
  CHECK(statistics.boxes <= 512 * sites.size() + 16384 + 1024);
  Octree_options lifted_only;
  lifted_only.box_budget = 0;
  check_same(octree_diagram(sites, lifted_only), diagram);
  CHECK(diagram.vertices.size() == 3117);
  MESSAGE(std::string(name) << ": " << limit.stop() << " s");
}
