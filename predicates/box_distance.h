// The squared distance from a site centre to a box, its lengths times `scale`: a polynomial in the doubles
// involved, so it is exact in Exact and enclosed in Interval.
#pragma once

#include "predicates/axis_box.h"
#include "predicates/number_types.h"
#include "predicates/site.h"

namespace apollonius {

template <class NT>
NT squared_distance_to_box(const Site& s, const Axis_box& box, const NT& scale) {
  const double c[3] = {s.x, s.y, s.z};
  NT sum(0);
  for (int a = 0; a < 3; ++a) {
    if (c[a] < box.lo[a]) {
      const NT d = (NT(box.lo[a]) - NT(c[a])) * scale;
      sum = sum + d * d;
    } else if (c[a] > box.hi[a]) {
      const NT d = (NT(c[a]) - NT(box.hi[a])) * scale;
      sum = sum + d * d;
    }
  }
  return sum;
}

}  // namespace apollonius
