// Faces at vertices where one face meets more than two edges (sheet_fan.h), against the mirror symmetry
// of coplanar sites: balls on the half-axes of the plane z = 0, all tangent to one sphere at the origin,
// tie at the double root there. Sites on neighbouring half-axes share a face that crosses the plane (its
// two edges leave the vertex on opposite sides of it); sites on opposite half-axes share faces that do
// not, each bounded by two edges on one side. Each edge's side is read at its arc witness, independently
// of the order on the sheet.
#include <doctest/doctest.h>

#include <cstdlib>
#include <algorithm>
#include <map>
#include <set>
#include <random>
#include <string>

#include "io/read_sites.h"
#include "predicates/arc_witness.h"
#include "predicates/rounding_guard.h"
#include "reference/brute_force_diagram.h"
#include "topology/build_topology.h"
#include "topology/euler_characteristic.h"

using namespace apollonius;

namespace {

// The side of the plane z = 0 of the edge's witness point.
Sign side_of_edge(const std::vector<Site>& sites, const Diagram& diagram, const Diagram_edge& e) {
  const Trisector t({e.tie_set[0], e.tie_set[1], e.tie_set[2]},
                    {sites[e.tie_set[0]], sites[e.tie_set[1]], sites[e.tie_set[2]]});
  std::optional<Arc_end> from, to;
  if (e.start) from = Arc_end(&diagram.vertices[*e.start].vertex);
  if (e.end) to = Arc_end(&diagram.vertices[*e.end].vertex);
  const Curve_point witness = arc_witness(t, from, to);
  const Field_point<Rational> p = witness.coordinates<Rational>();
  // z = X_2 / 2 + z_o, with X_2 = (a + b sqrt d) / denominator.
  const Rational shift = Rational(2) * to_rational(t.origin().z) * p.denominator;
  return sign_of_root_number(p.scaled[2].a + shift, p.scaled[2].b, p.discriminant);
}

// Which half-axis of the plane a site's centre lies on: 0 +x, 1 +y, 2 -x, 3 -y.
int half_axis(const Site& s) {
  if (s.x > 0) return 0;
  if (s.y > 0) return 1;
  if (s.x < 0) return 2;
  return 3;
}

// Checks every face where every edge runs from the vertex to infinity (when a small ball's cell is
// bounded, an edge loops from the vertex back to it, crossing the plane); returns how many faces of
// opposite sites it saw, nothing when an edge loops.
std::optional<std::size_t> check_mirror_pairing(const std::vector<Site>& sites) {
  const Diagram diagram = brute_force_diagram(sites);
  const Diagram_topology t = build_topology(sites, diagram, regions_for_every_site(diagram));
  CHECK(euler_defect(t) == 0);
  for (const Diagram_edge& e : t.edges)
    if ((e.start && e.end) || e.closed) return std::nullopt;
  std::map<std::pair<Site_index, Site_index>, std::size_t> faces_of_pair;
  for (const Diagram_face& f : t.faces) ++faces_of_pair[{f.a, f.b}];
  std::size_t split = 0;
  for (const Diagram_face& f : t.faces) {
    REQUIRE(f.boundary.size() == 1);
    REQUIRE(f.boundary[0].size() == 2);
    const Sign first = side_of_edge(sites, diagram, t.edges[f.boundary[0][0]]);
    const Sign second = side_of_edge(sites, diagram, t.edges[f.boundary[0][1]]);
    REQUIRE(first != Sign::ZERO);
    REQUIRE(second != Sign::ZERO);
    const bool opposite_axes = (half_axis(sites[f.a]) + 2) % 4 == half_axis(sites[f.b]);
    CAPTURE(f.a);
    CAPTURE(f.b);
    CHECK((first == second) == opposite_axes);
    CHECK(faces_of_pair[{f.a, f.b}] == (opposite_axes ? 2 : 1));
    split += opposite_axes ? 1 : 0;
  }
  return split;
}

}  // namespace

TEST_CASE("face_of_four_edges_at_a_double_root") {
  const std::vector<Site> sites =
      read_sites(std::string(APOLLONIUS_TEST_DATA) + "/regression/face_of_four_edges_at_a_double_root.balls", {}).sites;
  CHECK(check_mirror_pairing(sites) == std::optional<std::size_t>(2));
}

TEST_CASE("balls on the four half-axes tangent to one sphere: faces of opposite sites pair edges on one side") {
  const char* text = std::getenv("APOLLONIUS_TOPOLOGY_SEEDS");
  const std::uint64_t seeds = text != nullptr ? 10 * std::strtoull(text, nullptr, 10) : 100;
  std::size_t split = 0, looped = 0;
  for (std::uint64_t seed = 1; seed <= seeds; ++seed) {
    CAPTURE(seed);
    std::mt19937_64 random(seed);
    // Weights w in [1, 9] in steps of 1/8, centre at distance 2 + w: every ball touches the sphere of
    // radius 2 about the origin, exactly in doubles.
    std::vector<Site> sites;
    for (int axis = 0; axis < 4; ++axis) {
      const double w = 1.0 + static_cast<double>(random() % 65) / 8.0, d = 2.0 + w;
      const double x = axis == 0 ? d : axis == 2 ? -d : 0.0, y = axis == 1 ? d : axis == 3 ? -d : 0.0;
      sites.push_back({x, y, 0.0, w});
    }
    const std::optional<std::size_t> faces = check_mirror_pairing(sites);
    if (faces)
      split += *faces;
    else
      ++looped;
  }
  MESSAGE(split << " faces of opposite sites, each with two edges on one side; " << looped
                << " inputs with a bounded cell, checked by the Euler relation only");
  CHECK(split >= seeds);
}

TEST_CASE("equal balls on one circle: one edge with no vertex along the axis, faces between neighbours") {
  // The twelve integer points of the circle of radius 5.
  const std::vector<std::array<double, 2>> circle{{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3},
                                                  {-5, 0}, {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}};
  for (std::uint64_t seed = 1; seed <= 60; ++seed) {
    CAPTURE(seed);
    std::mt19937_64 random(seed);
    std::vector<std::size_t> chosen;  // positions on the circle, counterclockwise
    for (std::size_t k = 0; k < circle.size(); ++k)
      if (random() % 2 == 0) chosen.push_back(k);
    if (chosen.size() < 4) continue;
    std::vector<std::size_t> site_of(chosen.size());  // sites in a shuffled input order
    for (std::size_t i = 0; i < site_of.size(); ++i) site_of[i] = i;
    std::shuffle(site_of.begin(), site_of.end(), random);
    std::vector<Site> sites(chosen.size());
    for (std::size_t i = 0; i < chosen.size(); ++i)
      sites[site_of[i]] = {circle[chosen[i]][0], circle[chosen[i]][1], 0.0, 1.0};
    const Diagram diagram = brute_force_diagram(sites);
    const Diagram_topology t = build_topology(sites, diagram, regions_for_every_site(diagram));
    CHECK(diagram.vertices.empty());
    REQUIRE(t.edges.size() == 1);
    CHECK(t.edges[0].tie_set.size() == sites.size());
    CHECK_FALSE(t.edges[0].start);
    CHECK_FALSE(t.edges[0].end);
    CHECK(t.edges[0].curve == Curve_shape::line);
    REQUIRE(t.faces.size() == sites.size());
    std::set<std::pair<Site_index, Site_index>> expected, faces;
    for (std::size_t i = 0; i < chosen.size(); ++i) {
      const Site_index a = site_of[i], b = site_of[(i + 1) % chosen.size()];
      expected.insert(std::minmax(a, b));
    }
    for (const Diagram_face& f : t.faces) {
      faces.insert({f.a, f.b});
      CHECK(f.boundary == std::vector<std::vector<std::size_t>>{{0}});
      CHECK_FALSE(f.bounded);
    }
    CHECK(faces == expected);
    CHECK(euler_defect(t) == 0);
  }
}
