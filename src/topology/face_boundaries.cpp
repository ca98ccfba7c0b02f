#include "topology/face_boundaries.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <tuple>

#include "diagram/cancellable_steps.h"
#include "diagram/flat_lists.h"
#include "predicates/arc_witness.h"
#include "predicates/sheet_fan.h"
#include "predicates/trisector_predicates.h"

namespace apollonius {
namespace {

using Pair = std::pair<Site_index, Site_index>;

Pair ordered(Site_index x, Site_index y) { return x < y ? Pair{x, y} : Pair{y, x}; }

// 32-bit ids: the half-edges and their links are this function's largest memory (checked below).
struct Half_edge {
  std::uint32_t edge;
  Pair pair;
};

// The pairs of consecutive sites around edge e, as half-edges appended to `halves`.
void add_pairs_around(const std::vector<Site>& sites, const Diagram& diagram, const Diagram_edge& e, std::uint32_t id,
                      std::vector<Half_edge>& halves) {
  const std::vector<Site_index>& tie = e.tie_set;
  if (tie.size() == 3) {  // all three pairs (a tie set is ascending), with no allocation: nearly every edge
    for (const Pair& p : {Pair{tie[0], tie[1]}, Pair{tie[0], tie[2]}, Pair{tie[1], tie[2]}}) halves.push_back({id, p});
    return;
  }
  const std::optional<std::size_t> at = e.start ? e.start : e.end;
  const std::array<Site_index, 3> triple{tie[0], tie[1], tie[2]};
  const Trisector t(triple, {sites[triple[0]], sites[triple[1]], sites[triple[2]]});
  std::vector<Site> tied;
  for (Site_index s : tie) tied.push_back(sites[s]);
  // The order is the same all along the edge: at a vertex of it, or, with none, at its canonical point.
  const std::vector<std::size_t> order = at ? order_around_edge(t, diagram.vertices[*at].vertex, tied)
                                            : order_around_edge(t, arc_witness(t, std::nullopt, std::nullopt), tied);
  for (std::size_t k = 0; k < order.size(); ++k)
    halves.push_back({id, ordered(tie[order[k]], tie[order[(k + 1) % order.size()]])});
}

// The ends (2 h + side) of the half-edges of one pair at one vertex, two by two as they bound the face's
// sectors there. More than two when the vertex has 5 or more tied sites: by their order around the vertex
// on the pair's sheet, starting at a branch whose face side is decided (sheet_fan.h).
std::vector<std::array<std::size_t, 2>> sectors_at_vertex(const std::vector<Site>& sites, const Diagram& diagram,
                                                         const std::vector<Diagram_edge>& edges,
                                                         const std::vector<Half_edge>& halves, std::size_t vertex,
                                                         const Pair& pair, const std::vector<std::size_t>& ends) {
  if (ends.size() == 2) return {{ends[0], ends[1]}};
  const auto where = [&] {  // built only to throw: this runs at every vertex and pair
    return "at vertex " + std::to_string(vertex) + ", the faces of sites " + std::to_string(pair.first) + " and " +
           std::to_string(pair.second) + " meet " + std::to_string(ends.size()) + " edges";
  };
  if (ends.size() % 2 != 0) throw std::logic_error(where());
  std::vector<std::unique_ptr<Trisector>> curves;
  std::vector<Sheet_branch> branches;
  for (std::size_t end : ends) {
    const std::vector<Site_index>& tie = edges[halves[end / 2].edge].tie_set;
    const std::array<Site_index, 3> triple{tie[0], tie[1], tie[2]};
    curves.push_back(std::make_unique<Trisector>(
        triple, std::array<Site, 3>{sites[triple[0]], sites[triple[1]], sites[triple[2]]}));
    std::vector<Site> others;
    for (Site_index s : tie)
      if (s != pair.first && s != pair.second) others.push_back(sites[s]);
    branches.push_back({curves.back().get(), end % 2 == 0 ? +1 : -1, std::move(others)});
  }
  const Vertex& v = diagram.vertices[vertex].vertex;
  const Site &a = sites[pair.first], &b = sites[pair.second];
  const std::vector<std::size_t> order = order_on_sheet(v, a, b, branches);
  const std::size_t n = order.size();
  std::vector<Sign> turns(n);
  for (std::size_t k = 0; k < n; ++k) turns[k] = face_turn(v, a, b, branches[order[k]]);
  const auto decided = std::find_if(turns.begin(), turns.end(), [](Sign s) { return s != Sign::ZERO; });
  if (decided == turns.end()) throw std::logic_error(where() + ": no face side decided at first order");
  // Sector k: from order[k] counterclockwise to order[k + 1]; the face is in every other one.
  const std::size_t first = static_cast<std::size_t>(decided - turns.begin());
  const std::size_t offset = *decided == Sign::POSITIVE ? first % 2 : (first + 1) % 2;
  std::vector<std::array<std::size_t, 2>> sectors;
  for (std::size_t k = offset; k < n; k += 2) {
    const std::size_t next = (k + 1) % n;
    if (turns[k] == Sign::NEGATIVE || turns[next] == Sign::POSITIVE)
      throw std::logic_error(where() + ": their face sides do not alternate");
    sectors.push_back({ends[order[k]], ends[order[next]]});
  }
  return sectors;
}

}  // namespace

std::vector<Boundary_component> boundary_components(const std::vector<Site>& sites, const Diagram& diagram,
                                                    const std::vector<Diagram_edge>& edges,
                                                    const Cancellation* cancellation) {
  // Each edge has at most one half-edge per site of its tie set; their ends (2 h + side) fit in 32 bits.
  std::size_t most_halves = 0;
  for (const Diagram_edge& e : edges) most_halves += e.tie_set.size();
  if (2 * most_halves + 1 >= std::numeric_limits<std::uint32_t>::max())
    throw std::length_error("boundary_components: 2^31 half-edges or more");
  std::vector<Half_edge> halves;
  std::vector<std::size_t> first_half(edges.size() + 1, 0);  // edge e's half-edges: [first_half[e], first_half[e + 1])
  halves.reserve(3 * edges.size());  // three pairs around an edge of three tied sites
  for (std::size_t e = 0; e < edges.size(); ++e) {
    throw_if_cancelled(cancellation);
    add_pairs_around(sites, diagram, edges[e], static_cast<std::uint32_t>(e), halves);
    first_half[e + 1] = halves.size();
  }

  // At each vertex, the half-edges of one pair come in twos: link their ends (side 0: start, 1: end).
  constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::array<std::uint32_t, 2>> link(halves.size(), {kNone, kNone});  // 2 h + side of the other end
  // The edge ends at each vertex (2 e + side), placed by vertex in linear time; then, one vertex at a time,
  // its half-edge ends as (pair, 2 h + side), sorted: grouped by pair. (Not one list of every half-edge
  // end: its first touch of fresh memory was most of this function's time.)
  const Flat_lists<std::size_t> edge_ends(
      diagram.vertices.size(),
      [&](auto emit) {
        for (std::size_t e = 0; e < edges.size(); ++e) {
          if (edges[e].start) emit(*edges[e].start, 2 * e);
          if (edges[e].end) emit(*edges[e].end, 2 * e + 1);
        }
      },
      cancellation);
  std::vector<std::pair<Pair, std::size_t>> at_vertex;  // of one vertex
  std::vector<std::size_t> ends;
  for (std::size_t vertex = 0; vertex < diagram.vertices.size(); ++vertex) {
    if (vertex % 4096 == 0) throw_if_cancelled(cancellation);
    at_vertex.clear();
    for (const std::size_t end : edge_ends[vertex]) {
      const std::size_t e = end / 2, side = end % 2;
      for (std::size_t h = first_half[e]; h < first_half[e + 1]; ++h) at_vertex.push_back({halves[h].pair, 2 * h + side});
    }
    std::sort(at_vertex.begin(), at_vertex.end());
    for (std::size_t i = 0; i < at_vertex.size();) {
      const Pair pair = at_vertex[i].first;
      ends.clear();
      for (; i < at_vertex.size() && at_vertex[i].first == pair; ++i) ends.push_back(at_vertex[i].second);
      const auto join = [&](std::size_t x, std::size_t y) {
        link[x / 2][x % 2] = static_cast<std::uint32_t>(y);
        link[y / 2][y % 2] = static_cast<std::uint32_t>(x);
      };
      if (ends.size() == 2) {  // one sector: nearly every vertex and pair, with no allocation
        join(ends[0], ends[1]);
        continue;
      }
      for (const auto& [x, y] : sectors_at_vertex(sites, diagram, edges, halves, vertex, pair, ends)) join(x, y);
    }
  }

  // Walk: from a half-edge out of its end side, until back at the start or at infinity; an open chain is
  // then extended from the start's other side.
  std::vector<bool> visited(halves.size(), false);
  std::vector<Boundary_component> components;
  // About one per face, and F = E - V + C + 1 (Euler, with one cell per site): so that the list rarely moves.
  if (edges.size() + sites.size() > diagram.vertices.size())
    components.reserve(edges.size() + sites.size() - diagram.vertices.size() + 16);
  for (std::size_t first = 0; first < halves.size(); ++first) {
    if (first % 4096 == 0) throw_if_cancelled(cancellation);
    if (visited[first]) continue;
    Boundary_component c;
    c.a = halves[first].pair.first;
    c.b = halves[first].pair.second;
    std::vector<std::size_t>& forward = c.edges;  // the backward part of an open chain goes in front
    forward.push_back(halves[first].edge);
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
      c.edges.insert(c.edges.begin(), backward.rbegin(), backward.rend());
    }
    components.push_back(std::move(c));
  }
  // Components of one pair share no edge: their first edges order them as their lists do.
  cancellable_sort(components.begin(), components.end(), cancellation, [](const Boundary_component& x, const Boundary_component& y) {
    return std::tie(x.a, x.b, x.edges.front()) < std::tie(y.a, y.b, y.edges.front());
  });
  return components;
}

}  // namespace apollonius
