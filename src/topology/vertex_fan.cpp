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
  std::vector<Site_index> tie_set(triple.begin(), triple.end());
  tie_set.insert(tie_set.end(), along.begin(), along.end());
  std::sort(tie_set.begin(), tie_set.end());
  if (forward) out.push_back({triple, tie_set, +1});
  if (backward) out.push_back({triple, std::move(tie_set), -1});
}

}  // namespace apollonius
