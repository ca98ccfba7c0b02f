#include "topology/trisector_edges.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

#include "diagram/threads.h"
#include "diagram/cancellable_steps.h"
#include "predicates/trisector_predicates.h"

namespace apollonius {
namespace {

// One departure, as its curve sees it.
struct Departure_on_curve {
  std::size_t vertex;
  int direction;
  const Departure::Sites* tie_set;
};

std::string describe(const std::array<Site_index, 3>& triple) {
  return std::to_string(triple[0]) + " " + std::to_string(triple[1]) + " " + std::to_string(triple[2]);
}

// The edges of one curve from its departures, sorted along it.
void pair_departures(const Trisector& trisector, Trisector_kind kind, Curve_shape shape, const Diagram& diagram,
                     std::vector<Departure_on_curve>& on_curve, std::vector<Diagram_edge>& out) {
  // Along the curve; at one vertex the arriving edge (backward) comes before the leaving one.
  const auto before = [&](const Departure_on_curve& x, const Departure_on_curve& y) {
    if (x.vertex != y.vertex) {
      const Sign s = compare_along_trisector(trisector, diagram.vertices[x.vertex].vertex, diagram.vertices[y.vertex].vertex);
      if (s != Sign::ZERO) return s == Sign::NEGATIVE;
      throw std::logic_error("two vertices at one point of the trisector " + describe(trisector.indices()));
    }
    return x.direction < y.direction;
  };
  // Two departures (nearly every curve): one comparison, where the insertion sort makes two.
  if (on_curve.size() == 2) {
    if (before(on_curve[1], on_curve[0])) std::swap(on_curve[0], on_curve[1]);
  } else {
    std::sort(on_curve.begin(), on_curve.end(), before);
  }
  const std::size_t n = on_curve.size();
  const bool closed = kind == Trisector_kind::ellipse;
  if (kind != Trisector_kind::ellipse && kind != Trisector_kind::hyperbola && kind != Trisector_kind::parabola)
    throw std::logic_error("departures along the trisector " + describe(trisector.indices()) + ", which is no curve");
  for (std::size_t i = 0; i < n; ++i) {
    const Departure_on_curve& d = on_curve[i];
    const bool has_next = closed || i + 1 < n;
    const Departure_on_curve* next = has_next ? &on_curve[(i + 1) % n] : nullptr;
    const bool has_previous = closed || i > 0;
    const Departure_on_curve* previous = has_previous ? &on_curve[(i + n - 1) % n] : nullptr;
    // Leaving forward: the next departure arrives (leaves backward), or the curve goes to infinity.
    if (d.direction > 0) {
      if (next != nullptr && next->direction > 0)
        throw std::logic_error("two edges leave forward in a row along the trisector " + describe(trisector.indices()));
      if (next != nullptr && *next->tie_set != *d.tie_set)
        throw std::logic_error("an edge changes its tie set along the trisector " + describe(trisector.indices()));
      Diagram_edge e;
      e.tie_set.assign(d.tie_set->begin(), d.tie_set->end());
      e.curve = shape;
      e.start = d.vertex;
      if (next != nullptr) e.end = next->vertex;
      out.push_back(std::move(e));
    } else if (previous == nullptr) {  // arriving from infinity
      Diagram_edge e;
      e.tie_set.assign(d.tie_set->begin(), d.tie_set->end());
      e.curve = shape;
      e.end = d.vertex;
      out.push_back(std::move(e));
    } else if (previous->direction < 0) {
      throw std::logic_error("two edges leave backward in a row along the trisector " + describe(trisector.indices()));
    }
  }
}

}  // namespace

std::vector<Diagram_edge> edges_through_vertices(const std::vector<Site>& sites, const Diagram& diagram, int threads,
                                                 const Cancellation* cancellation) {
  const Vertex_triples triples(sites, diagram, cancellation);
  return edges_through_vertices(sites, diagram, triples, threads, cancellation);
}

std::vector<Diagram_edge> edges_through_vertices(const std::vector<Site>& sites, const Diagram& diagram,
                                                 const Vertex_triples& triples, int threads,
                                                 const Cancellation* cancellation) {
  // Every (triple of a vertex's tie set, vertex), grouped by triple: each trisector is built once, for
  // all the vertices on it (a generic one has two).
  const std::vector<Vertex_triple>& entries = triples.all();
  std::vector<std::size_t> group_start;
  for (std::size_t i = 0; i < entries.size(); ++i)
    if (i == 0 || entries[i].triple != entries[i - 1].triple) group_start.push_back(i);
  group_start.push_back(entries.size());

  // The gradients and lifts (1 / |v - p_k|) of the large tie sets, for their first- and second-order sides
  // (vertex_fan.h), by vertex.
  struct Large_tie {
    std::size_t vertex;
    Tie_gradients gradients;
    std::vector<Interval> lifts;
  };
  const std::size_t small_up_to = triples.every_triple_up_to();
  std::vector<Large_tie> large;
  for (std::size_t v = 0; v < diagram.vertices.size(); ++v) {
    if (diagram.vertices[v].tie_set.size() <= small_up_to) continue;
    Large_tie tie{v, {}, {}};
    if (tie_gradients(sites, diagram.vertices[v], tie.gradients, &tie.lifts)) large.push_back(std::move(tie));
  }
  const auto large_tie_of = [&](std::size_t v) -> const Large_tie* {
    if (diagram.vertices[v].tie_set.size() <= small_up_to) return nullptr;
    const auto before = [](const Large_tie& x, std::size_t w) { return x.vertex < w; };
    const auto at = std::lower_bound(large.begin(), large.end(), v, before);
    return at != large.end() && at->vertex == v ? &*at : nullptr;
  };

  // Groups in chunks of consecutive curves, each chunk's edges in its own list: the output is the same
  // for every thread count, and there is no list (nor scratch vectors) per curve. One thread: one chunk,
  // which is the result, with room for one edge per (triple, vertex) pair, so that it never moves: a
  // generic vertex has four triples and ends four edges, each with one end or two, so 2 to 4 edges per
  // vertex (room for 2 was too little: docs/benchmarks.md, "Lists that never move"). Room never filled is
  // address space, not memory.
  const std::size_t curves = group_start.size() - 1;
  const std::size_t curves_per_chunk = threads <= 1 ? std::max<std::size_t>(curves, 1) : 256;
  std::vector<std::vector<Diagram_edge>> by_chunk((curves + curves_per_chunk - 1) / curves_per_chunk);
  if (by_chunk.size() == 1) by_chunk.front().reserve(entries.size() + 16);
  tbb::task_arena arena(usable_threads(threads));
  arena.execute([&] {
    tbb::parallel_for(std::size_t{0}, by_chunk.size(), [&](std::size_t chunk) {
      std::vector<Departure> departures;
      std::vector<std::size_t> vertex_of;  // of each departure
      std::vector<Departure_on_curve> on_curve;
      std::vector<Diagram_edge>& out = by_chunk[chunk];
      for (std::size_t g = chunk * curves_per_chunk; g < std::min(curves, (chunk + 1) * curves_per_chunk); ++g) {
        throw_if_cancelled(cancellation);  // a throw cancels the parallel loop
        const std::array<Site_index, 3>& triple = entries[group_start[g]].triple;
        const Trisector trisector(triple, {sites[triple[0]], sites[triple[1]], sites[triple[2]]});
        departures.clear();
        vertex_of.clear();
        for (std::size_t i = group_start[g]; i < group_start[g + 1]; ++i) {
          const Diagram_vertex& v = diagram.vertices[entries[i].vertex];
          std::array<std::size_t, 3> positions{};  // of the triple's sites in the vertex's tie set
          for (int m = 0; m < 3; ++m)
            positions[m] = static_cast<std::size_t>(std::lower_bound(v.tie_set.begin(), v.tie_set.end(), triple[m]) - v.tie_set.begin());
          const Large_tie* tie = large_tie_of(entries[i].vertex);
          departures_along(sites, v, trisector, positions, departures, tie != nullptr ? &tie->gradients : nullptr,
                           tie != nullptr ? &tie->lifts : nullptr);
          vertex_of.resize(departures.size(), entries[i].vertex);
        }
        if (departures.empty()) continue;
        on_curve.clear();
        for (std::size_t d = 0; d < departures.size(); ++d)
          on_curve.push_back({vertex_of[d], departures[d].direction, &departures[d].tie_set});
        const auto [kind, shape] = classify_trisector(trisector);
        const std::size_t first = out.size();
        pair_departures(trisector, kind, shape, diagram, on_curve, out);
        std::sort(out.begin() + static_cast<std::ptrdiff_t>(first), out.end(), edge_precedes);
      }
    });
  });
  // Sorted: a tie set begins with its triple, so the tie sets of curves in ascending order of triple
  // ascend, and each curve's edges are sorted.
  if (by_chunk.size() == 1) return std::move(by_chunk.front());
  std::vector<Diagram_edge> edges;
  move_concatenated(by_chunk, edges, cancellation);
  return edges;
}

}  // namespace apollonius
