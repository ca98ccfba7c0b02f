// The vdrc anomaly and visual sets (tests/data/vdrc, provenance in bench/data/README.md), each with the
// structure that makes it hard for a tracer that walks from vertex to vertex:
//  - ANO3_3CONNECT: the two roots of one quadruple joined by three edges;
//  - ANO1_0CONNECT: a small ball between two large ones, whose cell has no vertex: two bounded faces on one
//    closed edge, which is a hole in the face of the two large balls;
//  - Vis_II_5 and Vis_III_5: closed edges and faces with holes.
// The files of ANO4_4CONNECT and ANO2_0CONNECT are not available here; tests/data/constructed holds inputs
// of ours with their structures (four edges between two roots, a component on its own; two vertex-free
// cells). On every set the edges equal the brute-force reference and the Euler relation holds.
#include <doctest/doctest.h>

#include <algorithm>
#include <map>
#include <tuple>
#include <string>

#include "io/read_sites.h"
#include "reference/brute_force_diagram.h"
#include "reference/brute_force_edges.h"
#include "topology/build_topology.h"
#include "topology/euler_characteristic.h"

using namespace apollonius;

namespace {

struct Built {
  std::vector<Site> sites;
  Diagram diagram;
  Diagram_topology topology;
};

// NAME: a vdrc set (tests/data/vdrc/NAME.txt), or a path below tests/data ending in .balls.
Built build(const std::string& name) {
  Built b;
  const bool balls = name.size() > 6 && name.compare(name.size() - 6, 6, ".balls") == 0;
  const std::string path = std::string(APOLLONIUS_TEST_DATA) + (balls ? "/" + name : "/vdrc/" + name + ".txt");
  b.sites = read_sites(path, {}).sites;
  b.diagram = brute_force_diagram(b.sites);
  b.topology = build_topology(b.sites, b.diagram, regions_for_every_site(b.diagram));
  return b;
}

bool same(const Diagram_edge& x, const Diagram_edge& y) {
  return x.tie_set == y.tie_set && x.start == y.start && x.end == y.end && x.closed == y.closed && x.curve == y.curve;
}

// Edges joining two vertices, by the pair of vertex ids.
std::map<std::pair<std::size_t, std::size_t>, int> multiplicities(const Diagram_topology& t) {
  std::map<std::pair<std::size_t, std::size_t>, int> count;
  for (const Diagram_edge& e : t.edges)
    if (e.start && e.end && *e.start != *e.end) ++count[std::minmax(*e.start, *e.end)];
  return count;
}

// The connected components of the graph of vertices and edges with two ends: a component id per vertex.
std::vector<std::size_t> vertex_components(const Diagram_topology& t) {
  std::vector<std::size_t> component(t.vertices.vertices.size());
  for (std::size_t v = 0; v < component.size(); ++v) component[v] = v;
  const auto root = [&](std::size_t v) {
    while (component[v] != v) v = component[v] = component[component[v]];
    return v;
  };
  for (const Diagram_edge& e : t.edges)
    if (e.start && e.end) component[root(*e.start)] = root(*e.end);
  for (std::size_t v = 0; v < component.size(); ++v) component[v] = root(v);
  return component;
}

const Diagram_face& face_of(const Diagram_topology& t, Site_index a, Site_index b) {
  for (const Diagram_face& f : t.faces)
    if (f.a == a && f.b == b) return f;
  FAIL("no face of sites " << a << " and " << b);
  return t.faces.front();
}

}  // namespace

TEST_CASE("every vdrc set: edges equal the brute force, the Euler relation holds") {
  for (const char* name : {"ANO1_0CONNECT", "ANO3_3CONNECT", "Vis_II_5", "Vis_III_5", "Vis_I_10", "Vis_V_20", "Vis_VII_20",
                           "constructed/four_edges_between_two_roots.balls", "constructed/two_vertex_free_cells.balls"}) {
    CAPTURE(name);
    const Built b = build(name);
    const std::vector<Diagram_edge> expected = brute_force_edges(b.sites, b.diagram);
    REQUIRE(b.topology.edges.size() == expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) CHECK(same(b.topology.edges[i], expected[i]));
    CHECK(euler_defect(b.topology) == 0);
    CHECK(b.topology.cells.size() == b.sites.size() - b.diagram.hidden.size());
  }
}

TEST_CASE("ANO3_3CONNECT: the two roots of a quadruple joined by three edges") {
  const Built b = build("ANO3_3CONNECT");
  CHECK(b.diagram.vertices.size() == 8);
  int triple_joins = 0;
  for (const auto& [ends, count] : multiplicities(b.topology)) {
    CHECK(count <= 3);
    if (count < 3) continue;
    ++triple_joins;
    CHECK(b.diagram.vertices[ends.first].tie_set == b.diagram.vertices[ends.second].tie_set);
  }
  CHECK(triple_joins >= 1);
}

TEST_CASE("ANO1_0CONNECT: a cell with no vertex, a closed edge, a face with a hole") {
  const Built b = build("ANO1_0CONNECT");
  const Diagram_topology& t = b.topology;
  std::size_t closed = 0;
  for (const Diagram_edge& e : t.edges)
    if (e.closed) {
      ++closed;
      CHECK(e.tie_set == std::vector<Site_index>{0, 1, 2});
      CHECK(e.curve == Curve_shape::ellipse);
    }
  CHECK(closed == 1);
  // Site 2 (the small ball at the origin) touches only the large balls 0 and 1.
  const Diagram_cell* small = nullptr;
  for (const Diagram_cell& c : t.cells)
    if (c.site == 2) small = &c;
  REQUIRE(small != nullptr);
  CHECK(small->bounded);
  CHECK(small->faces.size() == 2);
  for (Site_index other : {0, 1}) {
    const Diagram_face& f = face_of(t, other, 2);
    CHECK(f.bounded);
    REQUIRE(f.boundary.size() == 1);
    CHECK(f.boundary[0].size() == 1);
    CHECK(t.edges[f.boundary[0][0]].closed);
  }
  const Diagram_face& large = face_of(t, 0, 1);
  CHECK(large.boundary.size() == 2);  // the outer boundary through the four vertices, and the hole
  for (const Diagram_vertex& v : b.diagram.vertices)
    CHECK(std::find(v.tie_set.begin(), v.tie_set.end(), Site_index{2}) == v.tie_set.end());
}

TEST_CASE("Vis_II_5 and Vis_III_5: closed edges and faces with holes") {
  for (const auto& [name, closed_edges, holed_faces] :
       {std::tuple{"Vis_II_5", 1, 2}, std::tuple{"Vis_III_5", 3, 3}}) {
    CAPTURE(name);
    const Built b = build(name);
    int closed = 0, holed = 0;
    for (const Diagram_edge& e : b.topology.edges) closed += e.closed ? 1 : 0;
    for (const Diagram_face& f : b.topology.faces) holed += f.boundary.size() > 1 ? 1 : 0;
    CHECK(closed == closed_edges);
    CHECK(holed == holed_faces);
  }
}

TEST_CASE("four edges between the two roots of a quadruple, a component on its own (ANO4_4CONNECT's structure)") {
  const Built b = build("constructed/four_edges_between_two_roots.balls");
  const Diagram_topology& t = b.topology;
  REQUIRE(b.diagram.vertices.size() >= 2);
  const std::vector<Site_index> quadruple{0, 1, 2, 3};
  CHECK(b.diagram.vertices[0].tie_set == quadruple);
  CHECK(b.diagram.vertices[1].tie_set == quadruple);
  // One edge on each trisector of the quadruple, every one from root to root.
  std::vector<std::vector<Site_index>> triples;
  for (const Diagram_edge& e : t.edges) {
    const bool at_root = (e.start && *e.start < 2) || (e.end && *e.end < 2);
    if (!at_root) continue;
    REQUIRE(e.start);
    REQUIRE(e.end);
    CHECK(std::min(*e.start, *e.end) == 0);
    CHECK(std::max(*e.start, *e.end) == 1);
    triples.push_back(e.tie_set);
  }
  std::sort(triples.begin(), triples.end());
  CHECK(triples == std::vector<std::vector<Site_index>>{{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}});
  CHECK(multiplicities(t).at({0, 1}) == 4);
  // The roots form a component of their own; the far balls' vertices form another.
  const std::vector<std::size_t> component = vertex_components(t);
  CHECK(component[0] == component[1]);
  for (std::size_t v = 2; v < component.size(); ++v) CHECK(component[v] != component[0]);
  CHECK(b.diagram.vertices.size() > 2);
}

TEST_CASE("two cells with no vertex, each bounded by a closed edge (ANO2_0CONNECT's structure)") {
  const Built b = build("constructed/two_vertex_free_cells.balls");
  const Diagram_topology& t = b.topology;
  for (const auto& [small, large_a, large_b] : {std::tuple<Site_index, Site_index, Site_index>{2, 0, 1}, {5, 3, 4}}) {
    CAPTURE(small);
    for (const Diagram_vertex& v : b.diagram.vertices)
      CHECK(std::find(v.tie_set.begin(), v.tie_set.end(), small) == v.tie_set.end());
    const Diagram_cell* cell = nullptr;
    for (const Diagram_cell& c : t.cells)
      if (c.site == small) cell = &c;
    REQUIRE(cell != nullptr);
    CHECK(cell->bounded);
    REQUIRE(cell->faces.size() == 2);
    std::size_t closed = t.edges.size();
    for (std::size_t e = 0; e < t.edges.size(); ++e)
      if (t.edges[e].tie_set == std::vector<Site_index>{large_a, large_b, small}) closed = e;
    REQUIRE(closed < t.edges.size());
    CHECK(t.edges[closed].closed);
    CHECK(t.edges[closed].curve == Curve_shape::ellipse);
    for (Site_index other : {large_a, large_b}) {
      const Diagram_face& f = face_of(t, other, small);
      CHECK(f.bounded);
      CHECK(f.boundary == std::vector<std::vector<std::size_t>>{{closed}});
    }
    // The closed edge is a hole in the face of the two large balls.
    const Diagram_face& large = face_of(t, large_a, large_b);
    CHECK(large.boundary.size() == 2);
    CHECK(std::count(large.boundary.begin(), large.boundary.end(), std::vector<std::size_t>{closed}) == 1);
  }
}
