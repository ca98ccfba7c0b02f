#include "topology/vertex_fan.h"

#include <algorithm>
#include <stdexcept>

#include "predicates/trisector_predicates.h"

namespace apollonius {

void departures_along(const std::vector<Site>& sites, const Diagram_vertex& v, const Trisector& trisector,
                      const std::array<std::size_t, 3>& positions, std::vector<Departure>& out) {
  const std::vector<Site_index>& tie = v.tie_set;
  const std::size_t k = tie.size();
  const std::array<Site_index, 3>& triple = trisector.indices();
  bool forward = true, backward = true;
  std::vector<Site_index> along;  // the other sites that tie along the whole curve
  for (std::size_t m = 0; m < k && (forward || backward); ++m) {
    if (m == positions[0] || m == positions[1] || m == positions[2]) continue;
    const auto [after, before] = sides_near_vertex(trisector, v.vertex, sites[tie[m]]);
    if (after == Sign::ZERO && before == Sign::ZERO) {
      along.push_back(tie[m]);
      continue;
    }
    forward = forward && after == Sign::POSITIVE;
    backward = backward && before == Sign::POSITIVE;
  }
  if (!forward && !backward) return;
  // Counted once, from the smallest triple of the edge's tie set.
  if (!along.empty() && along.front() < triple[2]) return;
  if (forward && backward && along.size() + 3 == k)
    throw std::logic_error("departures_along: every tied site ties along one curve at a vertex");
  for (const int direction : {+1, -1}) {
    if ((direction > 0 && !forward) || (direction < 0 && !backward)) continue;
    Departure& d = out.emplace_back();  // built in place: each tie set inline, no copy
    d.triple = triple;
    d.direction = direction;
    d.tie_set.assign(triple.begin(), triple.end());
    for (Site_index s : along) d.tie_set.push_back(s);
    std::sort(d.tie_set.begin(), d.tie_set.end());
  }
}

}  // namespace apollonius
