#include "certify/coordinate_tolerance.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace apollonius {

double input_scale(const std::vector<Site>& sites) {
  double scale = 0;
  for (const Site& s : sites)
    scale = std::max({scale, std::fabs(s.x), std::fabs(s.y), std::fabs(s.z), std::fabs(s.w)});
  return scale;
}

Coordinate_error coordinate_error(const std::array<double, 4>& claimed, const std::array<double, 4>& rounded_exact,
                                  double scale) {
  constexpr double infinity = std::numeric_limits<double>::infinity();
  Coordinate_error error;
  for (int j = 0; j < 4; ++j) {
    const double d = claimed[j] == rounded_exact[j] ? 0.0 : std::fabs(claimed[j] - rounded_exact[j]);
    const double unit = std::max(scale, std::fabs(rounded_exact[j]));
    // d / unit, where an infinite difference or a nonzero one at unit 0 is infinitely off.
    const double relative = d == 0 ? 0 : (std::isinf(d) || unit == 0 ? infinity : d / unit);
    error.absolute = std::max(error.absolute, d);
    error.relative = std::max(error.relative, relative);
  }
  return error;
}

}  // namespace apollonius
