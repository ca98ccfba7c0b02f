// Edges against an independent exact oracle: for equal weights the diagram is the Voronoi diagram, the dual
// of CGAL's Delaunay_triangulation_3 (exact predicates and constructions). Cells of one circumcentre are one
// vertex (cospherical sites); a Delaunay facet between cells of different circumcentres is the edge between
// them, and the sites on both circumspheres are its tie set; a convex-hull facet is an edge to infinity
// whose tie set is the sites of its cell's circumsphere on the facet's plane.
#include <doctest/doctest.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <map>
#include <random>
#include <set>
#include <string>
#include <tuple>

#include "octree/octree_diagram.h"
#include "reference/brute_force_diagram.h"
#include "reference/site_generators.h"
#include "topology/build_topology.h"
#include "topology/euler_characteristic.h"

using namespace apollonius;

namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Triangulation =
    CGAL::Delaunay_triangulation_3<Kernel, CGAL::Triangulation_data_structure_3<
                                               CGAL::Triangulation_vertex_base_with_info_3<Site_index, Kernel>,
                                               CGAL::Delaunay_triangulation_cell_base_3<Kernel>>>;

using Tie = std::vector<Site_index>;
// An edge as both sides can name it: its tie set and its two ends' tie sets (empty: infinity), sorted.
using Edge_key = std::tuple<Tie, Tie, Tie>;

Edge_key key_of(Tie tie, Tie u, Tie v) {
  if (v < u) std::swap(u, v);
  return {std::move(tie), std::move(u), std::move(v)};
}

std::multiset<Edge_key> delaunay_edges(const std::vector<Site>& sites) {
  std::vector<std::pair<Kernel::Point_3, Site_index>> points;
  for (Site_index i = 0; i < sites.size(); ++i) points.push_back({{sites[i].x, sites[i].y, sites[i].z}, i});
  const Triangulation dt(points.begin(), points.end());
  REQUIRE(dt.dimension() == 3);
  std::map<Kernel::Point_3, std::set<Site_index>> spheres;
  for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c)
    for (int k = 0; k < 4; ++k) spheres[c->circumcenter()].insert(c->vertex(k)->info());
  const auto tie_of = [&](Triangulation::Cell_handle c) {
    const auto& s = spheres.at(c->circumcenter());
    return Tie(s.begin(), s.end());
  };
  std::set<Edge_key> edges;  // several facets of one edge (cocircular sites) give the same key
  for (auto f = dt.all_facets_begin(); f != dt.all_facets_end(); ++f) {
    Triangulation::Cell_handle c = f->first, n = c->neighbor(f->second);
    if (dt.is_infinite(c)) std::swap(c, n);
    if (dt.is_infinite(c)) continue;
    const Tie u = tie_of(c);
    if (dt.is_infinite(n)) {
      std::array<Kernel::Point_3, 3> p;
      // The facet's three vertices, seen from c.
      const int opposite = c == f->first ? f->second : c->index(n);
      for (int k = 0, t = 0; k < 4; ++k)
        if (k != opposite) p[t++] = c->vertex(k)->point();
      Tie on_plane;
      for (Site_index s : u)
        if (CGAL::orientation(p[0], p[1], p[2], Kernel::Point_3(sites[s].x, sites[s].y, sites[s].z)) == CGAL::COPLANAR)
          on_plane.push_back(s);
      edges.insert(key_of(on_plane, u, {}));
      continue;
    }
    const Tie v = tie_of(n);
    if (u == v) continue;  // inside one vertex of cospherical sites
    Tie both;
    std::set_intersection(u.begin(), u.end(), v.begin(), v.end(), std::back_inserter(both));
    edges.insert(key_of(both, u, v));
  }
  return {edges.begin(), edges.end()};
}

// The faces: the Delaunay edges whose dual is 2-dimensional (a diagonal of cospherical sites has a point or
// a segment: its circumcentres and the rays to infinity around it lie on one line), unbounded exactly when
// the edge is on the convex hull.
std::map<std::pair<Site_index, Site_index>, bool> delaunay_faces(const std::vector<Site>& sites) {
  std::vector<std::pair<Kernel::Point_3, Site_index>> points;
  for (Site_index i = 0; i < sites.size(); ++i) points.push_back({{sites[i].x, sites[i].y, sites[i].z}, i});
  const Triangulation dt(points.begin(), points.end());
  std::map<std::pair<Site_index, Site_index>, bool> faces;  // pair -> bounded
  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
    Site_index u = e->first->vertex(e->second)->info(), v = e->first->vertex(e->third)->info();
    if (v < u) std::swap(u, v);
    std::vector<Kernel::Point_3> centres;
    std::vector<Kernel::Vector_3> rays;  // outward normals of the hull facets at the edge
    auto cell = dt.incident_cells(*e), done = cell;
    do {
      if (dt.is_infinite(cell)) {
        const int inf = cell->index(dt.infinite_vertex());
        std::array<Kernel::Point_3, 3> p;
        for (int k = 0, t = 0; k < 4; ++k)
          if (k != inf) p[t++] = cell->vertex(k)->point();
        // The infinite cell's finite facet is oriented so that the infinite vertex is on its positive side.
        Kernel::Vector_3 normal = CGAL::cross_product(p[1] - p[0], p[2] - p[0]);
        if (inf % 2 == 1) normal = -normal;
        rays.push_back(normal);
      } else if (std::find(centres.begin(), centres.end(), cell->circumcenter()) == centres.end()) {
        centres.push_back(cell->circumcenter());
      }
    } while (++cell != done);
    bool plane = false;  // the dual spans two dimensions
    for (std::size_t i = 2; i < centres.size() && !plane; ++i)
      plane = !CGAL::collinear(centres[0], centres[1], centres[i]);
    if (!plane && centres.size() >= 2)
      for (const auto& r : rays) plane = plane || CGAL::cross_product(r, centres[1] - centres[0]) != CGAL::NULL_VECTOR;
    if (!plane && centres.size() == 1)
      for (std::size_t i = 1; i < rays.size(); ++i) plane = plane || CGAL::cross_product(rays[0], rays[i]) != CGAL::NULL_VECTOR;
    if (plane) faces[{u, v}] = rays.empty();
  }
  return faces;
}

std::multiset<Edge_key> our_edges(const Diagram_topology& t) {
  std::multiset<Edge_key> edges;
  const auto tie = [&](const std::optional<std::size_t>& v) { return v ? t.vertices.vertices[*v].tie_set : Tie{}; };
  for (const Diagram_edge& e : t.edges) edges.insert(key_of(e.tie_set, tie(e.start), tie(e.end)));
  return edges;
}

std::string describe(const Edge_key& k) {
  std::string text;
  for (const Tie* tie : {&std::get<0>(k), &std::get<1>(k), &std::get<2>(k)}) {
    text += "(";
    for (Site_index s : *tie) text += std::to_string(s) + " ";
    text += ")";
  }
  return text;
}

// The brute force decides the vertices of the small degenerate inputs: the octree does not yet finish on some
// of them (the open issue on many sites tangent to one sphere).
void check_against_delaunay(const std::vector<Site>& sites, bool brute = false) {
  Octree_regions regions;
  Diagram diagram = brute ? brute_force_diagram(sites) : octree_diagram(sites, Octree_options{1, nullptr, Arithmetic::certified, &regions});
  if (brute) regions = regions_for_every_site(diagram);
  const Diagram_topology t = build_topology(sites, std::move(diagram), regions);
  CHECK(euler_defect(t) == 0);
  std::map<std::pair<Site_index, Site_index>, bool> faces;
  for (const Diagram_face& f : t.faces) {
    CHECK(f.boundary.size() == 1);  // Voronoi faces are convex: no holes
    CHECK(faces.count({f.a, f.b}) == 0);
    faces[{f.a, f.b}] = f.bounded;
  }
  CHECK(faces == delaunay_faces(sites));
  for (const Diagram_edge& e : t.edges) CHECK(e.curve == Curve_shape::line);
  const std::multiset<Edge_key> ours = our_edges(t), theirs = delaunay_edges(sites);
  std::vector<Edge_key> only_ours, only_theirs;
  std::set_difference(ours.begin(), ours.end(), theirs.begin(), theirs.end(), std::back_inserter(only_ours));
  std::set_difference(theirs.begin(), theirs.end(), ours.begin(), ours.end(), std::back_inserter(only_theirs));
  for (const Edge_key& k : only_ours) FAIL_CHECK("only ours: " << describe(k));
  for (const Edge_key& k : only_theirs) FAIL_CHECK("only Delaunay's: " << describe(k));
}

}  // namespace

TEST_CASE("equal weights: the edges are the duals of the Delaunay facets") {
  for (std::uint64_t seed = 1; seed <= 1500; ++seed) {
    CAPTURE(seed);
    const std::size_t n = 5 + seed % 40;
    CAPTURE(n);
    check_against_delaunay(generate_sites(Site_family::equal_weights, n, seed));
  }
}

TEST_CASE("equal weights, degenerate: integer lattices and cospherical points") {
  SUBCASE("a 3 x 3 x 3 lattice: every vertex ties 8 sites, every edge 4") {
    std::vector<Site> sites;
    for (int x = 0; x < 3; ++x)
      for (int y = 0; y < 3; ++y)
        for (int z = 0; z < 3; ++z) sites.push_back({double(x), double(y), double(z), 1});
    check_against_delaunay(sites, true);
  }
  SUBCASE("lattices with random holes") {
    for (std::uint64_t seed = 1; seed <= 60; ++seed) {
      CAPTURE(seed);
      std::mt19937_64 random(seed);
      std::vector<Site> sites;
      for (int x = 0; x < 3; ++x)
        for (int y = 0; y < 3; ++y)
          for (int z = 0; z < 3; ++z)
            if (random() % 3 != 0) sites.push_back({double(x), double(y), double(z), 2});
      if (sites.size() < 5) continue;
      check_against_delaunay(sites, true);
    }
  }
  SUBCASE("integer points on spheres (Pythagorean), with and without their centre") {
    for (const int radius : {3, 5}) {
      std::vector<Site> sites;
      for (int x = -radius; x <= radius; ++x)
        for (int y = -radius; y <= radius; ++y)
          for (int z = -radius; z <= radius; ++z)
            if (x * x + y * y + z * z == radius * radius) sites.push_back({double(x), double(y), double(z), 0.5});
      CAPTURE(radius);
      CAPTURE(sites.size());
      check_against_delaunay(sites, true);
      sites.push_back({0, 0, 0, 0.5});
      check_against_delaunay(sites, true);
    }
  }
}
