#include "diagram/diagram.h"

#include <algorithm>
#include <numeric>

#include "diagram/cancellable_steps.h"
#include "predicates/kernels.h"

namespace apollonius {

template <class Kernel>
Diagram assemble_diagram(std::size_t site_count, std::vector<Hidden_site> hidden,
                         std::vector<std::pair<std::vector<Site_index>, Vertex>> vertices,
                         const Cancellation* cancellation) {
  Diagram diagram;
  diagram.site_count = site_count;
  diagram.hidden = std::move(hidden);
  std::vector<std::array<double, 4>> rounded(vertices.size());
  for (std::size_t k = 0; k < vertices.size(); ++k) {
    if (k % 1024 == 0) throw_if_cancelled(cancellation);
    rounded[k] = Kernel::printed_coordinates(vertices[k].second);
  }
  // docs/contract.md orders lines by printed values; equal printed values fall back to the exact order.
  // Sorted by index, then each vertex moved once: they are large, and one copy of them at a time is enough.
  std::vector<std::size_t> order(vertices.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  cancellable_sort(order.begin(), order.end(), cancellation, [&](std::size_t a, std::size_t b) {
    const std::vector<Site_index>&u = vertices[a].first, &v = vertices[b].first;
    // One pass over the tie sets (lexicographic, a prefix first).
    const auto [p, q] = std::mismatch(u.begin(), u.end(), v.begin(), v.end());
    if (p != u.end() || q != v.end()) return q != v.end() && (p == u.end() || *p < *q);
    if (rounded[a] != rounded[b]) return rounded[a] < rounded[b];
    return Kernel::compare(vertices[a].second, vertices[b].second) == Sign::NEGATIVE;
  });
  diagram.vertices.reserve(vertices.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    if (i % 4096 == 0) throw_if_cancelled(cancellation);
    const std::size_t k = order[i];
    diagram.vertices.push_back(Diagram_vertex{std::move(vertices[k].first), std::move(vertices[k].second), rounded[k]});
  }
  std::vector<std::pair<std::vector<Site_index>, Vertex>>().swap(vertices);

  std::vector<bool> has_vertex(site_count, false), is_hidden_site(site_count, false);
  for (const Diagram_vertex& v : diagram.vertices)
    for (Site_index s : v.tie_set) has_vertex[s] = true;
  for (const Hidden_site& h : diagram.hidden) is_hidden_site[h.site] = true;
  for (Site_index s = 0; s < site_count; ++s)
    if (!has_vertex[s] && !is_hidden_site[s]) diagram.sites_without_vertex.push_back(s);
  return diagram;
}

template Diagram assemble_diagram<Certified_kernel>(std::size_t, std::vector<Hidden_site>,
                                                   std::vector<std::pair<std::vector<Site_index>, Vertex>>,
                                                   const Cancellation*);
template Diagram assemble_diagram<Floating_kernel>(std::size_t, std::vector<Hidden_site>,
                                                  std::vector<std::pair<std::vector<Site_index>, Vertex>>,
                                                  const Cancellation*);

void restrict_to_box(Diagram& diagram, const Axis_box& box) {
  const auto outside = [&](const Diagram_vertex& v) { return !vertex_in_box(v.vertex, box, std::array<bool, 3>{true, true, true}); };
  diagram.vertices.erase(std::remove_if(diagram.vertices.begin(), diagram.vertices.end(), outside), diagram.vertices.end());
}

}  // namespace apollonius
