#include "topology/vertex_fan.h"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <utility>

#include "predicates/rounding_guard.h"
#include "predicates/trisector_predicates.h"

namespace apollonius {
namespace {

const std::optional<Sign> kUncertain;

// Per site of the tie set, the sign of t.(n_s - n_i) where certain and not zero (the first order of d_s - r
// along t), else nothing. Returns false when two sites have opposite certain signs.
bool first_order_sides(const Tie_gradients& n, const std::array<std::size_t, 3>& positions,
                       std::vector<std::optional<Sign>>& sides) {
  Rounding_guard guard;
  const auto minus = [](const std::array<Interval, 3>& a, const std::array<Interval, 3>& b) {
    return std::array<Interval, 3>{a[0] - b[0], a[1] - b[1], a[2] - b[2]};
  };
  const std::array<Interval, 3>& base = n[positions[0]];
  const std::array<Interval, 3> u = minus(n[positions[1]], base), w = minus(n[positions[2]], base);
  const std::array<Interval, 3> t = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
  bool positive = false, negative = false;
  sides.assign(n.size(), std::nullopt);
  for (std::size_t m = 0; m < n.size(); ++m) {
    const std::array<Interval, 3> d = minus(n[m], base);
    const Interval value = t[0] * d[0] + t[1] * d[1] + t[2] * d[2];
    if (value.inf() > 0) sides[m] = Sign::POSITIVE, positive = true;
    if (value.sup() < 0) sides[m] = Sign::NEGATIVE, negative = true;
  }
  return !(positive && negative);
}

}  // namespace

void departures_along(const std::vector<Site>& sites, const Diagram_vertex& v, const Trisector& trisector,
                      const std::array<std::size_t, 3>& positions, std::vector<Departure>& out,
                      const Tie_gradients* gradients) {
  const std::vector<Site_index>& tie = v.tie_set;
  const std::size_t k = tie.size();
  const std::array<Site_index, 3>& triple = trisector.indices();
  std::vector<std::optional<Sign>> first_order;  // empty without gradients
  if (gradients != nullptr && !first_order_sides(*gradients, positions, first_order)) return;  // both sides lose
  std::optional<Sign> forward_along_t;  // POSITIVE: forward is along t
  bool forward = true, backward = true;
  std::vector<Site_index> along;  // the other sites that tie along the whole curve
  for (std::size_t m = 0; m < k && (forward || backward); ++m) {
    if (m == positions[0] || m == positions[1] || m == positions[2]) continue;
    const std::optional<Sign>& side = first_order.empty() ? kUncertain : first_order[m];
    std::pair<Sign, Sign> sides;
    if (side.has_value() && forward_along_t.has_value()) {
      const Sign first = *forward_along_t * *side;
      sides = {first, -first};
    } else {
      sides = sides_near_vertex(trisector, v.vertex, sites[tie[m]]);
    }
    const auto [after, before] = sides;
    if (side.has_value() && !forward_along_t.has_value() && after != Sign::ZERO && before == -after)
      forward_along_t = after * side.value();
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
