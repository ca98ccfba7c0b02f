#include "diagram.h"

#include <algorithm>
#include <numeric>

#include "kernels.h"

namespace apollonius {

template <class Kernel>
Diagram assemble_diagram(std::size_t site_count, std::vector<Hidden_site> hidden,
                         std::vector<std::pair<std::vector<Site_index>, Vertex>> vertices) {
  Diagram diagram;
  diagram.site_count = site_count;
  diagram.hidden = std::move(hidden);
  std::vector<Diagram_vertex> found;
  found.reserve(vertices.size());
  for (auto& [tie_set, vertex] : vertices) {
    const std::array<double, 4> rounded = Kernel::printed_coordinates(vertex);
    found.push_back(Diagram_vertex{std::move(tie_set), std::move(vertex), rounded});
  }
  // SPEC section 4 orders lines by printed values; equal printed values fall back to the exact order.
  // Sorted by index, then moved once: a Diagram_vertex is large.
  std::vector<std::size_t> order(found.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const Diagram_vertex &u = found[a], &v = found[b];
    // One pass over the tie sets (lexicographic, a prefix first).
    const auto [p, q] = std::mismatch(u.tie_set.begin(), u.tie_set.end(), v.tie_set.begin(), v.tie_set.end());
    if (p != u.tie_set.end() || q != v.tie_set.end()) return q != v.tie_set.end() && (p == u.tie_set.end() || *p < *q);
    if (u.rounded != v.rounded) return u.rounded < v.rounded;
    return Kernel::compare(u.vertex, v.vertex) == Sign::NEGATIVE;
  });
  diagram.vertices.reserve(found.size());
  for (std::size_t k : order) diagram.vertices.push_back(std::move(found[k]));

  std::vector<bool> has_vertex(site_count, false), is_hidden_site(site_count, false);
  for (const Diagram_vertex& v : diagram.vertices)
    for (Site_index s : v.tie_set) has_vertex[s] = true;
  for (const Hidden_site& h : diagram.hidden) is_hidden_site[h.site] = true;
  for (Site_index s = 0; s < site_count; ++s)
    if (!has_vertex[s] && !is_hidden_site[s]) diagram.sites_without_vertex.push_back(s);
  return diagram;
}

template Diagram assemble_diagram<Certified_kernel>(std::size_t, std::vector<Hidden_site>,
                                                   std::vector<std::pair<std::vector<Site_index>, Vertex>>);
template Diagram assemble_diagram<Floating_kernel>(std::size_t, std::vector<Hidden_site>,
                                                  std::vector<std::pair<std::vector<Site_index>, Vertex>>);

void restrict_to_box(Diagram& diagram, const Axis_box& box) {
  const auto outside = [&](const Diagram_vertex& v) { return !vertex_in_box(v.vertex, box, std::array<bool, 3>{true, true, true}); };
  diagram.vertices.erase(std::remove_if(diagram.vertices.begin(), diagram.vertices.end(), outside), diagram.vertices.end());
}

}  // namespace apollonius
