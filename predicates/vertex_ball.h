// The double-double stage of the vertex predicates (docs/design.md, "Arithmetic"): X of a vertex as
// double-double balls (double_double_ball.h), about 100 bits with a certified bound, between the interval
// filters (53 bits) and the exact stage. Sites one ulp off a lattice make vertices, and their conflicts and
// box bounds, differ by a few ulps of the coordinates, which intervals cannot tell and 106 bits can.
#pragma once

#include <array>
#include <cmath>
#include <optional>

#include "predicates/double_double_ball.h"
#include "predicates/rounding_guard.h"
#include "predicates/site.h"

namespace apollonius {

using Ball_coordinates = std::array<Double_double_ball, 4>;

// x - y, exactly (Knuth's TwoSum) unless it overflows, which leaves the ball unusable.
inline Double_double_ball ball_difference(double x, double y) {
  Double_double_ball d;
  double_double::two_sum(x, -y, d.hi, d.lo);
  return d;
}

// Exact unless hi / 2 falls below 2^-1021, which the 2^-511 of any sum with it covers.
inline Double_double_ball half(const Double_double_ball& x) { return {x.hi / 2, x.lo / 2, x.error / 2}; }

// The vertex centre coordinate o_j + X_j / 2 (j < 3) or r = X_3 / 2 - w_0 (j = 3), o the origin site.
inline Double_double_ball absolute_coordinate(const Site& origin, const Ball_coordinates& X, int j) {
  const double offset[4] = {origin.x, origin.y, origin.z, -origin.w};
  return Double_double_ball(offset[j]) + half(X[j]);
}

}  // namespace apollonius
