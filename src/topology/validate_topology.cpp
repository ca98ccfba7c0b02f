#include "topology/validate_topology.h"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

#include "diagram/flat_lists.h"
#include "topology/euler_characteristic.h"

namespace apollonius {
namespace {

template <class Subset>
bool holds(const std::vector<Site_index>& set, const Subset& subset) {
  return std::includes(set.begin(), set.end(), subset.begin(), subset.end());
}

[[noreturn]] void violated(const std::string& what) { throw std::logic_error("invalid diagram: " + what); }

}  // namespace

void validate_topology(const std::vector<Site>& sites, const Diagram_topology& t, const Cancellation* cancellation) {
  const std::vector<Diagram_vertex>& vertices = t.vertices.vertices;
  for (std::size_t e = 0; e < t.edges.size(); ++e) {
    if (e % 4096 == 0) throw_if_cancelled(cancellation);
    const Diagram_edge& edge = t.edges[e];
    if (edge.tie_set.size() < 3 || !std::is_sorted(edge.tie_set.begin(), edge.tie_set.end()))
      violated("edge " + std::to_string(e) + " has no ascending tie set of 3 or more");
    if (edge.closed && (edge.start || edge.end)) violated("closed edge " + std::to_string(e) + " has an end");
    if (e > 0 && !edge_precedes(t.edges[e - 1], edge))
      violated("edges " + std::to_string(e - 1) + " and " + std::to_string(e) + " are out of order or equal");
    for (const std::optional<std::size_t>& v : {edge.start, edge.end}) {
      if (!v) continue;
      if (*v >= vertices.size() || !holds(vertices[*v].tie_set, edge.tie_set))
        violated("edge " + std::to_string(e) + " ends at a vertex without its tie set");
    }
  }
  Flat_lists<Site_index> covered(  // the sites of the edges at each vertex
      vertices.size(),
      [&](auto emit) {
        for (const Diagram_edge& edge : t.edges)
          for (const std::optional<std::size_t>& v : {edge.start, edge.end})
            if (v)
              for (Site_index s : edge.tie_set) emit(*v, s);
      },
      cancellation);
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    if (v % 4096 == 0) throw_if_cancelled(cancellation);
    const auto sites_at = covered[v];
    std::sort(sites_at.begin(), sites_at.end());
    if (!std::equal(sites_at.begin(), std::unique(sites_at.begin(), sites_at.end()), vertices[v].tie_set.begin(),
                    vertices[v].tie_set.end()))
      violated("the edges at vertex " + std::to_string(v) + " miss one of its sites");
  }
  for (std::size_t f = 0; f < t.faces.size(); ++f) {
    if (f % 4096 == 0) throw_if_cancelled(cancellation);
    const Diagram_face& face = t.faces[f];
    const std::array<Site_index, 2> pair{face.a, face.b};
    for (const std::vector<std::size_t>& component : face.boundary) {
      if (component.empty()) violated("face " + std::to_string(f) + " has an empty boundary component");
      bool open = false;
      for (std::size_t k = 0; k < component.size(); ++k) {
        const Diagram_edge& e = t.edges.at(component[k]);
        if (!holds(e.tie_set, pair)) violated("face " + std::to_string(f) + " is bounded by an edge without its sites");
        open = open || (!e.closed && !(e.start && e.end));
        if (component.size() == 1) continue;
        // Consecutive edges meet at a vertex (a chain's two ends at infinity are not consecutive).
        const Diagram_edge& next = t.edges.at(component[(k + 1) % component.size()]);
        const bool meet = (e.start && (*e.start == next.start || *e.start == next.end)) ||
                          (e.end && (*e.end == next.start || *e.end == next.end));
        if (!meet && !(k + 1 == component.size() && open))
          violated("face " + std::to_string(f) + " has a boundary that does not close");
      }
    }
  }
  std::size_t cells = 0;
  std::vector<bool> hidden(sites.size(), false);
  for (const Hidden_site& h : t.vertices.hidden) hidden[h.site] = true;
  for (Site_index s = 0; s < sites.size(); ++s) cells += hidden[s] ? 0 : 1;
  if (t.cells.size() != cells) violated("a cell per site that is not hidden");
  if (const long defect = euler_defect(t); defect != 0)
    violated("the Euler relation is off by " + std::to_string(defect));
}

}  // namespace apollonius
