// Face nesting (topology/face_nesting.h): one closed cycle alone, decided by one level line
// (Level_lines::fewest), gets the same face as the sweep with one line per slab (every_slab), on every
// pair of every generated family, the bundled peptide and the vdrc sets with holes. A failure prints the
// input and the pair.
#include <doctest/doctest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "io/read_sites.h"
#include "octree/octree_diagram.h"
#include "reference/site_generators.h"
#include "topology/build_topology.h"
#include "topology/face_boundaries.h"
#include "topology/face_nesting.h"

using namespace apollonius;

namespace {

struct Counts {
  std::size_t cycles = 0, bounded = 0;  // single closed cycles compared; of them, bounded faces
};

// Every pair whose boundary is one closed cycle: both ways agree.
void compare_single_cycles(const std::vector<Site>& sites, Counts& counts) {
  Octree_regions regions;
  Diagram_topology t = build_topology(sites, octree_diagram(sites, Octree_options{1, nullptr, Arithmetic::certified, &regions}), regions);
  const std::vector<Boundary_component> components = boundary_components(sites, t.vertices, t.edges);
  for (std::size_t i = 0; i < components.size(); ++i) {
    const Boundary_component& c = components[i];
    const bool alone = (i == 0 || components[i - 1].a != c.a || components[i - 1].b != c.b) &&
                       (i + 1 == components.size() || components[i + 1].a != c.a || components[i + 1].b != c.b);
    if (!alone || !c.closed) continue;
    CAPTURE(c.a);
    CAPTURE(c.b);
    const Face_grouping one_line = group_components(sites, t.vertices, t.edges, {&c}, nullptr, Level_lines::fewest);
    const Face_grouping sweep = group_components(sites, t.vertices, t.edges, {&c}, nullptr, Level_lines::every_slab);
    CHECK(one_line.faces == sweep.faces);
    CHECK(one_line.bounded == sweep.bounded);
    ++counts.cycles;
    counts.bounded += sweep.bounded.front() ? 1 : 0;
  }
}

// Two balls on the x axis and a cluster of m lighter random balls between them: the cluster's cells cut
// one hole in the face of the two, which is unbounded around it.
std::vector<Site> hole_between_two(std::size_t m, std::uint64_t seed) {
  std::vector<Site> sites{{-10, 0, 0, 5}, {10, 0, 0, 5}};  // heavier: they own the plane far away
  std::uint64_t state = seed * 0x9E3779B97F4A7C15ull + 1;
  const auto uniform = [&] {  // in [0, 1), a multiple of 2^-20
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(state >> 44) / static_cast<double>(1 << 20);
  };
  for (std::size_t i = 0; i < m; ++i)
    sites.push_back({2 * uniform() - 1, 2 * uniform() - 1, 2 * uniform() - 1, 0.5 * uniform()});
  return sites;
}

// APOLLONIUS_NESTING_SEEDS scales the generated inputs (default 4 per family, 40 holes).
std::uint64_t seeds_per_family() {
  const char* text = std::getenv("APOLLONIUS_NESTING_SEEDS");
  return text != nullptr ? std::strtoull(text, nullptr, 10) : 4;
}

std::vector<Site> data_sites(const std::string& path) {
  return read_sites(std::string(APOLLONIUS_TEST_DATA) + "/" + path, {}).sites;
}

}  // namespace

TEST_CASE("one closed cycle alone: one level line decides its face as the sweep of every slab does") {
  Counts counts;
  for (const std::string& name : site_family_names())
    for (std::uint64_t seed = 1; seed <= seeds_per_family(); ++seed) {
      const std::size_t n = 5 + 3 * (1 + (seed - 1) % 4);
      CAPTURE(name);
      CAPTURE(n);
      CAPTURE(seed);
      compare_single_cycles(generate_sites(site_family_from_name(name), n, seed), counts);
    }
  for (std::uint64_t seed = 1; seed <= 10 * seeds_per_family(); ++seed) {
    CAPTURE(seed);
    compare_single_cycles(hole_between_two(1 + seed % 8, seed), counts);
  }
  for (const char* path : {"pept.balls", "vdrc/ANO1_0CONNECT.txt", "vdrc/Vis_II_5.txt", "vdrc/Vis_III_5.txt"}) {
    CAPTURE(path);
    compare_single_cycles(data_sites(path), counts);
  }
  MESSAGE(counts.cycles << " single closed cycles, " << counts.bounded << " of them bounding a bounded face");
  // Both answers occur: discs (bounded) and holes (unbounded faces around them).
  CHECK(counts.bounded >= 10);
  CHECK(counts.cycles - counts.bounded >= 10);
}
