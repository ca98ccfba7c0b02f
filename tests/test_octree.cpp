// The octree algorithm against the brute-force reference: identical tie sets and printed coordinates on
// thousands of random and degenerate inputs, on the small vdrc sets, and for every thread count.
#include <doctest/doctest.h>

#include <cstdlib>

#include "brute_force_diagram.h"
#include "diagram_checks.h"
#include "io/read_sites.h"
#include "octree_diagram.h"
#include "site_generators.h"

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

// APOLLONIUS_DIFFERENTIAL_SEEDS raises the number of seeds per family for long runs.
std::uint64_t seeds_per_family(std::uint64_t default_count) {
  if (const char* env = std::getenv("APOLLONIUS_DIFFERENTIAL_SEEDS")) return std::strtoull(env, nullptr, 10);
  return default_count;
}

// Families whose every predicate reaches the exact stage (intervals overflow or underflow at 2^+-300) or
// whose vertices nearly coincide cost ~50 times more; they get fewer seeds per CI run.
std::uint64_t seeds_for(Site_family family) {
  const bool expensive = family == Site_family::scaled_up || family == Site_family::scaled_down ||
                         family == Site_family::lattice_noise;
  return seeds_per_family(expensive ? 25 : 500);
}

}  // namespace

TEST_CASE("octree equals brute force on every generator family") {
  std::size_t inputs = 0, vertices = 0, expected_inputs = 0;
  for (const std::string& name : site_family_names()) {
    const Site_family family = site_family_from_name(name);
    const std::uint64_t seeds = seeds_for(family);
    expected_inputs += seeds;
    for (std::uint64_t seed = 1; seed <= seeds; ++seed) {
      const std::size_t n = 5 + (seed * 7919) % 36;  // 5 to 40 sites
      CAPTURE(name);
      CAPTURE(seed);
      CAPTURE(n);
      const std::vector<Site> sites = generate_sites(family, n, seed);
      const Diagram reference = brute_force_diagram(sites);
      const Diagram octree = octree_diagram(sites);
      check_same(octree, reference);
      ++inputs;
      vertices += reference.vertices.size();
    }
  }
  MESSAGE(inputs << " inputs, " << vertices << " vertices, all equal");
  CHECK(inputs == expected_inputs);
  CHECK(inputs >= 5000);
}

TEST_CASE("octree equals brute force on the small vdrc sets") {
  for (const char* name : {"ANO1_0CONNECT", "ANO3_3CONNECT", "Vis_I_10", "Vis_II_5", "Vis_III_5", "Vis_V_20", "Vis_VII_20"}) {
    CAPTURE(name);
    const std::vector<Site> sites = read_sites(std::string(APOLLONIUS_TEST_DATA) + "/vdrc/" + name + ".txt", {}).sites;
    const Diagram octree = octree_diagram(sites);
    validate_diagram(octree, sites);
    check_same(octree, brute_force_diagram(sites));
  }
}

TEST_CASE("the output does not depend on the number of threads") {
  const std::vector<Site> sites = read_sites(std::string(APOLLONIUS_TEST_DATA) + "/pept.balls", {}).sites;
  const Diagram one = octree_diagram(sites, Octree_options{1});
  validate_diagram(one, sites);
  for (int threads : {2, 3, 8}) {
    CAPTURE(threads);
    check_same(octree_diagram(sites, Octree_options{threads}), one);
  }
}
