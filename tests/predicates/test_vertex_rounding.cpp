// The printed coordinates of vertices: the double-double stage (certified_roundings) against the exact
// rounding (to_nearest_double of the exact point) on every vertex of every generator family, and on
// vertices placed exactly on a rounding midpoint, where the fast stage must decline.
#include <doctest/doctest.h>

#include <cmath>

#include "reference/brute_force_diagram.h"
#include "support/exact_checks.h"
#include "reference/site_generators.h"
#include "predicates/vertex_rounding.h"
#include "predicates/vertices_of.h"

using namespace apollonius;
using namespace apollonius::testing;

namespace {

// The same vertex recomputed from its quadruple: a diagram's vertex may already hold its exact coordinates.
Vertex fresh_copy(const Vertex& v) {
  for (const Vertex& w : vertices_of(v.quadruple()).vertices)
    if (w.root() == v.root()) return w;
  FAIL("the vertex's root vanished");
  return v;
}

}  // namespace

TEST_CASE("the double-double stage agrees with the exact rounding wherever it answers") {
  std::size_t coordinates = 0, certified = 0;
  for (const std::string& name : site_family_names()) {
    for (std::uint64_t seed = 1; seed <= 60; ++seed) {
      CAPTURE(name);
      CAPTURE(seed);
      const std::vector<Site> sites = generate_sites(site_family_from_name(name), 5 + seed % 8, seed);
      for (const Diagram_vertex& v : brute_force_diagram(sites).vertices) {
        for (const Vertex& w : vertices_of(v.vertex.quadruple()).vertices) {
          const std::array<double, 4> exact = exactly_rounded_point(w);
          const std::array<std::optional<double>, 4> fast = certified_roundings(w);
          for (int j = 0; j < 4; ++j) {
            CAPTURE(j);
            ++coordinates;
            if (!fast[j]) continue;
            ++certified;
            CHECK(*fast[j] == exact[j]);
          }
          CHECK(rounded_coordinates(w) == exact);
        }
      }
    }
  }
  MESSAGE(certified << " of " << coordinates << " coordinates certified by the double-double stage");
  CHECK(coordinates > 10000);
  CHECK(certified > coordinates / 2);
}

TEST_CASE("a vertex exactly on a midpoint between doubles: the fast stage declines, ties go to even") {
  // A triangular prism with equal weights, mirror-symmetric about the plane x = 1 + 2^-53 (the midpoint
  // between 1 and its successor): its six sites tie at one vertex on that plane.
  const double below = 1 - 0x1p-52, above = 1 + 0x1p-51;  // (below + above) / 2 = 1 + 2^-53
  const std::vector<Site> sites = {{below, 0, 0, 0.25}, {above, 0, 0, 0.25}, {below, 3, 1, 0.25},
                                   {above, 3, 1, 0.25}, {below, 1, 4, 0.25}, {above, 1, 4, 0.25}};
  std::size_t checked = 0;
  for (const Diagram_vertex& v : brute_force_diagram(sites).vertices) {
    const Vertex fresh = fresh_copy(v.vertex);
    const auto p = exact_point(fresh);
    if (!exactly_equal(p[0], Root_number<Exact>{Exact(1) + Exact(0x1p-53), Exact(0), Exact(0), Exact(1)})) continue;
    ++checked;
    CHECK_FALSE(certified_roundings(fresh)[0].has_value());
    CHECK(rounded_coordinates(fresh)[0] == 1.0);  // 1 has an even significand, its successor an odd one
  }
  CHECK(checked > 0);
}

TEST_CASE("vertices far from the double range's middle are rounded exactly") {
  for (Site_family family : {Site_family::scaled_up, Site_family::scaled_down}) {
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
      CAPTURE(name_of(family));
      CAPTURE(seed);
      const std::vector<Site> sites = generate_sites(family, 8, seed);
      for (const Diagram_vertex& v : brute_force_diagram(sites).vertices) {
        const Vertex fresh = fresh_copy(v.vertex);
        CHECK(rounded_coordinates(fresh) == exactly_rounded_point(fresh));
      }
    }
  }
}
