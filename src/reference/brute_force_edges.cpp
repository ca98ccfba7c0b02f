#include "reference/brute_force_edges.h"

#include <algorithm>

#include "predicates/arc_witness.h"
#include "predicates/trisector_predicates.h"

namespace apollonius {

std::vector<Diagram_edge> brute_force_edges(const std::vector<Site>& sites, const Diagram& diagram) {
  std::vector<bool> hidden(sites.size(), false);
  for (const Hidden_site& h : diagram.hidden) hidden[h.site] = true;
  std::vector<Site_index> active;
  for (Site_index s = 0; s < sites.size(); ++s)
    if (!hidden[s]) active.push_back(s);

  std::vector<Diagram_edge> edges;
  for (std::size_t i = 0; i < active.size(); ++i)
    for (std::size_t j = i + 1; j < active.size(); ++j)
      for (std::size_t k = j + 1; k < active.size(); ++k) {
        const std::array<Site_index, 3> triple{active[i], active[j], active[k]};
        const Trisector t(triple, {sites[triple[0]], sites[triple[1]], sites[triple[2]]});
        const Trisector_kind kind = classify_trisector(t).first;
        const Curve_shape shape = classify_trisector(t).second;
        if (kind != Trisector_kind::ellipse && kind != Trisector_kind::hyperbola && kind != Trisector_kind::parabola)
          continue;
        std::vector<std::size_t> on_curve;  // vertex ids whose tie set holds the triple
        for (std::size_t v = 0; v < diagram.vertices.size(); ++v) {
          const std::vector<Site_index>& tie = diagram.vertices[v].tie_set;
          if (std::includes(tie.begin(), tie.end(), triple.begin(), triple.end())) on_curve.push_back(v);
        }
        std::sort(on_curve.begin(), on_curve.end(), [&](std::size_t u, std::size_t v) {
          return compare_along_trisector(t, diagram.vertices[u].vertex, diagram.vertices[v].vertex) == Sign::NEGATIVE;
        });
        // Arcs: from infinity (open curves) or the last vertex (closed), then between consecutive vertices.
        const bool closed = kind == Trisector_kind::ellipse;
        const std::size_t n = on_curve.size();
        const std::size_t arcs = closed ? std::max<std::size_t>(n, 1) : n + 1;
        for (std::size_t a = 0; a < arcs; ++a) {
          std::optional<std::size_t> from, to;
          if (closed && n > 0) {
            from = on_curve[(a + n - 1) % n];
            to = on_curve[a];
          } else if (!closed) {
            if (a > 0) from = on_curve[a - 1];
            if (a < n) to = on_curve[a];
          }
          const auto end = [&](const std::optional<std::size_t>& v) -> std::optional<Arc_end> {
            if (!v) return std::nullopt;
            return Arc_end(&diagram.vertices[*v].vertex);
          };
          const Curve_point witness = arc_witness(t, end(from), end(to));
          std::vector<Site_index> tie_set(triple.begin(), triple.end());
          bool in_diagram = true;
          for (Site_index s : active) {
            if (s == triple[0] || s == triple[1] || s == triple[2]) continue;
            const Sign c = curve_point_conflict(witness, sites[s]);
            if (c == Sign::NEGATIVE) {
              in_diagram = false;
              break;
            }
            if (c == Sign::ZERO) tie_set.push_back(s);
          }
          std::sort(tie_set.begin(), tie_set.end());
          if (!in_diagram || !std::equal(triple.begin(), triple.end(), tie_set.begin())) continue;
          Diagram_edge e;
          e.tie_set = tie_set;
          e.curve = shape;
          e.start = from;
          e.end = to;
          e.closed = closed && n == 0;
          edges.push_back(std::move(e));
        }
      }
  std::sort(edges.begin(), edges.end(), [](const Diagram_edge& x, const Diagram_edge& y) {
    if (x.tie_set != y.tie_set) return x.tie_set < y.tie_set;
    if (x.start != y.start) return x.start < y.start;
    return x.end < y.end;
  });
  return edges;
}

}  // namespace apollonius
