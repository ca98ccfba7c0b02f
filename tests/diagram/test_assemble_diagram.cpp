// assemble_diagram (diagram.h) sorts the vertices where they lie: against the order written out plainly
// (std::vector's lexicographic tie sets, then the printed values, then the exact order), on shuffled
// diagrams of every degenerate family (settled or not) and on tie sets that share their first four sites.
// settle (diagram.h) keeps the rounding and lets the exact values be computed again, equal. gathered
// (cancellable_steps.h) appends to the longest list with room for all.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <random>

#include "diagram/cancellable_steps.h"
#include "diagram/diagram.h"
#include "diagram/fresh_memory.h"
#include "predicates/kernels.h"
#include "reference/brute_force_diagram.h"
#include "reference/site_generators.h"

using namespace apollonius;

namespace {

// docs/contract.md's order, with no shortcut.
bool plainly_before(const Diagram_vertex& u, const Diagram_vertex& v) {
  if (u.tie_set != v.tie_set) return u.tie_set < v.tie_set;
  if (u.rounded != v.rounded) return u.rounded < v.rounded;
  return Certified_kernel::compare(u.vertex, v.vertex) == Sign::NEGATIVE;
}

// The vertices without their rounding, in a random order; `settled` as the octree's lists hold them instead.
std::vector<Diagram_vertex> unrounded_shuffle(const std::vector<Diagram_vertex>& vertices, std::uint64_t seed,
                                              bool settled = false) {
  std::vector<Diagram_vertex> shuffled;
  for (const Diagram_vertex& v : vertices) {
    shuffled.push_back({v.tie_set, v.vertex});
    if (settled) settle<Certified_kernel>(shuffled.back());
  }
  std::mt19937_64 random(seed);
  std::shuffle(shuffled.begin(), shuffled.end(), random);
  return shuffled;
}

// The vertices dealt into three lists (as threads leave them): with `room`, the first can hold them all.
std::vector<std::vector<Diagram_vertex>> dealt(std::vector<Diagram_vertex> vertices, bool room) {
  std::vector<std::vector<Diagram_vertex>> lists(3);
  if (room) lists[0].reserve(vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i) lists[i % 3].push_back(std::move(vertices[i]));
  for (auto& list : lists)
    if (!room) list.shrink_to_fit();
  return lists;
}

}  // namespace

TEST_CASE("assemble_diagram puts shuffled vertices back in the contract's order, on every family, from one list or three") {
  for (Site_family family : {Site_family::uniform, Site_family::lattice, Site_family::lattice_noise, Site_family::cospherical,
                             Site_family::sphere_tangent, Site_family::circle, Site_family::circle_mixed, Site_family::duplicates,
                             Site_family::coplanar}) {
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
      const std::vector<Site> sites = generate_sites(family, 24, seed);
      const Diagram reference = brute_force_diagram(sites);
      CAPTURE(static_cast<int>(family));
      CAPTURE(seed);
      // One list, three with room in the first, three with none; each with the vertices settled or not.
      const int way = static_cast<int>(seed % 3);
      const bool settled = seed % 2 == 0;
      CAPTURE(way);
      CAPTURE(settled);
      std::vector<Diagram_vertex> shuffled = unrounded_shuffle(reference.vertices, seed, settled);
      const Diagram assembled =
          way == 0 ? assemble_diagram<Certified_kernel>(sites.size(), reference.hidden, std::move(shuffled))
                   : assemble_diagram<Certified_kernel>(sites.size(), reference.hidden, dealt(std::move(shuffled), way == 1));
      REQUIRE(assembled.vertices.size() == reference.vertices.size());
      for (std::size_t i = 0; i < assembled.vertices.size(); ++i) {
        const Diagram_vertex &a = assembled.vertices[i], &r = reference.vertices[i];
        CHECK(a.tie_set == r.tie_set);
        CHECK(a.rounded == r.rounded);
        CHECK(a.rounded == a.vertex.rounded());
        CHECK(Certified_kernel::compare(a.vertex, r.vertex) == Sign::ZERO);
        if (i > 0) CHECK(plainly_before(assembled.vertices[i - 1], a));
      }
      CHECK(assembled.sites_without_vertex == reference.sites_without_vertex);
    }
  }
}

TEST_CASE("assemble_diagram orders tie sets that share their first four sites as std::vector does, a prefix first") {
  const std::vector<Site> sites = generate_sites(Site_family::uniform, 12, 4);
  const Diagram reference = brute_force_diagram(sites);
  REQUIRE(reference.vertices.size() >= 2);
  const Vertex& p = reference.vertices[0].vertex;
  const Vertex& q = reference.vertices[1].vertex;
  REQUIRE(p.rounded() != q.rounded());
  // The tie sets need not match the vertices: the order only reads them.
  const std::vector<std::vector<Site_index>> tie_sets = {
      {0, 1, 2, 3}, {0, 1, 2, 3, 4}, {0, 1, 2, 3, 5}, {0, 1, 2, 3, 4, 6}, {0, 1, 2, 4}, {0, 1, 2, 3, 4, 5, 6}, {1, 2, 3, 4}};
  std::vector<Diagram_vertex> made;
  for (const auto& tie : tie_sets) {
    made.push_back({tie, p});
    made.push_back({tie, q});
  }
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    CAPTURE(seed);
    const Diagram assembled = seed % 2 == 0 ? assemble_diagram<Certified_kernel>(12, {}, unrounded_shuffle(made, seed))
                                            : assemble_diagram<Certified_kernel>(12, {}, dealt(unrounded_shuffle(made, seed), false));
    REQUIRE(assembled.vertices.size() == made.size());
    for (std::size_t i = 1; i < assembled.vertices.size(); ++i)
      CHECK(plainly_before(assembled.vertices[i - 1], assembled.vertices[i]));
  }
}

TEST_CASE("a settled vertex keeps its rounding, and computes its released exact values again, equal") {
  for (Site_family family : {Site_family::uniform, Site_family::lattice_noise, Site_family::wide_range, Site_family::scaled_down,
                             Site_family::far_vertices, Site_family::cospherical, Site_family::circle_mixed}) {
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
      const std::vector<Site> sites = generate_sites(family, 16, seed);
      const Diagram reference = brute_force_diagram(sites);
      CAPTURE(static_cast<int>(family));
      CAPTURE(seed);
      for (const Diagram_vertex& v : reference.vertices) {
        const std::array<Root_number<Exact>, 4> exact = exact_point(v.vertex);  // computed before the copy
        Diagram_vertex settled{v.tie_set, v.vertex};
        REQUIRE_FALSE(settled.is_rounded());
        settle<Certified_kernel>(settled);
        CHECK(settled.is_rounded());
        CHECK(settled.rounded == v.rounded);
        CHECK(settled.vertex.ball_coordinates_if_computed() == nullptr);
        const std::array<Root_number<Exact>, 4> again = exact_point(settled.vertex);
        for (int j = 0; j < 4; ++j) CHECK(compare(again[j], exact[j]) == Sign::ZERO);
        CHECK(Certified_kernel::compare(settled.vertex, v.vertex) == Sign::ZERO);
        for (const Site& s : sites) CHECK(Certified_kernel::conflict(settled.vertex, s) == Certified_kernel::conflict(v.vertex, s));
      }
    }
  }
}

TEST_CASE("gathered keeps the longest list with room where it lies, and populate_for_writing keeps what memory holds") {
  std::vector<int> short_roomy = {1, 2};
  short_roomy.reserve(100000);
  std::vector<int> long_roomy(30000, 7);
  long_roomy.reserve(100000);
  const int* kept = long_roomy.data();
  std::vector<std::vector<int>> lists;  // not from an initializer list, which would copy them without their room
  lists.push_back(std::move(short_roomy));
  lists.push_back(std::move(long_roomy));
  lists.push_back({3});
  lists.push_back({});
  const std::vector<int> all = gathered(lists, nullptr);
  CHECK(all.data() == kept);  // not moved: the others were appended to it
  REQUIRE(all.size() == 30003);
  CHECK(std::all_of(all.begin(), all.begin() + 30000, [](int x) { return x == 7; }));
  CHECK(std::vector<int>(all.begin() + 30000, all.end()) == std::vector<int>{1, 2, 3});

  std::vector<std::uint64_t> written(1 << 18);
  for (std::size_t k = 0; k < written.size(); ++k) written[k] = k * 0x9e3779b97f4a7c15ull;
  populate_for_writing(written.data() + 3, (written.size() - 5) * sizeof(std::uint64_t));  // pages around data
  populate_for_writing(written.data(), 0);
  bool unchanged = true;
  for (std::size_t k = 0; k < written.size(); ++k) unchanged = unchanged && written[k] == k * 0x9e3779b97f4a7c15ull;
  CHECK(unchanged);
}
