#include "diagram/diagram.h"

#include <algorithm>
#include <cstdint>

#include "diagram/cancellable_steps.h"
#include "predicates/kernels.h"

namespace apollonius {

namespace {

// A vertex's place in the sort, compared without reaching the vertex for all but equal heads: every tie set
// has four or more sites, so its first four (in `head`, two to a word, the first high) start the
// lexicographic order of the tie sets.
static_assert(sizeof(Site_index) == 4, "two sites to a 64-bit word");
struct Sort_key {
  std::array<std::uint64_t, 2> head;
  std::size_t tie_size;
  std::size_t position;  // where the vertex lies
};

// Asks for the cache lines of v ahead of a move from it.
void prefetch(const Diagram_vertex& v) {
  const char* first = reinterpret_cast<const char*>(&v);
  for (std::size_t offset = 0; offset < sizeof(Diagram_vertex); offset += 64) __builtin_prefetch(first + offset);
}

// Puts vertices[order[i]] at i for every i, moving each vertex once (one cycle of the permutation at a
// time); `order` ends as the identity. The vertices come in refinement order and go in site order, so
// each move reads a vertex far from the last one: the vertex kLookahead moves ahead on the cycle is
// fetched meanwhile (a cycle's positions ahead of j still hold their targets; past its end the lookahead
// stays on a settled position).
void permute_in_place(std::vector<Diagram_vertex>& vertices, std::vector<std::size_t>& order, const Cancellation* cancellation) {
  constexpr int kLookahead = 4;
  std::size_t moves = 0;
  for (std::size_t i = 0; i < order.size(); ++i) {
    if (order[i] == i) continue;
    std::size_t ahead = i;
    for (int step = 0; step < kLookahead; ++step) prefetch(vertices[ahead = order[ahead]]);
    Diagram_vertex held = std::move(vertices[i]);
    std::size_t j = i;
    while (order[j] != i) {
      if (++moves % 4096 == 0) throw_if_cancelled(cancellation);
      prefetch(vertices[ahead = order[ahead]]);
      const std::size_t k = order[j];
      vertices[j] = std::move(vertices[k]);
      order[j] = j;
      j = k;
    }
    vertices[j] = std::move(held);
    order[j] = j;
  }
}

}  // namespace

template <class Kernel>
Diagram assemble_diagram(std::size_t site_count, std::vector<Hidden_site> hidden, std::vector<Diagram_vertex> vertices,
                         const Cancellation* cancellation) {
  Diagram diagram;
  diagram.site_count = site_count;
  diagram.hidden = std::move(hidden);
  std::vector<Sort_key> keys(vertices.size());
  for (std::size_t k = 0; k < vertices.size(); ++k) {
    if (k % 1024 == 0) throw_if_cancelled(cancellation);
    Diagram_vertex& v = vertices[k];
    if (!v.is_rounded()) v.rounded = Kernel::printed_coordinates(v.vertex);
    const auto pair = [&](int i) { return std::uint64_t{v.tie_set[i]} << 32 | v.tie_set[i + 1]; };
    keys[k] = {{pair(0), pair(2)}, v.tie_set.size(), k};
  }
  // docs/contract.md orders lines by tie set (lexicographic, a prefix first), then by printed values; equal
  // printed values fall back to the exact order.
  cancellable_sort(keys.begin(), keys.end(), cancellation, [&](const Sort_key& a, const Sort_key& b) {
    if (a.head[0] != b.head[0]) return a.head[0] < b.head[0];
    if (a.head[1] != b.head[1]) return a.head[1] < b.head[1];
    const Diagram_vertex &u = vertices[a.position], &v = vertices[b.position];
    if (a.tie_size > 4 || b.tie_size > 4) {
      const auto [p, q] = std::mismatch(u.tie_set.begin() + 4, u.tie_set.end(), v.tie_set.begin() + 4, v.tie_set.end());
      if (p != u.tie_set.end() || q != v.tie_set.end()) return q != v.tie_set.end() && (p == u.tie_set.end() || *p < *q);
    }
    if (u.rounded != v.rounded) return u.rounded < v.rounded;
    return Kernel::compare(u.vertex, v.vertex) == Sign::NEGATIVE;
  });
  std::vector<std::size_t> order(keys.size());
  for (std::size_t i = 0; i < keys.size(); ++i) order[i] = keys[i].position;
  std::vector<Sort_key>().swap(keys);
  permute_in_place(vertices, order, cancellation);
  diagram.vertices = std::move(vertices);

  std::vector<bool> has_vertex(site_count, false), is_hidden_site(site_count, false);
  for (const Diagram_vertex& v : diagram.vertices)
    for (Site_index s : v.tie_set) has_vertex[s] = true;
  for (const Hidden_site& h : diagram.hidden) is_hidden_site[h.site] = true;
  for (Site_index s = 0; s < site_count; ++s)
    if (!has_vertex[s] && !is_hidden_site[s]) diagram.sites_without_vertex.push_back(s);
  return diagram;
}

template <class Kernel>
Diagram assemble_diagram(std::size_t site_count, std::vector<Hidden_site> hidden,
                         std::vector<std::vector<Diagram_vertex>> lists, const Cancellation* cancellation) {
  return assemble_diagram<Kernel>(site_count, std::move(hidden), gathered(lists, cancellation), cancellation);
}

template Diagram assemble_diagram<Certified_kernel>(std::size_t, std::vector<Hidden_site>, std::vector<Diagram_vertex>,
                                                   const Cancellation*);
template Diagram assemble_diagram<Floating_kernel>(std::size_t, std::vector<Hidden_site>, std::vector<Diagram_vertex>,
                                                  const Cancellation*);
template Diagram assemble_diagram<Certified_kernel>(std::size_t, std::vector<Hidden_site>,
                                                   std::vector<std::vector<Diagram_vertex>>, const Cancellation*);
template Diagram assemble_diagram<Floating_kernel>(std::size_t, std::vector<Hidden_site>,
                                                  std::vector<std::vector<Diagram_vertex>>, const Cancellation*);

void restrict_to_box(Diagram& diagram, const Axis_box& box) {
  const auto outside = [&](const Diagram_vertex& v) { return !vertex_in_box(v.vertex, box, std::array<bool, 3>{true, true, true}); };
  diagram.vertices.erase(std::remove_if(diagram.vertices.begin(), diagram.vertices.end(), outside), diagram.vertices.end());
}

}  // namespace apollonius
