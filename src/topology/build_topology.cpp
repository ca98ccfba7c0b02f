#include "topology/build_topology.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>

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

Diagram_topology build_topology(const std::vector<Site>& sites, Diagram diagram, const Topology_options& options) {
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

}  // namespace apollonius
