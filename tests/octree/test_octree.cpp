// The octree algorithm, and its lifted fallback, against the brute-force reference: identical tie sets and
// printed coordinates on thousands of random and degenerate inputs, on the small vdrc sets, and for every
// thread count.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>
#include <utility>

#include "reference/brute_force_diagram.h"
#include "support/diagram_checks.h"
#include "io/read_sites.h"
#include "octree/lifted_triangulation.h"
#include "octree/octree_diagram.h"
#include "predicates/predicate_counter.h"
#include "reference/site_generators.h"
#include "support/time_limit.h"

using namespace apollonius;
using namespace apollonius::testing;

namespace {

// Same vertices (tie sets and printed coordinates, in order), same hidden sites, same sites without vertex.
void check_same(const Diagram& octree, const Diagram& reference) {
  REQUIRE(octree.vertices.size() == reference.vertices.size());
  for (std::size_t i = 0; i < octree.vertices.size(); ++i) {
    CAPTURE(i);
    CHECK(octree.vertices[i].tie_set == reference.vertices[i].tie_set);
    CHECK(octree.vertices[i].rounded == reference.vertices[i].rounded);
  }
  CHECK(octree.hidden.size() == reference.hidden.size());
  CHECK(octree.sites_without_vertex == reference.sites_without_vertex);
}

// With the regions asked for (the whole diagram), step 5 never runs at once: the octree's own output.
void check_regions_keep_the_octree(const std::vector<Site>& sites, const Diagram& octree) {
  Octree_statistics statistics;
  Octree_regions regions;
  Octree_options with_regions{1, &statistics};
  with_regions.regions = &regions;
  check_same(octree_diagram(sites, with_regions), octree);
  CHECK_FALSE(statistics.lifted_fallback);
}

// APOLLONIUS_DIFFERENTIAL_SEEDS and APOLLONIUS_DIFFERENTIAL_MAX_SITES raise the number of seeds per family
// and the largest input (default 40 sites) for long runs; APOLLONIUS_DIFFERENTIAL_FAMILIES (names separated
// by commas) runs only those families, so that a long run can be split across processes.
std::uint64_t from_environment(const char* name, std::uint64_t default_value) {
  if (const char* env = std::getenv(name)) return std::strtoull(env, nullptr, 10);
  return default_value;
}

bool family_selected(const std::string& name) {
  const char* env = std::getenv("APOLLONIUS_DIFFERENTIAL_FAMILIES");
  if (env == nullptr) return true;
  const std::string list = std::string(",") + env + ",";
  return list.find("," + name + ",") != std::string::npos;
}

// Vertices that nearly coincide make the brute force reach its exact stage everywhere, and sites 2^900
// times apart need about 2^900 times finer boxes; sites tied at one point or along a circle make every
// conflict test of the brute force exact: fewer seeds of those families per CI run.
std::uint64_t seeds_for(Site_family family) {
  const bool slow = family == Site_family::lattice_noise || family == Site_family::wide_range;
  const bool tied = family == Site_family::sphere_tangent || family == Site_family::circle_tangent ||
                    family == Site_family::two_spheres || family == Site_family::shells ||
                    family == Site_family::circle || family == Site_family::circle_mixed;
  return from_environment("APOLLONIUS_DIFFERENTIAL_SEEDS", slow || tied ? 50 : 500);
}

// The first seed of every family: APOLLONIUS_DIFFERENTIAL_FIRST_SEED (default 1), so that a long run can
// go on where an earlier one stopped.
std::uint64_t first_seed() {
  return std::max<std::uint64_t>(1, from_environment("APOLLONIUS_DIFFERENTIAL_FIRST_SEED", 1));
}

// CPU seconds one input may take, octree or brute force: APOLLONIUS_DIFFERENTIAL_TIME_LIMIT (default 60, so
// that the sanitizer builds pass; the long runs set 1). Past it the program names the input and exits 124.
double time_limit() { return seconds_from_environment("APOLLONIUS_DIFFERENTIAL_TIME_LIMIT", 60); }
// The brute force's limit: APOLLONIUS_DIFFERENTIAL_REFERENCE_TIME_LIMIT (default 10 times the octree's). Its
// O(n^5) exact tests on 60 sites tied along one circle take more than 10 s, so the long runs raise it.
double reference_time_limit() {
  return seconds_from_environment("APOLLONIUS_DIFFERENTIAL_REFERENCE_TIME_LIMIT", 10 * time_limit());
}
// Octree CPU times above APOLLONIUS_DIFFERENTIAL_REPORT_OVER seconds (default: none) are listed, so that a long
// run with a loose limit still names every slow input.
double report_over() { return seconds_from_environment("APOLLONIUS_DIFFERENTIAL_REPORT_OVER", 1e300); }

// The brute force on the sites of the family. The families scaled by 2^+-300 are the uniform family
// scaled: their reference is the uniform family's diagram, scaled (exact: every value stays a normal
// double), because the brute force on them reaches its exact stage for every predicate. Scaling
// invariance itself is tested in test_invariance.
Diagram reference_diagram(Site_family family, std::size_t n, std::uint64_t seed) {
  if (family != Site_family::scaled_up && family != Site_family::scaled_down)
    return brute_force_diagram(generate_sites(family, n, seed));
  Diagram reference = brute_force_diagram(generate_sites(Site_family::uniform, n, seed));
  const int exponent = family == Site_family::scaled_up ? 300 : -300;
  for (Diagram_vertex& v : reference.vertices)
    for (double& x : v.rounded) x = std::ldexp(x, exponent);
  return reference;
}

}  // namespace

TEST_CASE("octree equals brute force on every generator family") {
  const std::uint64_t max_sites = std::max<std::uint64_t>(5, from_environment("APOLLONIUS_DIFFERENTIAL_MAX_SITES", 40));
  std::size_t inputs = 0, vertices = 0, expected_inputs = 0;
  std::pair<double, std::string> slowest, slowest_lifted;  // the octree's and the lifted's longest time, and its input
  for (const std::string& name : site_family_names()) {
    if (!family_selected(name)) continue;
    const Site_family family = site_family_from_name(name);
    const std::uint64_t seeds = seeds_for(family);
    expected_inputs += seeds;
    for (std::uint64_t seed = first_seed(); seed < first_seed() + seeds; ++seed) {
      const std::size_t n = 5 + (seed * 7919) % (max_sites - 4);  // 5 to max_sites sites
      CAPTURE(name);
      CAPTURE(seed);
      CAPTURE(n);
      const std::vector<Site> sites = generate_sites(family, n, seed);
      const std::string input = "generate " + name + " --n " + std::to_string(n) + " --seed " + std::to_string(seed);
      Input_time_limit reference_limit(reference_time_limit(), input + " (brute force)");
      const Diagram reference = reference_diagram(family, n, seed);
      reference_limit.stop();
      Input_time_limit octree_limit(time_limit(), input + " (octree)");
      Octree_options octree_only;
      // These inputs are small: the defaults would take step 5 at once, or past the seed candidates' budget
      // on deep ones.
      octree_only.never_lifted_at_once();
      octree_only.seed_candidate_budget = std::numeric_limits<std::size_t>::max();
      const Diagram octree = octree_diagram(sites, octree_only);
      octree_limit.stop();
      const double seconds = octree_limit.cpu_seconds();
      if (seconds > report_over()) MESSAGE("octree " << seconds << " CPU s: " << input);
      slowest = std::max(slowest, std::make_pair(seconds, input));
      check_same(octree, reference);
      // The lifted fallback (octree_diagram.h, step 5) on every input, not only where the octree gives up.
      Octree_options lifted_only;
      lifted_only.box_budget = 0;
      Octree_statistics lifted_statistics;
      lifted_only.statistics = &lifted_statistics;
      Input_time_limit lifted_limit(time_limit(), input + " (lifted)");
      const Diagram lifted = octree_diagram(sites, lifted_only);
      lifted_limit.stop();
      const double lifted_seconds = lifted_limit.cpu_seconds();
      if (lifted_seconds > report_over()) MESSAGE("lifted " << lifted_seconds << " CPU s: " << input);
      slowest_lifted = std::max(slowest_lifted, std::make_pair(lifted_seconds, input));
      if (sites.size() - lifted.hidden.size() >= 4) CHECK(lifted_statistics.lifted_fallback);  // else no step runs
      check_same(lifted, reference);
      ++inputs;
      vertices += reference.vertices.size();
    }
  }
  MESSAGE(inputs << " inputs of 5 to " << max_sites << " sites, " << vertices << " vertices, all equal; slowest octree "
                 << slowest.first << " CPU s: " << slowest.second << "; slowest lifted " << slowest_lifted.first
                 << " CPU s: " << slowest_lifted.second);
  CHECK(inputs == expected_inputs);
  CHECK(inputs >= std::min<std::uint64_t>(5000, expected_inputs));
}

// A tie-point leaf (box_refinement.cpp) whose star gives up is decided from its candidates' lifted
// triangulation; stars give up only on large inputs (hundreds of balls on concentric shells), so here every
// tie-point leaf takes the triangulation at once, on the families that tie many sites at one point.
TEST_CASE("tie-point leaves decided from their lifted triangulation equal the brute force") {
  const std::uint64_t max_sites = std::max<std::uint64_t>(5, from_environment("APOLLONIUS_DIFFERENTIAL_MAX_SITES", 40));
  std::size_t inputs = 0, lifted_leaves = 0;
  for (const Site_family family : {Site_family::cospherical, Site_family::lattice, Site_family::sphere_tangent,
                                   Site_family::circle_tangent, Site_family::two_spheres, Site_family::shells}) {
    const std::string name = name_of(family);
    if (!family_selected(name)) continue;
    for (std::uint64_t seed = first_seed(); seed < first_seed() + seeds_for(family) / 2; ++seed) {
      const std::size_t n = 5 + (seed * 7919) % (max_sites - 4);
      const std::string input = "generate " + name + " --n " + std::to_string(n) + " --seed " + std::to_string(seed);
      CAPTURE(input);
      const std::vector<Site> sites = generate_sites(family, n, seed);
      Input_time_limit reference_limit(reference_time_limit(), input + " (brute force)");
      const Diagram reference = reference_diagram(family, n, seed);
      reference_limit.stop();
      Input_time_limit octree_limit(time_limit(), input + " (octree, no tie-point stars)");
      Octree_statistics statistics;
      Octree_options no_stars;
      no_stars.octree_alone();
      no_stars.tie_point_stars = false;
      no_stars.statistics = &statistics;
      check_same(octree_diagram(sites, no_stars), reference);
      lifted_leaves += statistics.lifted_leaves;
      ++inputs;
    }
  }
  MESSAGE(inputs << " inputs, " << lifted_leaves << " leaves decided from their lifted triangulation, all equal");
  if (inputs > 0) CHECK(lifted_leaves > 0);
}

TEST_CASE("octree equals brute force on the small vdrc sets") {
  for (const char* name : {"ANO1_0CONNECT", "ANO3_3CONNECT", "Vis_I_10", "Vis_II_5", "Vis_III_5", "Vis_V_20", "Vis_VII_20"}) {
    CAPTURE(name);
    const std::vector<Site> sites = read_sites(std::string(APOLLONIUS_TEST_DATA) + "/vdrc/" + name + ".txt", {}).sites;
    Octree_options octree_only;
    octree_only.never_lifted_at_once();
    const Diagram octree = octree_diagram(sites, octree_only);
    validate_diagram(octree, sites);
    const Diagram reference = brute_force_diagram(sites);
    check_same(octree, reference);
    Octree_options lifted_only;
    lifted_only.box_budget = 0;
    check_same(octree_diagram(sites, lifted_only), reference);
  }
}

TEST_CASE("the output does not depend on the number of threads") {
  const std::vector<Site> sites = read_sites(std::string(APOLLONIUS_TEST_DATA) + "/pept.balls", {}).sites;
  Octree_options octree_only{1};
  octree_only.never_lifted_at_once();  // pept has 107 sites
  const Diagram one = octree_diagram(sites, octree_only);
  validate_diagram(one, sites);
  for (int threads : {2, 3, 8}) {
    CAPTURE(threads);
    octree_only.threads = threads;
    check_same(octree_diagram(sites, octree_only), one);
    check_same(octree_diagram(sites, Octree_options{threads}), one);
    Octree_options lifted_only{threads};
    lifted_only.box_budget = 0;
    check_same(octree_diagram(sites, lifted_only), one);
  }
}

// The octree's budget (octree_diagram.h, step 5): spent, the vertices come from the lifted triangulation,
// the same as the octree's own; with the whole diagram's regions asked for too, which then have no box.
TEST_CASE("the octree turns to the lifted triangulation once its box budget is spent") {
  const std::vector<Site> sites = generate_sites(Site_family::circle_tangent, 60, 3);
  Octree_statistics unlimited_statistics;
  Octree_options unlimited{1, &unlimited_statistics};
  unlimited.octree_alone();
  const Diagram octree = octree_diagram(sites, unlimited);
  CHECK_FALSE(unlimited_statistics.lifted_fallback);
  REQUIRE(unlimited_statistics.boxes > 4096);
  for (int threads : {1, 2}) {
    CAPTURE(threads);
    Octree_statistics statistics;
    Octree_options budgeted{threads, &statistics};
    budgeted.box_budget = 2048;
    budgeted.seed_candidate_budget = std::numeric_limits<std::size_t>::max();
    budgeted.never_lifted_at_once();
    check_same(octree_diagram(sites, budgeted), octree);
    CHECK(statistics.lifted_fallback);
    CHECK_FALSE(statistics.lifted_small_input);
    CHECK(statistics.boxes >= 2048);
    CHECK(statistics.lifted_quadruples > 0);

    Octree_statistics with_regions_statistics;
    Octree_regions regions;
    Octree_options with_regions{threads, &with_regions_statistics};
    with_regions.box_budget = 2048;
    with_regions.regions = &regions;
    check_same(octree_diagram(sites, with_regions), octree);
    CHECK(with_regions_statistics.lifted_fallback);
    CHECK(regions.lifted_fallback);
    CHECK_FALSE(regions.has_octree);
    CHECK(regions.boxes.empty());
    CHECK(regions.escaping.size() == sites.size() - octree.hidden.size());
    REQUIRE(regions.far_sets.size() == 1);
    CHECK(regions.far_sets[0] == regions.escaping);
    // The vertex-free search takes the fallback's triangulation of that far set instead of building it again.
    REQUIRE(regions.lifts != nullptr);
    CHECK(regions.lifts->sites == regions.far_sets[0]);
    CHECK(regions.lifts->quadruples.size() == with_regions_statistics.lifted_quadruples);

    Octree_regions unlimited_regions;
    Octree_options unlimited_with_regions{threads};
    unlimited_with_regions.regions = &unlimited_regions;
    unlimited_with_regions.octree_alone();
    check_same(octree_diagram(sites, unlimited_with_regions), octree);
    CHECK(unlimited_regions.has_octree);
    CHECK_FALSE(unlimited_regions.lifted_fallback);
    CHECK(unlimited_regions.lifts == nullptr);
    CHECK_FALSE(unlimited_regions.boxes.empty());
  }
}

// One ball far from a cluster: the seed boxes between them are far larger than the cluster's spacing. The
// witnesses of the paper's distance propagation, which reached such boxes one event at a time, let
// hundreds of the cluster's sites into each (over 128 per site here; 6,000 per site beside BALL_SMALL_10000);
// each box's nearest sites (candidate_propagation.h, pass 1) keep them few, and the octree refines. The
// budget of seed candidates (octree_diagram.h, step 5) stays as a bound: past it, the lifted triangulation
// gives the octree's output, before any box is refined; regions asked for then have no box.
TEST_CASE("a ball far from a cluster keeps its seed candidates few; past their budget, the lifted triangulation") {
  std::vector<Site> sites = generate_sites(Site_family::uniform, 1000, 3);
  sites.push_back({1e6, 0, 0, 1});
  Input_time_limit limit(time_limit(), "uniform 1000 and a ball 1e6 away");
  Octree_options lifted_options;
  lifted_options.box_budget = 0;  // --algorithm lifted
  const Diagram lifted = octree_diagram(sites, lifted_options);
  validate_diagram(lifted, sites);
  const std::size_t active = sites.size() - lifted.hidden.size();
  REQUIRE(active > Octree_options{}.lifted_at_most_sites);
  for (int threads : {1, 2}) {
    CAPTURE(threads);
    Octree_statistics statistics;
    Octree_options automatic{threads, &statistics};
    check_same(octree_diagram(sites, automatic), lifted);
    CHECK_FALSE(statistics.lifted_fallback);
    CHECK(statistics.boxes > 0);
    CHECK(statistics.seed_candidates <= 16 * active);

    for (const std::size_t budget : {std::size_t{1000}, statistics.seed_candidates - 1}) {
      CAPTURE(budget);
      Octree_statistics budgeted_statistics;
      Octree_options budgeted{threads, &budgeted_statistics};
      budgeted.seed_candidate_budget = budget;
      check_same(octree_diagram(sites, budgeted), lifted);
      CHECK(budgeted_statistics.lifted_fallback);
      CHECK(budgeted_statistics.lifted_seed_candidates);
      CHECK_FALSE(budgeted_statistics.lifted_deep_input);
      CHECK(budgeted_statistics.boxes == 0);  // the propagation stopped before any box was refined

      Octree_statistics with_regions_statistics;
      Octree_regions regions;
      Octree_options with_regions{threads, &with_regions_statistics};
      with_regions.regions = &regions;
      with_regions.seed_candidate_budget = budget;
      check_same(octree_diagram(sites, with_regions), lifted);
      CHECK(with_regions_statistics.lifted_fallback);
      CHECK(with_regions_statistics.lifted_seed_candidates);
      CHECK(regions.lifted_fallback);
    }
  }
  // The same on an ordinary input; the box budget's reason stays apart.
  const std::vector<Site> uniform = generate_sites(Site_family::uniform, 1000, 4);
  Octree_options octree_only;
  octree_only.never_lifted_at_once();
  const Diagram expected = octree_diagram(uniform, octree_only);
  Octree_statistics statistics;
  Octree_options budgeted{1, &statistics};
  budgeted.never_lifted_at_once();
  budgeted.seed_candidate_budget = 1000;
  check_same(octree_diagram(uniform, budgeted), expected);
  CHECK(statistics.lifted_seed_candidates);
  limit.stop();
}

// The seed candidates per active site of inputs that the octree suits: far below the budget's 128.
TEST_CASE("ordinary inputs stay far below the seed candidates' budget") {
  for (const char* name : {"uniform", "lattice", "coplanar", "collinear", "nested", "tangent", "mixed-sign",
                           "duplicates", "cospherical", "lattice-noise", "far-vertices", "shells"}) {
    CAPTURE(name);
    const std::vector<Site> sites = generate_sites(site_family_from_name(name), 2000, 7);
    Octree_statistics statistics;
    Octree_options automatic{1, &statistics};
    const Diagram diagram = octree_diagram(sites, automatic);
    const std::size_t active = sites.size() - diagram.hidden.size();
    CAPTURE(statistics.seed_candidates);
    CAPTURE(active);
    CHECK_FALSE(statistics.lifted_seed_candidates);
    if (!statistics.lifted_fallback) CHECK(statistics.seed_candidates <= 64 * active);
  }
}

// Small inputs (octree_diagram.h, step 5): at most lifted_at_most_sites active sites go to the lifted
// triangulation at once, with the octree's output; not with regions, nor on the floating path.
TEST_CASE("small inputs go to the lifted triangulation at once") {
  const std::size_t limit = Octree_options{}.lifted_at_most_sites;
  REQUIRE(limit > 20);
  for (const std::size_t n : {std::size_t{20}, limit, limit + 1, limit + 150}) {
    CAPTURE(n);
    const std::vector<Site> sites = generate_sites(Site_family::uniform, n, 5);
    Octree_statistics octree_statistics;
    Octree_options octree_only{1, &octree_statistics};
    octree_only.octree_alone();
    const Diagram octree = octree_diagram(sites, octree_only);
    const std::size_t active = sites.size() - octree.hidden.size();
    CHECK_FALSE(octree_statistics.lifted_fallback);

    Octree_statistics statistics;
    const Diagram automatic = octree_diagram(sites, Octree_options{1, &statistics});
    check_same(automatic, octree);
    CHECK(statistics.lifted_fallback == (active <= limit));
    CHECK(statistics.lifted_small_input == (active <= limit));
    CHECK(statistics.boxes == (active <= limit ? 0 : octree_statistics.boxes));

    check_regions_keep_the_octree(sites, octree);

    Octree_statistics floating_statistics;
    octree_diagram(sites, Octree_options{1, &floating_statistics, Arithmetic::floating});
    CHECK_FALSE(floating_statistics.lifted_fallback);
  }
}

// Sites of one weight (octree_diagram.h, step 5; equal_weight_lifts.h): at any size straight to the
// Delaunay triangulation of the centres, with the octree's output, for every thread count; ties of many
// sites (lattice cubes, a sphere of integer points), coplanar centres and repeats included.
TEST_CASE("sites of one weight go to the Delaunay triangulation at once, at any size") {
  const auto with_weight = [](std::vector<Site> sites, double w) {
    for (Site& s : sites) s.w = w;
    return sites;
  };
  std::vector<std::pair<std::string, std::vector<Site>>> inputs = {
      {"equal-weights 300", generate_sites(Site_family::equal_weights, 300, 2)},
      {"equal-weights 3000", generate_sites(Site_family::equal_weights, 3000, 3)},
      {"lattice 2000, w = 1.5", with_weight(generate_sites(Site_family::lattice, 2000, 4), 1.5)},
      {"lattice-noise 1000, w = 0.7", with_weight(generate_sites(Site_family::lattice_noise, 1000, 5), 0.7)},
      {"coplanar 400, w = 2", with_weight(generate_sites(Site_family::coplanar, 400, 6), 2)},
      {"duplicates 400, w = 1", with_weight(generate_sites(Site_family::duplicates, 400, 7), 1)},
      {"scaled-down 500, w = 2^-300",
       with_weight(generate_sites(Site_family::scaled_down, 500, 8), std::ldexp(1.0, -300))},
      {"wide-range 300, w = -3", with_weight(generate_sites(Site_family::wide_range, 300, 9), -3)}};
  // Every integer point at distance 5 from the origin (30 of them) and a 7^3 cube lattice: one vertex
  // holds all 30, and every lattice cube's eight corners tie at its centre.
  std::vector<Site> sphere_and_lattice;
  for (int x = -5; x <= 5; ++x)
    for (int y = -5; y <= 5; ++y)
      for (int z = -5; z <= 5; ++z)
        if (x * x + y * y + z * z == 25) sphere_and_lattice.push_back({double(x), double(y), double(z), 1});
  for (int x = 0; x < 7; ++x)
    for (int y = 0; y < 7; ++y)
      for (int z = 0; z < 7; ++z) sphere_and_lattice.push_back({20.0 + 2 * x, 2.0 * y, 2.0 * z, 1});
  inputs.emplace_back("integer sphere of radius 5 and a 7^3 lattice", sphere_and_lattice);
  for (const auto& [name, sites] : inputs) {
    CAPTURE(name);
    Input_time_limit limit(time_limit(), name);
    Octree_options octree_only;
    octree_only.never_lifted_at_once();
    const Diagram octree = octree_diagram(sites, octree_only);
    validate_diagram(octree, sites);
    const std::size_t active = sites.size() - octree.hidden.size();
    for (int threads : {1, 2}) {
      CAPTURE(threads);
      Octree_statistics statistics;
      const Diagram automatic = octree_diagram(sites, Octree_options{threads, &statistics});
      check_same(automatic, octree);
      const bool small = active <= Octree_options{}.lifted_at_most_sites;
      CHECK(statistics.lifted_fallback == (active >= 4));
      CHECK(statistics.lifted_one_weight == (active >= 4 && !small));
      CHECK(statistics.boxes == 0);
    }
    limit.stop();
    if (name.rfind("integer sphere", 0) == 0) {
      const auto all_thirty = std::find_if(octree.vertices.begin(), octree.vertices.end(),
                                           [](const Diagram_vertex& v) { return v.tie_set.size() == 30; });
      CHECK(all_thirty != octree.vertices.end());
      CHECK(std::count_if(octree.vertices.begin(), octree.vertices.end(),
                          [](const Diagram_vertex& v) { return v.tie_set.size() == 8; }) >= 6 * 6 * 6);
    }
  }
}

// Every integer point at distance 85 from the origin, 510 sites of one weight: one vertex, at the origin,
// holds them all. Each range of cells decided it again with a conflict test per site (510 per range, each
// exact), 30 s for 2,160 such sites; the cells of one sphere are now found across marked facets and decided
// once per range, with no conflict test.
TEST_CASE("sites of one weight all on one sphere: one vertex holds them all") {
  std::vector<Site> sites;
  for (int x = -85; x <= 85; ++x)
    for (int y = -85; y <= 85; ++y)
      for (int z = -85; z <= 85; ++z)
        if (x * x + y * y + z * z == 85 * 85) sites.push_back({double(x), double(y), double(z), 0.5});
  REQUIRE(sites.size() == 510);
  for (int threads : {1, 2}) {
    CAPTURE(threads);
    Input_time_limit limit(time_limit(), "510 integer points on one sphere");
    Octree_statistics statistics;
    const Diagram diagram = octree_diagram(sites, Octree_options{threads, &statistics});
    limit.stop();
    CHECK(statistics.lifted_one_weight);
    REQUIRE(diagram.vertices.size() == 1);
    CHECK(diagram.vertices[0].tie_set.size() == 510);
    CHECK(diagram.vertices[0].rounded == std::array<double, 4>{0, 0, 0, 84.5});
    validate_diagram(diagram, sites);
  }
}

// Fixed: the lifted triangulation's quadruples went to TBB's own split, about 64 ranges with one thread, and
// each range that meets a vertex of k tied sites finds its tie set again at O(k) conflict tests: the two
// tie points of these 1,000 balls took 127,488 exact conflict tests. Now at most 8 ranges per thread.
TEST_CASE("regression: lifted_tie_sets_once_per_range_two_spheres_1000_2") {
  const std::vector<Site> sites = generate_sites(Site_family::two_spheres, 1000, 2);
  for (int threads : {1, 2}) {
    CAPTURE(threads);
    Input_time_limit limit(time_limit(), "two-spheres 1000 seed 2");
    Octree_options options{threads};
    options.box_budget = 0;  // --algorithm lifted
    reset_predicate_statistics();
    const Diagram diagram = octree_diagram(sites, options);
    std::uint64_t tests = 0;
    for (const Predicate_statistics& p : predicate_statistics())
      if (p.name == "vertex_conflict") tests = p.evaluations;
    REQUIRE(diagram.vertices.size() == 2);
    CHECK(diagram.vertices[0].tie_set.size() == 1000);
    CHECK(diagram.vertices[1].tie_set.size() == 1000);
    CHECK(tests <= static_cast<std::uint64_t>(2 * 1000 * 8 * threads));
  }
}

// Sites from 1e-260 to 4e265 (a cluster 4e-9 wide beside balls of radius 1 and out to 4e265): the conflict
// and hidden tests overflow plain intervals or cancel to the cluster's width relative to a far origin; the
// wide stages, taken from the vertex's site nearest the tested one, decide them (vertex_conflict.h).
TEST_CASE("sites from 1e-260 to 4e265: the wide stages decide the conflict and hidden tests") {
  const std::vector<Site> sites =
      read_sites(std::string(APOLLONIUS_TEST_DATA) +
                     "/regression/far_field_enumerated_39k_quadruples_of_34_escaping_sites_to_4e265.balls", {})
          .sites;
  reset_predicate_statistics();
  const Diagram diagram = octree_diagram(sites, Octree_options{1});
  const std::vector<Predicate_statistics> statistics = predicate_statistics();
  const auto of = [&](const std::string& name) {
    const auto p = std::find_if(statistics.begin(), statistics.end(),
                                [&](const Predicate_statistics& s) { return s.name == name; });
    REQUIRE(p != statistics.end());
    return *p;
  };
  CHECK(of("is_hidden").evaluations > 100);
  CHECK(of("is_hidden").exact_stages == 0);  // 136 of 136 before the wide stage
  CHECK(of("vertex_conflict").evaluations > 4000);
  CHECK(of("vertex_conflict").exact_stages <= 10);  // 1,147 before
  CHECK(of("vertices_of").exact_stages <= 200);     // 297 before the closest-pair retry
  check_same(diagram, brute_force_diagram(sites));
}

// Deep inputs (octree_diagram.h, step 5; deep_clusters.h): a cluster beside a far ball, and sites from
// 1e-260 to 1e265, go to the lifted triangulation at once, with the octree's output, for every thread count;
// not with regions, nor when the octree is asked for.
TEST_CASE("deep inputs go to the lifted triangulation at once") {
  std::vector<Site> cluster_and_far_ball = generate_sites(Site_family::uniform, 700, 14);
  cluster_and_far_ball.push_back({-3e13, 2e13, 1e13, 2});
  const std::vector<std::pair<std::string, std::vector<Site>>> inputs = {
      {"wide-range 600", generate_sites(Site_family::wide_range, 600, 4)},
      {"uniform 700 and a ball 3e13 away", cluster_and_far_ball}};
  for (const auto& [name, sites] : inputs) {
    CAPTURE(name);
    Input_time_limit limit(time_limit(), name);
    Octree_statistics octree_statistics;
    Octree_options octree_only{1, &octree_statistics};
    octree_only.octree_alone();
    const Diagram octree = octree_diagram(sites, octree_only);
    validate_diagram(octree, sites);
    REQUIRE(sites.size() - octree.hidden.size() > Octree_options{}.lifted_at_most_sites);
    CHECK_FALSE(octree_statistics.lifted_deep_input);
    for (int threads : {1, 2}) {
      CAPTURE(threads);
      Octree_statistics statistics;
      check_same(octree_diagram(sites, Octree_options{threads, &statistics}), octree);
      CHECK(statistics.lifted_deep_input);
      CHECK_FALSE(statistics.lifted_small_input);
      CHECK(statistics.boxes == 0);
    }
    check_regions_keep_the_octree(sites, octree);
    limit.stop();
  }
}
