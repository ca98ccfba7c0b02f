#include "reference/brute_force_diagram.h"

#include <algorithm>

#include "predicates/compare_vertices.h"
#include "predicates/kernels.h"
#include "diagram/site_set.h"
#include "predicates/vertex_conflict.h"
#include "predicates/vertices_of.h"

namespace apollonius {
namespace {

// The tie set of v if no active site is strictly closer than v's own sites, otherwise nothing.
// `last_closer` remembers the site that last rejected a vertex and is tried first: it is often closer again.
bool tie_set_of(const Vertex& v, const std::vector<Site>& sites, const std::vector<Site_index>& active,
                Site_index& last_closer, std::vector<Site_index>& tie_set) {
  const auto& own = v.sites();
  auto is_own = [&](Site_index s) { return std::find(own.begin(), own.end(), s) != own.end(); };
  if (!is_own(last_closer) && vertex_conflict(v, sites[last_closer]) == Sign::NEGATIVE) return false;
  tie_set.assign(own.begin(), own.end());
  for (Site_index s : active) {
    if (is_own(s)) continue;
    const Sign sign = vertex_conflict(v, sites[s]);
    if (sign == Sign::NEGATIVE) {
      last_closer = s;
      return false;
    }
    if (sign == Sign::ZERO) tie_set.push_back(s);
  }
  std::sort(tie_set.begin(), tie_set.end());
  return true;
}

// Whether the two vertices certainly differ: their interval boxes are disjoint.
bool certainly_apart(const Vertex& u, const Vertex& v) {
  const std::array<Interval, 4> a = u.point_interval(), b = v.point_interval();
  for (int j = 0; j < 4; ++j)
    if (a[j].sup() < b[j].inf() || b[j].sup() < a[j].inf()) return true;
  return false;
}

// The root of `roots` that is u, given that u is one of them (at most two, distinct): the intervals tell
// most apart, compare_vertices the rest.
std::size_t root_equal_to(const Vertex& u, const Quadruple_vertices& roots) {
  if (roots.vertices.size() == 1) return 0;
  if (certainly_apart(roots.vertices[0], u)) return 1;
  if (certainly_apart(roots.vertices[1], u)) return 0;
  return compare_vertices(roots.vertices[0], u) == Sign::ZERO ? 0 : 1;
}

}  // namespace

Diagram brute_force_diagram(const std::vector<Site>& sites) {
  std::vector<Hidden_site> hidden = classify_hidden_sites<Certified_kernel>(sites);
  const std::vector<Site_index> active = active_sites(sites.size(), hidden);
  const std::size_t n = active.size();

  // A vertex with a tie set of 5 or more is a root of every quadruple of its tie set (it is equidistant to
  // them with a valid r). Once found, that root is not decided again: with k sites tied at one point that
  // saves C(k, 4) (n - 4) vertex_conflict calls, (k - 4) of each ending in the exact stage.
  std::vector<std::pair<std::vector<Site_index>, Vertex>> found;
  std::vector<std::size_t> degenerate;  // indices in `found` of the vertices with 5 or more tied sites
  Site_index last_closer = active.empty() ? 0 : active[0];
  std::vector<Site_index> tie_set;
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b)
      for (std::size_t c = b + 1; c < n; ++c)
        for (std::size_t d = c + 1; d < n; ++d) {
          const std::array<Site_index, 4> indices = {active[a], active[b], active[c], active[d]};
          const Quadruple_vertices roots = vertices_of(make_quadruple(indices, sites));
          std::array<bool, 2> known = {false, false};
          for (std::size_t f : degenerate) {
            const std::vector<Site_index>& tie = found[f].first;
            if (roots.vertices.empty() ||
                !std::all_of(indices.begin(), indices.end(), [&](Site_index s) { return std::binary_search(tie.begin(), tie.end(), s); }))
              continue;
            known[root_equal_to(found[f].second, roots)] = true;
          }
          for (std::size_t r = 0; r < roots.vertices.size(); ++r) {
            if (known[r] || !tie_set_of(roots.vertices[r], sites, active, last_closer, tie_set)) continue;
            if (tie_set.size() > 4) degenerate.push_back(found.size());
            found.emplace_back(tie_set, roots.vertices[r]);
          }
        }

  // Keep one vertex per point: the tie set is a function of the point, so equal points share a tie set.
  std::stable_sort(found.begin(), found.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<Diagram_vertex> unique;
  for (std::size_t i = 0; i < found.size();) {
    std::size_t end = i;
    while (end < found.size() && found[end].first == found[i].first) ++end;
    const std::size_t group_start = unique.size();
    for (std::size_t k = i; k < end; ++k) {
      const bool seen = std::any_of(unique.begin() + group_start, unique.end(), [&](const auto& u) {
        return compare_vertices(u.vertex, found[k].second) == Sign::ZERO;
      });
      if (!seen) unique.push_back({found[k].first, found[k].second});
    }
    i = end;
  }
  return assemble_diagram<Certified_kernel>(sites.size(), std::move(hidden), std::move(unique));
}

}  // namespace apollonius
