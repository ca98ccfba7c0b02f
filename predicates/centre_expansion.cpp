#include "centre_expansion.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace apollonius {
namespace {

constexpr double kUnit = 0x1p-53;  // unit roundoff of round-to-nearest doubles
constexpr double kInfinity = std::numeric_limits<double>::infinity();

}  // namespace

Box_frame frame_of(const Axis_box& box) {
  Box_frame frame{};
  frame.box = box;
  double squares = 0;
  for (int a = 0; a < 3; ++a) {
    frame.centre[a] = box.lo[a] + (box.hi[a] - box.lo[a]) / 2;
    frame.corner_offset[0][a] = box.lo[a] - frame.centre[a];
    frame.corner_offset[1][a] = box.hi[a] - frame.centre[a];
    // One subtraction each way; 1 + 4u covers its rounding (ERROR_BOUNDS.md, "Centre expansion", item 1).
    const double extent = std::max(-frame.corner_offset[0][a], frame.corner_offset[1][a]);
    frame.half_extent[a] = extent * (1 + 4 * kUnit);
    squares += frame.half_extent[a] * frame.half_extent[a];
  }
  frame.reach = std::sqrt(squares) * (1 + 8 * kUnit);
  frame.reach_squared = frame.reach * frame.reach;
  frame.usable = squares >= kTinySquare && squares <= kHugeSquare;
  return frame;
}

double distance_to_box(const Site& s, const Box_frame& frame) {
  const double p[3] = {s.x, s.y, s.z};
  double sum = 0;
  for (int a = 0; a < 3; ++a) {
    const double below = frame.box.lo[a] - p[a], above = p[a] - frame.box.hi[a];
    const double gap = below > 0 ? below : above > 0 ? above : 0;
    sum += gap * gap;
  }
  return in_error_bound_range(sum) ? std::sqrt(sum) : -1;
}

Witness_expansion expand_witness(const Site& s, const Box_frame& frame) {
  Witness_expansion e;
  static_cast<Centre_expansion&>(e) = expand_at_centre(s, frame);
  e.distance_to_box = distance_to_box(s, frame);
  e.usable = e.usable && e.distance_to_box >= 0;
  return e;
}

void add_corners(Witness_expansion& e, const Site& s, const Box_frame& frame) {
  double largest = 0;
  for (int q = 0; q < 8; ++q) {
    const double dx = (q & 1 ? frame.box.hi[0] : frame.box.lo[0]) - s.x;
    const double dy = (q & 2 ? frame.box.hi[1] : frame.box.lo[1]) - s.y;
    const double dz = (q & 4 ? frame.box.hi[2] : frame.box.lo[2]) - s.z;
    const double squared = dx * dx + dy * dy + dz * dz;
    e.usable = e.usable && in_error_bound_range(squared);
    const double distance = std::sqrt(squared);
    e.corner[q] = distance - s.w;
    largest = std::max(largest, distance);
  }
  e.corner_magnitude = largest + std::fabs(s.w);
  e.has_corners = true;
}

bool far_dominates(const Site& j, const Witness_expansion& at_j, const Site& i, const Centre_expansion& at_i,
                   double rho_i, const Box_frame& frame, double linear, double slack) {
  const double gap = at_i.weighted - at_j.weighted;
  const double dx = i.x - j.x, dy = i.y - j.y, dz = i.z - j.z;
  const double separation_squared = dx * dx + dy * dy + dz * dz;
  const double rho_j = at_j.distance_to_box;
  if (!in_error_bound_range(separation_squared) || rho_i < 0) return false;
  const double separation = std::sqrt(separation_squared);
  const double rho_sum = rho_i + rho_j;
  const double curvature =
      rho_i > 0 && rho_j > 0 ? frame.reach_squared / 2 * (separation / (rho_i * rho_j) + 2 * separation / (rho_j * rho_sum))
                             : kInfinity;
  const double lipschitz = rho_sum > 0 ? std::min(2.0, 2 * separation / rho_sum) : 2.0;
  const double bound = std::min(lipschitz * frame.reach, linear + curvature);
  // The slack covers the rounding errors of f(c) and of the bound (ERROR_BOUNDS.md, "Centre expansion").
  return bound + slack * 64 * kUnit * (bound + frame.reach + at_i.magnitude + at_j.magnitude + gap) < gap;
}

}  // namespace apollonius
