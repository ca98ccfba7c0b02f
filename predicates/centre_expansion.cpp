#include "predicates/centre_expansion.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace apollonius {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Units are 2^-k for |k| <= kLargestUnitExponent, so that 2^-k and 2^k are normal numbers. Built from the
// bits rather than by ldexp: every box is framed, and libm's scalbn showed in profiles.
constexpr int kLargestUnitExponent = 1000;

// The k with 2^k <= x < 2^(k + 1) for a positive normal x, -1023 for a subnormal one, clamped to units.
int unit_exponent(double x) {
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  const int exponent = static_cast<int>(bits >> 52 & 0x7ff) - 1023;
  return std::clamp(exponent, -kLargestUnitExponent, kLargestUnitExponent);
}

double power_of_two(int k) {
  const std::uint64_t bits = static_cast<std::uint64_t>(k + 1023) << 52;
  double x;
  std::memcpy(&x, &bits, sizeof x);
  return x;
}

}  // namespace

Box_frame frame_of(const Axis_box& box) {
  Box_frame frame{};
  frame.box = box;
  std::array<double, 3> extent;
  double longest = 0;
  for (int a = 0; a < 3; ++a) {
    frame.centre[a] = box.lo[a] + (box.hi[a] - box.lo[a]) / 2;
    extent[a] = std::max(frame.centre[a] - box.lo[a], box.hi[a] - frame.centre[a]);
    longest = std::max(longest, extent[a]);
  }
  // Box units: the longest half-extent in [1, 2), unless it lies beyond 2^+-1000 (docs/ERROR_BOUNDS.md item 1).
  frame.exponent = unit_exponent(longest);
  frame.unit = power_of_two(-frame.exponent);
  double squares = 0;
  for (int a = 0; a < 3; ++a) {
    frame.corner_offset[0][a] = (box.lo[a] - frame.centre[a]) * frame.unit;
    frame.corner_offset[1][a] = (box.hi[a] - frame.centre[a]) * frame.unit;
    // One subtraction each way; 1 + 4u covers its rounding (docs/ERROR_BOUNDS.md, "Centre expansion", item 1).
    frame.half_extent[a] = extent[a] * frame.unit * (1 + 4 * kUnitRoundoff);
    squares += frame.half_extent[a] * frame.half_extent[a];
  }
  frame.reach = std::sqrt(squares) * (1 + 8 * kUnitRoundoff);
  frame.reach_squared = frame.reach * frame.reach;
  frame.usable = squares >= kTinySquare && squares <= kHugeSquare;
  return frame;
}

void sharpen(Centre_expansion& e, const Site& s, const Box_frame& frame) {
  const Sharp_centre_value sharp = sharp_centre_value(s, frame);
  if (!sharp.known) return;
  e.weighted = sharp.value;
  e.weighted_error = sharp.error;
  e.weighted_known = true;
}

double distance_to_box(const Site& s, const Box_frame& frame) {
  const double p[3] = {s.x, s.y, s.z};
  double sum = 0;
  for (int a = 0; a < 3; ++a) {
    const double below = frame.box.lo[a] - p[a], above = p[a] - frame.box.hi[a];
    const double gap = (below > 0 ? below : above > 0 ? above : 0) * frame.unit;
    sum += gap * gap;
  }
  return in_error_bound_range(sum) ? std::sqrt(sum) : -1;
}

void add_corners(Witness_expansion& e, const Site& s, const Box_frame& frame) {
  const double centre[3] = {s.x, s.y, s.z};
  double square[2][3];  // (y_a - x_a)^2 in box units, for the lower and upper bound of axis a
  for (int a = 0; a < 3; ++a) {
    const double below = (frame.box.lo[a] - centre[a]) * frame.unit, above = (frame.box.hi[a] - centre[a]) * frame.unit;
    square[0][a] = below * below;
    square[1][a] = above * above;
  }
  std::array<double, 8> squared;
  for (int q = 0; q < 8; ++q) squared[q] = square[q & 1][0] + square[q >> 1 & 1][1] + square[q >> 2 & 1][2];
  const auto [least, most] = std::minmax_element(squared.begin(), squared.end());
  // Checked per corner only when some corner is 0 or out of range (or NaN).
  const bool in_range = (*least >= kTinySquare && *most <= kHugeSquare) ||
                        std::all_of(squared.begin(), squared.end(), in_error_bound_range);
  for (int q = 0; q < 8; ++q) e.corner_distance[q] = std::sqrt(squared[q]);
  e.usable = e.usable && in_range;
  e.farthest_corner = std::sqrt(*most);
  e.has_corners = true;
}

namespace {

// What (B) needs of the pair (i, j) in pair units, from p = (x_j - x_i) 2^-exponent (centre_expansion.h;
// docs/ERROR_BOUNDS.md item 4). Usable when |c - x_i| + |c - x_j| is at least 2^-470 box units.
struct Pair_at_centre {
  int exponent;                     // the largest |p_a| lies in [1, 2) (unless |exponent| = 1000)
  std::array<double, 3> towards_j;  // p
  double weight_difference;         // (w_i - w_j) 2^-exponent
  double distance_difference;       // (|c - x_i| - |c - x_j|) 2^-exponent
  bool usable;
};

Pair_at_centre pair_at_centre(const Site& i, const Centre_expansion& at_i, const Site& j, const Centre_expansion& at_j) {
  Pair_at_centre pair{};
  const std::array<double, 3> difference = {j.x - i.x, j.y - i.y, j.z - i.z};
  const double largest = std::max({std::fabs(difference[0]), std::fabs(difference[1]), std::fabs(difference[2])});
  pair.usable = largest > 0 && largest < kInfinity && at_i.distance + at_j.distance >= 0x1p-470;
  if (!pair.usable) return pair;
  pair.exponent = unit_exponent(largest);
  const double unit = power_of_two(-pair.exponent);
  std::array<double, 3>& p = pair.towards_j;
  for (int a = 0; a < 3; ++a) p[a] = difference[a] * unit;
  pair.weight_difference = (i.w - j.w) * unit;
  double dot = 0;
  for (int a = 0; a < 3; ++a) dot += p[a] * (at_i.offset[a] + at_j.offset[a]);
  pair.distance_difference = dot / (at_i.distance + at_j.distance);
  return pair;
}

}  // namespace

double centre_difference(const Site& i, const Centre_expansion& at_i, const Site& j, const Centre_expansion& at_j) {
  const Pair_at_centre pair = pair_at_centre(i, at_i, j, at_j);
  return pair.usable ? pair.distance_difference - pair.weight_difference : at_i.weighted - at_j.weighted;
}

bool far_dominates(const Site& j, const Witness_expansion& at_j, const Site& i, const Centre_expansion& at_i,
                   double rho_i, const Box_frame& frame, double slack) {
  const Pair_at_centre pair = pair_at_centre(i, at_i, j, at_j);
  if (!pair.usable || rho_i < 0) return false;
  const double gap = pair.distance_difference - pair.weight_difference;
  // g = (p - u q) / |c - x_k| over the larger of the two distances, u the other site's gradient; g h is
  // in pair units as p is, h and |c - x_k| both in box units.
  const bool over_i = at_i.distance >= at_j.distance;
  const std::array<double, 3>& u = over_i ? at_j.gradient : at_i.gradient;
  const double inverse = 1 / (over_i ? at_i.distance : at_j.distance);
  double linear = 0;
  for (int a = 0; a < 3; ++a)
    linear += std::fabs((pair.towards_j[a] - u[a] * pair.distance_difference) * inverse) * frame.half_extent[a];
  if (!(gap > linear)) return false;

  const std::array<double, 3>& p = pair.towards_j;
  const double separation = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);  // |p|
  const double rho_j = distance_to_box(j, frame);
  if (rho_j < 0) return false;
  const double rho_sum = rho_i + rho_j;
  const double curvature =
      rho_i > 0 && rho_j > 0 ? frame.reach_squared / 2 * (separation / (rho_i * rho_j) + 2 * separation / (rho_j * rho_sum))
                             : kInfinity;
  // L H with L = min(2, 2D / (rho_i + rho_j)); the 2 H term converted to pair units (inf if it overflows).
  const int shift = frame.exponent - pair.exponent;  // in [-2000, 2000]: two steps keep the factors normal
  const double reach = frame.reach * power_of_two(shift / 2) * power_of_two(shift - shift / 2);
  const double lipschitz_reach = rho_sum > 0 ? std::min(2 * reach, 2 * separation * frame.reach / rho_sum) : 2 * reach;
  const double bound = std::min(lipschitz_reach, linear + curvature);
  // The slack covers the rounding errors of f(c) and of the bound (docs/ERROR_BOUNDS.md, "Centre expansion").
  const double error_scale =
      bound + separation + std::fabs(pair.weight_difference) + gap + 2 * separation * frame.reach * inverse;
  return bound + slack * 64 * kUnitRoundoff * error_scale < gap;
}

}  // namespace apollonius
