#include "topology/face_boundaries.h"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>

#include "predicates/trisector_predicates.h"

namespace apollonius {
namespace {

using Pair = std::pair<Site_index, Site_index>;

Pair ordered(Site_index x, Site_index y) { return x < y ? Pair{x, y} : Pair{y, x}; }

// The pairs of consecutive sites around the edge.
std::vector<Pair> pairs_around(const std::vector<Site>& sites, const Diagram& diagram, const Diagram_edge& e) {
  const std::vector<Site_index>& tie = e.tie_set;
  if (tie.size() == 3) return {ordered(tie[0], tie[1]), ordered(tie[0], tie[2]), ordered(tie[1], tie[2])};
  const std::optional<std::size_t> at = e.start ? e.start : e.end;
  if (!at)
    throw std::logic_error("a degenerate edge of " + std::to_string(tie.size()) +
                           " tied sites with no vertex: its faces are not decided in this version");
  const std::array<Site_index, 3> triple{tie[0], tie[1], tie[2]};
  const Trisector t(triple, {sites[triple[0]], sites[triple[1]], sites[triple[2]]});
  std::vector<Site> tied;
  for (Site_index s : tie) tied.push_back(sites[s]);
  const std::vector<std::size_t> order = order_around_edge(t, diagram.vertices[*at].vertex, tied);
  std::vector<Pair> pairs;
  for (std::size_t k = 0; k < order.size(); ++k) pairs.push_back(ordered(tie[order[k]], tie[order[(k + 1) % order.size()]]));
  return pairs;
}

struct Half_edge {
  std::size_t edge;
  Pair pair;
};

}  // namespace

std::vector<Boundary_component> boundary_components(const std::vector<Site>& sites, const Diagram& diagram,
                                                    const std::vector<Diagram_edge>& edges) {
  std::vector<Half_edge> halves;
  for (std::size_t e = 0; e < edges.size(); ++e)
    for (const Pair& p : pairs_around(sites, diagram, edges[e])) halves.push_back({e, p});

  // At each vertex, the half-edges of one pair come in twos: link their ends (side 0: start, 1: end).
  constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  std::vector<std::array<std::size_t, 2>> link(halves.size(), {kNone, kNone});  // 2 h + side of the other end
  std::map<std::pair<std::size_t, Pair>, std::vector<std::size_t>> at_vertex;  // (vertex, pair) -> 2 h + side
  for (std::size_t h = 0; h < halves.size(); ++h) {
    const Diagram_edge& e = edges[halves[h].edge];
    if (e.start) at_vertex[{*e.start, halves[h].pair}].push_back(2 * h);
    if (e.end) at_vertex[{*e.end, halves[h].pair}].push_back(2 * h + 1);
  }
  for (const auto& [key, ends] : at_vertex) {
    if (ends.size() != 2)
      throw std::logic_error("at vertex " + std::to_string(key.first) + ", the faces of sites " +
                             std::to_string(key.second.first) + " and " + std::to_string(key.second.second) + " meet " +
                             std::to_string(ends.size()) + " edges: not decided in this version");
    link[ends[0] / 2][ends[0] % 2] = ends[1];
    link[ends[1] / 2][ends[1] % 2] = ends[0];
  }

  // Walk: from a half-edge out of its end side, until back at the start or at infinity; an open chain is
  // then extended from the start's other side.
  std::vector<bool> visited(halves.size(), false);
  std::vector<Boundary_component> components;
  for (std::size_t first = 0; first < halves.size(); ++first) {
    if (visited[first]) continue;
    Boundary_component c;
    c.a = halves[first].pair.first;
    c.b = halves[first].pair.second;
    std::vector<std::size_t> forward{halves[first].edge};
    visited[first] = true;
    std::size_t h = first, side = 1;
    c.closed = true;
    for (;;) {
      const std::size_t next = link[h][side];
      if (next == kNone) {
        c.closed = edges[halves[first].edge].closed;
        break;
      }
      h = next / 2, side = 1 - next % 2;
      if (h == first) break;
      visited[h] = true;
      forward.push_back(halves[h].edge);
    }
    if (!c.closed) {  // back from the start to the other infinity
      std::vector<std::size_t> backward;
      h = first, side = 0;
      for (std::size_t next; (next = link[h][side]) != kNone;) {
        h = next / 2, side = 1 - next % 2;
        visited[h] = true;
        backward.push_back(halves[h].edge);
      }
      c.edges.assign(backward.rbegin(), backward.rend());
    }
    c.edges.insert(c.edges.end(), forward.begin(), forward.end());
    components.push_back(std::move(c));
  }
  std::sort(components.begin(), components.end(), [](const Boundary_component& x, const Boundary_component& y) {
    return std::tie(x.a, x.b, x.edges) < std::tie(y.a, y.b, y.edges);
  });
  return components;
}

}  // namespace apollonius
