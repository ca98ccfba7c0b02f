// Cancellation (diagram/cancellation.h) of the whole diagram's topology: a requested cancellation stops
// every phase of build_topology (edges, vertex-free parts, boundary components, nesting, faces and cells)
// and the validator with Cancelled, whenever it comes, and leaves nothing half done; one that is never
// requested changes no output.
#include <doctest/doctest.h>

#include <algorithm>
#include <chrono>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <variant>

#include "diagram/cancellation.h"
#include "octree/octree_diagram.h"
#include "reference/site_generators.h"
#include "topology/build_topology.h"
#include "topology/face_boundaries.h"
#include "topology/face_nesting.h"
#include "topology/trisector_edges.h"
#include "topology/validate_topology.h"
#include "topology/vertex_fan.h"
#include "topology/vertex_free.h"

using namespace apollonius;

namespace {

struct Vertices_and_regions {
  Diagram diagram;
  Octree_regions regions;
};

Vertices_and_regions octree_vertices(const std::vector<Site>& sites) {
  Vertices_and_regions v;
  Octree_options options;
  options.regions = &v.regions;
  v.diagram = octree_diagram(sites, options);
  return v;
}

bool same_edge(const Diagram_edge& x, const Diagram_edge& y) {
  return x.tie_set == y.tie_set && x.curve == y.curve && x.start == y.start && x.end == y.end && x.closed == y.closed;
}
bool same_face(const Diagram_face& x, const Diagram_face& y) {
  return x.a == y.a && x.b == y.b && x.boundary == y.boundary && x.bounded == y.bounded;
}
bool same_cell(const Diagram_cell& x, const Diagram_cell& y) {
  return x.site == y.site && x.faces == y.faces && x.bounded == y.bounded;
}

// Every edge, face and cell the same, in the same order (one CHECK each list, not one per item).
void check_same(const Diagram_topology& a, const Diagram_topology& b) {
  CHECK(a.vertices.vertices.size() == b.vertices.vertices.size());
  CHECK(std::equal(a.edges.begin(), a.edges.end(), b.edges.begin(), b.edges.end(), same_edge));
  CHECK(std::equal(a.faces.begin(), a.faces.end(), b.faces.begin(), b.faces.end(), same_face));
  CHECK(std::equal(a.cells.begin(), a.cells.end(), b.cells.begin(), b.cells.end(), same_cell));
}

// The topology, or the message of what this version does not decide (std::logic_error).
std::variant<Diagram_topology, std::string> topology_or_defect(const std::vector<Site>& sites,
                                                               const Vertices_and_regions& v,
                                                               const Topology_options& options) {
  try {
    return build_topology(sites, v.diagram, v.regions, options);
  } catch (const std::logic_error& e) {
    return std::string(e.what());
  }
}

}  // namespace

TEST_CASE("a topology cancellation that is never requested changes nothing") {
  for (const Site_family_description& f : kSiteFamilies) {
    // Fewer sites where the topology is slow (deep octrees, long exact numbers).
    const std::size_t n = f.family == Site_family::wide_range ? 6 : f.family == Site_family::lattice_noise ? 16 : 40;
    const std::vector<Site> sites = generate_sites(f.family, n, 7);
    const Vertices_and_regions v = octree_vertices(sites);
    const auto without = topology_or_defect(sites, v, {1, nullptr});
    for (int threads : {1, 2}) {
      CAPTURE(f.name);
      CAPTURE(threads);
      const Cancellation never;
      const auto with = topology_or_defect(sites, v, {threads, &never});
      REQUIRE(with.index() == without.index());
      if (with.index() == 1) {
        CHECK(std::get<1>(with) == std::get<1>(without));
        continue;
      }
      check_same(std::get<0>(with), std::get<0>(without));
      validate_topology(sites, std::get<0>(with), &never);
    }
  }
}

TEST_CASE("a cancellation requested before the call stops build_topology, and every phase checks it") {
  const std::vector<Site> sites = generate_sites(Site_family::uniform, 300, 3);
  const Vertices_and_regions v = octree_vertices(sites);
  const Diagram_topology whole = build_topology(sites, v.diagram, v.regions);
  REQUIRE_FALSE(whole.edges.empty());
  Cancellation cancellation;
  cancellation.request();
  for (int threads : {1, 2}) {
    CAPTURE(threads);
    CHECK_THROWS_AS(build_topology(sites, v.diagram, v.regions, {threads, &cancellation}), Cancelled);
    CHECK_THROWS_AS(build_edges(sites, v.diagram, {threads, &cancellation}), Cancelled);
    CHECK_THROWS_AS(vertex_free_parts(sites, whole.vertices, whole.edges, v.regions, threads, &cancellation), Cancelled);
    Diagram_topology faces_to_add = build_edges(sites, v.diagram);
    CHECK_THROWS_AS(add_faces_and_cells(sites, faces_to_add, {}, v.regions.far_sets, threads, &cancellation), Cancelled);
  }
  CHECK_THROWS_AS(edges_through_vertices(sites, whole.vertices, 1, &cancellation), Cancelled);
  CHECK_THROWS_AS(boundary_components(sites, whole.vertices, whole.edges, &cancellation), Cancelled);
  // The nesting of one pair's components, on a pair that has some.
  const std::vector<Boundary_component> components = boundary_components(sites, whole.vertices, whole.edges);
  REQUIRE_FALSE(components.empty());
  const std::vector<const Boundary_component*> first_pair{&components.front()};
  CHECK_THROWS_AS(group_components(sites, whole.vertices, whole.edges, first_pair, &cancellation), Cancelled);
  CHECK(group_components(sites, whole.vertices, whole.edges, first_pair).faces.size() == 1);
  CHECK_THROWS_AS(validate_topology(sites, whole, &cancellation), Cancelled);
  validate_topology(sites, whole);
}

TEST_CASE("a cancellation requested during build_topology gives Cancelled or the whole answer") {
  const std::vector<Site> sites = generate_sites(Site_family::uniform, 3000, 11);
  const Vertices_and_regions v = octree_vertices(sites);
  for (int threads : {1, 2}) {
    const auto start = std::chrono::steady_clock::now();
    const Diagram_topology reference = build_topology(sites, v.diagram, v.regions, {threads});
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    int cancelled = 0;
    for (int delay_ms : {0, 2, 10, 30, 60, 120, 250, 400, 1000}) {
      CAPTURE(threads);
      CAPTURE(delay_ms);
      Cancellation cancellation;
      std::thread requester([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms));
        cancellation.request();
      });
      try {
        const Diagram_topology t = build_topology(sites, v.diagram, v.regions, {threads, &cancellation});
        check_same(t, reference);
        validate_topology(sites, t);
      } catch (const Cancelled&) {
        ++cancelled;
        // Nothing of the cancelled run is left behind: the next one is whole.
        check_same(build_topology(sites, v.diagram, v.regions, {threads}), reference);
      }
      requester.join();
      // Requested at once, long before the topology of 3000 sites is built.
      if (delay_ms == 0) CHECK(cancelled == 1);
    }
    MESSAGE("threads " << threads << ": build_topology " << seconds << " s; " << cancelled << " of 9 runs cancelled");
  }
}
