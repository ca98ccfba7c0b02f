// The whole diagram (docs/contract.md, "The whole diagram"): the vertices of Diagram, and the edges, faces
// and cells that join them (paper sections 4 and 5.3-5.5).
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "diagram/diagram.h"
#include "predicates/trisector.h"

namespace apollonius {

// A connected piece of the points where exactly the sites of tie_set tie (3 or more, a tie that is not
// isolated). It lies on the trisector of its three smallest sites, and runs forward along it (trisector.h)
// from `start` to `end`. Invariant: a closed edge has neither end; otherwise an end missing is at infinity.
struct Diagram_edge {
  std::vector<Site_index> tie_set;  // ascending
  Curve_shape curve = Curve_shape::none;
  std::optional<std::size_t> start, end;  // vertex ids
  bool closed = false;                    // a whole closed curve with no vertex
};

// The order of Diagram_topology's edges: by tie set, then start, then end, a missing end (infinity) first.
inline bool edge_precedes(const Diagram_edge& x, const Diagram_edge& y) {
  if (x.tie_set != y.tie_set) return x.tie_set < y.tie_set;
  if (x.start != y.start) return x.start < y.start;
  return x.end < y.end;
}

// A connected piece of the points where exactly sites a < b tie. Invariant: each boundary component is a
// list of edge ids in order along it, closed, or an open chain between two ends at infinity.
struct Diagram_face {
  Site_index a = 0, b = 0;
  std::vector<std::vector<std::size_t>> boundary;
  bool bounded = false;
};

// The points where one site is nearest: one per site that is not hidden.
struct Diagram_cell {
  Site_index site = 0;
  std::vector<std::size_t> faces;  // face ids, ascending
  bool bounded = false;
};

// What building it did, for --stats.
struct Topology_statistics {
  double edges_seconds = 0, vertex_free_seconds = 0, faces_seconds = 0;
  std::size_t candidate_triples = 0, candidate_pairs = 0, nested_pairs = 0;
};

// Invariants: edges sorted by tie set, then start, then end (a missing end first); faces by (a, b), then
// by their first boundary edge; cells ascending by site. Every id refers into these lists or to
// vertices.vertices.
struct Diagram_topology {
  Diagram vertices;
  std::vector<Diagram_edge> edges;
  std::vector<Diagram_face> faces;
  std::vector<Diagram_cell> cells;
  Topology_statistics statistics;
};

}  // namespace apollonius
