#include "centre_expansion.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace apollonius {
namespace {

constexpr double kUnit = 0x1p-53;  // unit roundoff of round-to-nearest doubles
constexpr double kInfinity = std::numeric_limits<double>::infinity();

}  // namespace

double distance_to_box(const Site& s, const Box_frame& frame) {
  const double p[3] = {s.x, s.y, s.z};
  double sum = 0;
  for (int a = 0; a < 3; ++a) {
    const double gap = p[a] < frame.box.lo[a] ? frame.box.lo[a] - p[a] : p[a] > frame.box.hi[a] ? p[a] - frame.box.hi[a] : 0;
    sum += gap * gap;
  }
  return in_error_bound_range(sum) ? std::sqrt(sum) : -1;
}

Box_frame frame_of(const Axis_box& box) {
  Box_frame frame{};
  frame.box = box;
  double squares = 0;
  for (int a = 0; a < 3; ++a) {
    frame.centre[a] = box.lo[a] + (box.hi[a] - box.lo[a]) / 2;
    // One subtraction each way; 1 + 4u covers its rounding (ERROR_BOUNDS.md, "Centre expansion", item 1).
    const double extent = std::max(frame.centre[a] - box.lo[a], box.hi[a] - frame.centre[a]);
    frame.half_extent[a] = extent * (1 + 4 * kUnit);
    squares += frame.half_extent[a] * frame.half_extent[a];
  }
  frame.reach = std::sqrt(squares) * (1 + 8 * kUnit);
  frame.reach_squared = frame.reach * frame.reach;
  frame.usable = squares >= kTinySquare && squares <= kHugeSquare;
  return frame;
}

Witness_expansion expand_witness(const Site& s, const Box_frame& frame) {
  Witness_expansion e;
  static_cast<Centre_expansion&>(e) = expand_at_centre(s, frame);
  e.distance_to_box = distance_to_box(s, frame);
  e.usable = e.usable && e.distance_to_box >= 0;
  e.curvature_term = e.distance_to_box > 0 ? frame.reach_squared / (2 * e.distance_to_box) : kInfinity;
  return e;
}

bool dominates_beyond_first_order(const Site& j, const Witness_expansion& at_j, const Site& i,
                                  const Centre_expansion& at_i, double rho_i, const Box_frame& frame, double linear) {
  const double gap = at_i.weighted - at_j.weighted;
  const double dx = i.x - j.x, dy = i.y - j.y, dz = i.z - j.z;
  const double separation_squared = dx * dx + dy * dy + dz * dz;
  const double rho_j = at_j.distance_to_box;
  if (!in_error_bound_range(separation_squared) || rho_i < 0) return false;
  const double separation = std::sqrt(separation_squared);
  const double rho_sum = rho_i + rho_j;
  const double two_sided =
      rho_i > 0 && rho_j > 0
          ? frame.reach_squared / 2 * (separation / (rho_i * rho_j) + 2 * separation / (rho_j * rho_sum))
          : kInfinity;
  const double lipschitz = rho_sum > 0 ? std::min(2.0, 2 * separation / rho_sum) : 2.0;
  const double bound = std::min(lipschitz * frame.reach, linear + std::min(at_j.curvature_term, two_sided));
  return certainly_exceeds(gap, bound, frame.reach + at_i.magnitude + at_j.magnitude + gap);
}

}  // namespace apollonius
