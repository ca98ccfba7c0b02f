// The floating path and crosscheck: the float octree agrees with the certified one on generic input; every
// kind of disagreement planted in a copy of the certified diagram is classified as it should be; the
// command exits 0 without disagreements and 1 with.
#include <doctest/doctest.h>

#include <CGAL/FPU.h>

#include <cmath>
#include <string>

#include "reference/brute_force_diagram.h"
#include "support/cli_helpers.h"
#include "certify/coordinate_tolerance.h"
#include "certify/crosscheck.h"
#include "io/read_sites.h"
#include "octree/octree_diagram.h"
#include "reference/site_generators.h"

using namespace apollonius;
using namespace apollonius::testing;

namespace {

std::vector<std::vector<Site_index>> tie_sets(const Diagram& d) {
  std::vector<std::vector<Site_index>> sets;
  for (const Diagram_vertex& v : d.vertices) sets.push_back(v.tie_set);
  return sets;
}

std::size_t count(const Crosscheck& check, Disagreement_kind kind) {
  std::size_t n = 0;
  for (const Disagreement& d : check.disagreements) n += d.kind == kind ? 1 : 0;
  return n;
}

}  // namespace

TEST_CASE("regression: float_far_field_left_rounding_upward") {
  // CGAL's interval sqrt ends in upward rounding; the floating far field used it in round-to-nearest and
  // left the thread rounding upward, under which the certified path's double filters lose their error
  // bounds (found by the Debug build's CGAL check at exit). Lattice noise makes the doubles overflow too.
  for (const std::string family : {"far-vertices", "lattice-noise"}) {
    CAPTURE(family);
    REQUIRE(CGAL::FPU_get_cw() == CGAL_FE_TONEAREST);
    const std::vector<Site> sites = generate_sites(site_family_from_name(family), 40, 1);
    const Diagram floating = octree_diagram(sites, Octree_options{1, nullptr, Arithmetic::floating});
    CHECK(CGAL::FPU_get_cw() == CGAL_FE_TONEAREST);
    CHECK(!floating.vertices.empty());
    for (const Diagram_vertex& v : floating.vertices)
      for (double x : v.rounded) CHECK(!std::isnan(x));
  }
}

// far-vertices is not generic here: its sites are placed symmetrically (see the regression case below).
TEST_CASE("the float path finds the same tie sets as the certified one on generic input") {
  for (const char* family : {"uniform", "equal-weights", "mixed-sign"}) {
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
      CAPTURE(family);
      CAPTURE(seed);
      const std::vector<Site> sites = generate_sites(site_family_from_name(family), 30, seed);
      const Diagram certified = octree_diagram(sites);
      const Diagram floating = octree_diagram(sites, Octree_options{1, nullptr, Arithmetic::floating});
      CHECK(tie_sets(floating) == tie_sets(certified));
      const Crosscheck check = crosscheck(sites, certified, floating, {1e-9, input_scale(sites)});
      CHECK(check.disagreements.empty());
      CHECK(check.agreeing == certified.vertices.size());
    }
  }
}

// A real disagreement, not a planted one. Balls 0, 1 and 2 are equal and symmetric about the z axis, so
// they tie exactly at the octree's dyadic corners on it. The removal test is exact at the corners for a
// witness no larger than the candidate (centre_expansion.h, test (A)); in plain doubles with no margin,
// rounding decides such an exact tie and removes an owner of vertex 0 1 2 19 at (0, 0, -1.5125).
// crosscheck must report it as missing, and the certified diagram must still equal brute force.
TEST_CASE("regression: float_path_removes_tied_site_at_box_corner_on_trisector") {
  const std::vector<Site> sites =
      read_sites(std::string(APOLLONIUS_TEST_DATA) + "/regression/float_path_removes_tied_site_at_box_corner_on_trisector.balls", {})
          .sites;
  const Diagram certified = octree_diagram(sites);
  CHECK(tie_sets(certified) == tie_sets(brute_force_diagram(sites)));
  const Diagram floating = octree_diagram(sites, Octree_options{1, nullptr, Arithmetic::floating});
  const Crosscheck check = crosscheck(sites, certified, floating, {1e-9, input_scale(sites)});
  for (const Disagreement& d : check.disagreements) CHECK(d.kind == Disagreement_kind::missing);
  CHECK(check.agreeing + check.disagreements.size() == certified.vertices.size());
}

TEST_CASE("planted disagreements: dropped, added, moved, and a degenerate vertex with part of its ties") {
  const std::vector<Site> sites = read_sites(std::string(APOLLONIUS_TEST_DATA) + "/pept.balls", {}).sites;
  const Diagram certified = octree_diagram(sites);
  REQUIRE(certified.vertices.size() > 10);
  const Coordinate_tolerance tolerance{1e-9, input_scale(sites)};

  Diagram planted = certified;
  planted.vertices.erase(planted.vertices.begin() + 3);  // missing
  planted.vertices[5].rounded[0] += 1e-6;                // moved
  Diagram_vertex far = planted.vertices[7];              // spurious: a point far away
  far.rounded = {1e6, 1e6, 1e6, 1e6};
  planted.vertices.push_back(far);
  const Crosscheck check = crosscheck(sites, certified, planted, tolerance);
  CHECK(count(check, Disagreement_kind::missing) == 1);
  CHECK(count(check, Disagreement_kind::moved) == 1);
  CHECK(count(check, Disagreement_kind::spurious) == 1);
  CHECK(check.agreeing == certified.vertices.size() - 2);
  REQUIRE(!check.disagreements.empty());
  CHECK(check.disagreements[0].sites == certified.vertices[3].tie_set);

  // Five sites tangent to one sphere (|x| - w = 1): one vertex with all five; a float diagram that names
  // four of them has the point but not the degeneracy.
  const std::vector<Site> cospherical = {{2, 0, 0, 1}, {0, 3, 0, 2}, {0, 0, 4, 3}, {-5, 0, 0, 4}, {0, 0, -2, 1}};
  const Diagram exact = octree_diagram(cospherical);
  Diagram partial = exact;
  std::size_t five = 0;
  for (Diagram_vertex& v : partial.vertices)
    if (v.tie_set.size() == 5) v.tie_set.pop_back(), ++five;
  REQUIRE(five == 1);
  const Crosscheck degenerate = crosscheck(cospherical, exact, partial, {1e-9, input_scale(cospherical)});
  CHECK(count(degenerate, Disagreement_kind::moved) == 1);
  CHECK(count(degenerate, Disagreement_kind::missing) == 0);
}

TEST_CASE("crosscheck through the command line: exit 0 on a protein, 1 where the doubles go wrong") {
  const Cli_result pept = run({"crosscheck", std::string(APOLLONIUS_TEST_DATA) + "/pept.balls"});
  CHECK(pept.code == EXIT_OK);
  CHECK(pept.out.empty());
  CHECK(pept.err.find("missing 0, spurious 0, moved 0") != std::string::npos);

  // Lattice points moved by one ulp: vertices nearly coincide, and plain doubles lose some.
  Scratch scratch;
  const std::string file = scratch.path("lattice_noise.balls");
  REQUIRE(run({"generate", "lattice-noise", "--n", "40", "--seed", "1", "-o", file}).code == EXIT_OK);
  const Cli_result noisy = run({"crosscheck", file});
  CHECK(noisy.code == EXIT_DISCREPANCIES);
  CHECK(!noisy.out.empty());
  CHECK(run({"crosscheck"}).code == EXIT_BAD_INPUT);
  CHECK(run({"vertices", file, "--arith", "float", "--algorithm", "brute"}).code == EXIT_BAD_INPUT);
  CHECK(run({"vertices", file, "--arith", "double"}).code == EXIT_BAD_INPUT);
}
