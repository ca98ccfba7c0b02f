#include "topology/build_topology.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "topology/face_boundaries.h"
#include "topology/trisector_edges.h"
#include "topology/vertex_fan.h"

namespace apollonius {
namespace {

// Edges by tie set, then start, then end, a missing end (infinity) first.
bool edge_order(const Diagram_edge& x, const Diagram_edge& y) {
  if (x.tie_set != y.tie_set) return x.tie_set < y.tie_set;
  if (x.start != y.start) return x.start < y.start;
  return x.end < y.end;
}

}  // namespace

Diagram_topology build_edges(const std::vector<Site>& sites, Diagram diagram, const Topology_options& options) {
  Diagram_topology topology;
  std::vector<std::vector<Departure>> departures(diagram.vertices.size());
  tbb::task_arena arena(std::clamp(options.threads, 1, tbb::this_task_arena::max_concurrency()));
  arena.execute([&] {
    tbb::parallel_for(std::size_t{0}, diagram.vertices.size(),
                      [&](std::size_t v) { departures[v] = vertex_departures(sites, diagram.vertices[v]); });
  });
  topology.edges = edges_through_vertices(sites, diagram, departures, options.threads);
  std::sort(topology.edges.begin(), topology.edges.end(), edge_order);
  topology.vertices = std::move(diagram);
  return topology;
}

void add_faces_and_cells(const std::vector<Site>& sites, Diagram_topology& topology) {
  const Diagram& diagram = topology.vertices;
  // Faces: one per pair whose boundary is one component. Several components of one pair are faces with
  // holes, or several faces: deciding which needs their nesting, not done in this version.
  const std::vector<Boundary_component> components = boundary_components(sites, diagram, topology.edges);
  for (std::size_t i = 0; i < components.size(); ++i) {
    const Boundary_component& c = components[i];
    if ((i > 0 && components[i - 1].a == c.a && components[i - 1].b == c.b) ||
        (i + 1 < components.size() && components[i + 1].a == c.a && components[i + 1].b == c.b))
      throw std::logic_error("sites " + std::to_string(c.a) + " and " + std::to_string(c.b) +
                             " share several boundary components: their nesting is not decided in this version");
    topology.faces.push_back({c.a, c.b, {c.edges}, c.closed});
  }
  std::vector<bool> hidden(sites.size(), false);
  for (const Hidden_site& h : diagram.hidden) hidden[h.site] = true;
  std::vector<Diagram_cell> cells(sites.size());
  for (Site_index s = 0; s < sites.size(); ++s) cells[s] = {s, {}, true};
  for (std::size_t f = 0; f < topology.faces.size(); ++f) {
    const Diagram_face& face = topology.faces[f];
    for (Site_index s : {face.a, face.b}) {
      cells[s].faces.push_back(f);
      cells[s].bounded = cells[s].bounded && face.bounded;
    }
  }
  for (Diagram_cell& c : cells)
    if (!hidden[c.site]) topology.cells.push_back(std::move(c));
}

}  // namespace apollonius
