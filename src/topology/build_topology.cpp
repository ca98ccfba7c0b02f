#include "topology/build_topology.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>

#include "diagram/threads.h"
#include "diagram/cancellable_steps.h"
#include "topology/face_boundaries.h"
#include "topology/face_nesting.h"
#include "topology/trisector_edges.h"
#include "topology/vertex_free.h"
#include "topology/vertex_fan.h"

namespace apollonius {
Diagram_topology build_edges(const std::vector<Site>& sites, Diagram diagram, const Topology_options& options) {
  Diagram_topology topology;
  topology.edges = edges_through_vertices(sites, diagram, options.threads, options.cancellation);  // sorted
  topology.vertices = std::move(diagram);
  return topology;
}

Octree_regions regions_for_every_site(const Diagram& diagram) {
  Octree_regions regions;
  std::vector<bool> hidden(diagram.site_count, false);
  for (const Hidden_site& h : diagram.hidden) hidden[h.site] = true;
  for (Site_index s = 0; s < diagram.site_count; ++s)
    if (!hidden[s]) regions.escaping.push_back(s);
  if (regions.escaping.size() >= 2) regions.far_sets.push_back(regions.escaping);
  return regions;
}

Diagram_topology build_topology(const std::vector<Site>& sites, Diagram diagram, const Octree_regions& regions,
                                const Topology_options& options) {
  using Clock = std::chrono::steady_clock;
  const auto seconds = [](Clock::time_point from) { return std::chrono::duration<double>(Clock::now() - from).count(); };
  auto start = Clock::now();
  Diagram_topology topology;
  const Vertex_triples vertex_triples(sites, diagram, options.cancellation);  // for both steps
  topology.edges = edges_through_vertices(sites, diagram, vertex_triples, options.threads, options.cancellation);
  topology.vertices = std::move(diagram);
  Topology_statistics& s = topology.statistics;
  s.edges_seconds = seconds(start);
  start = Clock::now();
  Vertex_free_parts parts = vertex_free_parts(sites, vertex_triples, topology.edges, regions,
                                              options.threads, options.cancellation);
  // Both lists sorted: merged in linear time.
  cancellable_sort(parts.edges.begin(), parts.edges.end(), options.cancellation, edge_precedes);
  const std::size_t through_vertices = topology.edges.size();
  for (Diagram_edge& e : parts.edges) topology.edges.push_back(std::move(e));
  std::inplace_merge(topology.edges.begin(), topology.edges.begin() + static_cast<std::ptrdiff_t>(through_vertices),
                     topology.edges.end(), edge_precedes);
  s.vertex_free_seconds = seconds(start);
  s.candidate_triples = parts.candidate_triples;
  s.candidate_pairs = parts.candidate_pairs;
  start = Clock::now();
  add_faces_and_cells(sites, topology, parts.sheets, regions.far_sets, options.threads, options.cancellation);
  s.faces_seconds = seconds(start);
  return topology;
}

void add_faces_and_cells(const std::vector<Site>& sites, Diagram_topology& topology,
                         const std::vector<std::pair<Site_index, Site_index>>& whole_sheets,
                         const std::vector<std::vector<Site_index>>& far_sets, int threads,
                         const Cancellation* cancellation) {
  // Whether a far set holds both sites: else their faces have no point far away, and are all bounded.
  std::vector<std::vector<std::size_t>> far_sets_of(sites.size());
  for (std::size_t f = 0; f < far_sets.size(); ++f)
    for (Site_index s : far_sets[f]) far_sets_of[s].push_back(f);
  const auto far_together = [&](Site_index a, Site_index b) {
    const std::vector<std::size_t>&x = far_sets_of[a], &y = far_sets_of[b];
    for (std::size_t i = 0, j = 0; i < x.size() && j < y.size();) {
      if (x[i] == y[j]) return true;
      x[i] < y[j] ? ++i : ++j;
    }
    return false;
  };
  const Diagram& diagram = topology.vertices;
  for (const auto& [a, b] : whole_sheets) topology.faces.push_back({a, b, {}, false});
  // Faces: one open chain alone is one unbounded face; otherwise the components' nesting decides
  // (face_nesting.h). Faces are sorted by pair, then by their boundary.
  std::vector<Boundary_component> components = boundary_components(sites, diagram, topology.edges, cancellation);
  // Each pair's components: [first, first + count) in `components`.
  struct Pair_components {
    std::size_t first = 0, count = 0;
    bool nested = false;
  };
  std::vector<Pair_components> pairs;
  std::vector<std::size_t> nested;  // positions in pairs of those whose nesting must be decided
  for (std::size_t i = 0; i < components.size();) {
    if (pairs.size() % 4096 == 0) throw_if_cancelled(cancellation);
    Pair_components p;
    p.first = i;
    const Boundary_component& c = components[i];
    for (; i < components.size() && components[i].a == c.a && components[i].b == c.b; ++i) ++p.count;
    // An open chain alone bounds one unbounded face; a closed cycle alone of sites that own no point far
    // away together bounds one bounded face (it contains no neighbourhood of infinity). On proteins nearly
    // every nested pair was such a cycle of two escaping sites, until the far sets decided them.
    p.nested = p.count > 1 || (c.closed && far_together(c.a, c.b));
    if (p.nested) nested.push_back(pairs.size());
    pairs.push_back(p);
  }
  // The pairs' nestings are independent: in parallel, each into its own slot, so the output is the same
  // for every thread count.
  std::vector<Face_grouping> groupings(nested.size());
  tbb::task_arena arena(usable_threads(threads));
  arena.execute([&] {
    tbb::parallel_for(std::size_t{0}, nested.size(), [&](std::size_t k) {
      throw_if_cancelled(cancellation);
      const Pair_components& p = pairs[nested[k]];
      std::vector<const Boundary_component*> of_pair;
      for (std::size_t i = p.first; i < p.first + p.count; ++i) of_pair.push_back(&components[i]);
      groupings[k] = group_components(sites, diagram, topology.edges, of_pair, cancellation);
    });
  });
  topology.faces.reserve(topology.faces.size() + components.size());  // at most one face per component
  for (std::size_t q = 0, k = 0; q < pairs.size(); ++q) {
    if (q % 4096 == 0) throw_if_cancelled(cancellation);
    const Pair_components& p = pairs[q];
    Boundary_component& c = components[p.first];
    if (!p.nested) {
      topology.faces.push_back({c.a, c.b, {std::move(c.edges)}, c.closed});
      continue;
    }
    ++topology.statistics.nested_pairs;
    const Face_grouping& grouping = groupings[k++];
    for (std::size_t f = 0; f < grouping.faces.size(); ++f) {
      Diagram_face face{c.a, c.b, {}, grouping.bounded[f]};
      for (std::size_t j : grouping.faces[f]) face.boundary.push_back(components[p.first + j].edges);
      topology.faces.push_back(std::move(face));
    }
  }
  cancellable_sort(topology.faces.begin(), topology.faces.end(), cancellation, [](const Diagram_face& x, const Diagram_face& y) {
    return std::tie(x.a, x.b, x.boundary) < std::tie(y.a, y.b, y.boundary);
  });
  std::vector<bool> hidden(sites.size(), false);
  for (const Hidden_site& h : diagram.hidden) hidden[h.site] = true;
  std::vector<Diagram_cell> cells(sites.size());
  for (Site_index s = 0; s < sites.size(); ++s) cells[s] = {s, {}, true};
  for (std::size_t f = 0; f < topology.faces.size(); ++f) {
    if (f % 4096 == 0) throw_if_cancelled(cancellation);
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
