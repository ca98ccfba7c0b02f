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

using Direction = std::array<Interval, 3>;  // as Tie_gradients' entries

Direction minus(const Direction& a, const Direction& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

// The signs that v's enclosures tell, per site of the tie set, without a predicate:
//  - first[m]: the sign of t.(n_m - n_i) where certain and not zero (the first order of d_m - r along t);
//  - second[m]: where that first order is certainly 0 (n_m on the circle of the triple's n_i, n_j, n_l) and
//    the lifts L_k = 1 / D_k are given (tie_gradients), the sign of d_m - r on both sides of v, where
//    certain. It is second order's (1 - c^2) (L_m - sum_k alpha_k L_k) / 2, with n_m = sum_k alpha_k n_k the
//    affine combination of the triple's (departure_star.cpp, settle_first_order_tie; c = nu.n_k, |c| < 1):
//    the sign of h = (L_m - L_i) det(j, l) - det(m, l) (L_j - L_i) - det(j, m) (L_l - L_i) times that of
//    det(j, l), for the n_k - n_i projected along an axis where t is certainly not 0 (bijective on the
//    circle's plane). Zero or uncertain: the predicate decides (third order, or a tie along the curve).
// Returns false when two sites have opposite certain first-order signs.
bool enclosed_sides(const Tie_gradients& n, const std::vector<Interval>* lifts,
                    const std::array<std::size_t, 3>& positions, std::vector<std::optional<Sign>>& first,
                    std::vector<std::optional<Sign>>& second) {
  Rounding_guard guard;
  const Direction& base = n[positions[0]];
  const Direction u = minus(n[positions[1]], base), w = minus(n[positions[2]], base);
  const Direction t = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
  bool positive = false, negative = false;
  first.assign(n.size(), std::nullopt);
  second.assign(n.size(), std::nullopt);
  // The projection's axis: the component of t farthest from 0 for certain, if any.
  int axis = -1;
  double clearance = 0;
  for (int a = 0; a < 3 && lifts != nullptr; ++a) {
    const double apart = t[a].inf() > 0 ? t[a].inf() : t[a].sup() < 0 ? -t[a].sup() : 0;
    if (apart > clearance) axis = a, clearance = apart;
  }
  const int p = (axis + 1) % 3, q = (axis + 2) % 3;
  const auto det = [&](const Direction& x, const Direction& y) { return x[p] * y[q] - x[q] * y[p]; };
  Interval base_lift(0), u_lift(0), w_lift(0), area(0);
  Sign area_sign = Sign::ZERO;
  if (axis >= 0) {
    base_lift = (*lifts)[positions[0]];
    u_lift = (*lifts)[positions[1]] - base_lift;
    w_lift = (*lifts)[positions[2]] - base_lift;
    area = det(u, w);
    if (area.inf() > 0) area_sign = Sign::POSITIVE;
    if (area.sup() < 0) area_sign = Sign::NEGATIVE;
  }
  for (std::size_t m = 0; m < n.size(); ++m) {
    const Direction d = minus(n[m], base);
    const Interval value = t[0] * d[0] + t[1] * d[1] + t[2] * d[2];
    if (value.inf() > 0) first[m] = Sign::POSITIVE, positive = true;
    if (value.sup() < 0) first[m] = Sign::NEGATIVE, negative = true;
    if (value.inf() == 0 && value.sup() == 0 && area_sign != Sign::ZERO) {  // certainly 0
      const Interval h = ((*lifts)[m] - base_lift) * area - det(d, w) * u_lift - det(u, d) * w_lift;
      if (h.inf() > 0) second[m] = area_sign;
      if (h.sup() < 0) second[m] = -area_sign;
    }
  }
  return !(positive && negative);
}

}  // namespace

void departures_along(const std::vector<Site>& sites, const Diagram_vertex& v, const Trisector& trisector,
                      const std::array<std::size_t, 3>& positions, std::vector<Departure>& out,
                      const Tie_gradients* gradients, const std::vector<Interval>* lifts) {
  const std::vector<Site_index>& tie = v.tie_set;
  const std::size_t k = tie.size();
  const std::array<Site_index, 3>& triple = trisector.indices();
  std::vector<std::optional<Sign>> first_order, second_order;  // empty without gradients
  if (gradients != nullptr && !enclosed_sides(*gradients, lifts, positions, first_order, second_order))
    return;  // both sides lose
  std::optional<Sign> forward_along_t;  // POSITIVE: forward is along t
  bool forward = true, backward = true;
  std::vector<Site_index> along;  // the other sites that tie along the whole curve
  for (std::size_t m = 0; m < k && (forward || backward); ++m) {
    if (m == positions[0] || m == positions[1] || m == positions[2]) continue;
    const std::optional<Sign>& side = first_order.empty() ? kUncertain : first_order[m];
    std::pair<Sign, Sign> sides;
    if (!second_order.empty() && second_order[m].has_value()) {
      sides = {*second_order[m], *second_order[m]};
    } else if (side.has_value() && forward_along_t.has_value()) {
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
