// Squared distances from a site centre to a box: to its nearest point and to its farthest corner. Both are
// polynomials in the doubles involved, so they are exact in Exact and enclosed in Interval.
#pragma once

#include <algorithm>

#include "axis_box.h"
#include "number_types.h"
#include "site.h"

namespace apollonius {

template <class NT>
NT squared_distance_to_box(const Site& s, const Axis_box& box) {
  const double c[3] = {s.x, s.y, s.z};
  NT sum(0);
  for (int a = 0; a < 3; ++a) {
    if (c[a] < box.lo[a]) {
      const NT d = NT(box.lo[a]) - NT(c[a]);
      sum = sum + d * d;
    } else if (c[a] > box.hi[a]) {
      const NT d = NT(c[a]) - NT(box.hi[a]);
      sum = sum + d * d;
    }
  }
  return sum;
}

inline Interval maximum(const Interval& x, const Interval& y) {
  return Interval(std::max(x.inf(), y.inf()), std::max(x.sup(), y.sup()));
}
inline Exact maximum(const Exact& x, const Exact& y) { return x < y ? y : x; }

template <class NT>
NT squared_distance_to_farthest_corner(const Site& s, const Axis_box& box) {
  const double c[3] = {s.x, s.y, s.z};
  NT sum(0);
  for (int a = 0; a < 3; ++a) {
    // Which bound is farther is itself decided in NT: c - lo and hi - c are not exact doubles.
    const NT to_lo = NT(c[a]) - NT(box.lo[a]), to_hi = NT(box.hi[a]) - NT(c[a]);
    sum = sum + maximum(to_lo * to_lo, to_hi * to_hi);
  }
  return sum;
}

// Certified double bounds (ERROR_BOUNDS.md, "Distance bounds"), without any rounding-mode change, of the
// least weighted distance min_box |x - p| - w and of the greatest, max_box |x - p| - w. Out of the range
// where the bound holds they are [-inf, +inf].
struct Distance_bounds {
  double lower, upper;
};
Distance_bounds least_distance_bounds(const Site& s, const Axis_box& box);
Distance_bounds greatest_distance_bounds(const Site& s, const Axis_box& box);

}  // namespace apollonius
