#include "box_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace apollonius {
namespace {

constexpr double kUnit = 0x1p-53;
constexpr double kTiny = 0x1p-960, kHuge = 0x1p960;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

bool in_range(double sum_of_squares) { return sum_of_squares == 0 || (sum_of_squares >= kTiny && sum_of_squares <= kHuge); }

Distance_bounds bounds_of(double sum_of_squares, double w) {
  if (!in_range(sum_of_squares) || !(std::fabs(w) <= kHuge)) return {-kInfinity, kInfinity};
  const double distance = std::sqrt(sum_of_squares);
  const double error = 8 * kUnit * (distance + std::fabs(w));
  return {(distance - w) - error, (distance - w) + error};
}

}  // namespace

Distance_bounds least_distance_bounds(const Site& s, const Axis_box& box) {
  const double c[3] = {s.x, s.y, s.z};
  double sum = 0;
  for (int a = 0; a < 3; ++a) {
    const double d = c[a] < box.lo[a] ? box.lo[a] - c[a] : c[a] > box.hi[a] ? c[a] - box.hi[a] : 0;
    sum += d * d;
  }
  return bounds_of(sum, s.w);
}

Distance_bounds greatest_distance_bounds(const Site& s, const Axis_box& box) {
  const double c[3] = {s.x, s.y, s.z};
  double sum = 0;
  for (int a = 0; a < 3; ++a) {
    const double d = std::max(std::fabs(c[a] - box.lo[a]), std::fabs(box.hi[a] - c[a]));
    sum += d * d;
  }
  return bounds_of(sum, s.w);
}

}  // namespace apollonius
