// A certified test for removing a candidate site from a box: site j (the witness) is strictly closer than
// site i at every point of the box if, with c the box centre, f = d_i - d_j and h_a the half-extents,
//     f(c) > min( L H,  sum_a |g_a| h_a + kappa H^2 / 2 ),                                   (*)
// where H bounds |x - c| on the box, g = grad d_i(c) - grad d_j(c), and
//  - L = min(2, 2 |x_i - x_j| / (rho_i + rho_j)) bounds |grad f| on the box (Dunkl-Williams), rho_k being
//    the distance from x_k to the box;
//  - kappa bounds the curvature of -f on the box: d_i is convex, so f(x) >= f(c) + g.(x - c) - |x - c|^2 / 2
//    times the largest eigenvalue of Hess d_j, at most 1 / rho_j; and since Hess d_i - Hess d_j has norm at
//    most D / (r_i r_j) + 2 D / (r_j (r_i + r_j)) (D = |x_i - x_j|, r_k = |x - x_k| >= rho_k), far boxes
//    get kappa ~ D / rho^2.
// This refines paper Theorem 6, which needs f(c) > 2H: near a bisector that is flat over the box, (*)
// removes a site as soon as the box does not cross the bisector, for either order of the weights (the
// paper's Theorems 7 and 8 separate the two cases). It is evaluated in plain doubles with the error bound
// derived in ERROR_BOUNDS.md ("Centre expansion"), and only ever certifies; a site it cannot remove stays
// a candidate.
#pragma once

#include <array>
#include <cmath>

#include "axis_box.h"
#include "site.h"

namespace apollonius {

// The box seen from its centre. Invariant: when usable, every point x of the box has |x_a - c_a| <=
// half_extent[a] and |x - c| <= reach.
struct Box_frame {
  Axis_box box;
  std::array<double, 3> centre;
  std::array<double, 3> half_extent;
  double reach, reach_squared;
  bool usable;
};

Box_frame frame_of(const Axis_box& box);

// d_s near the box centre, as computed in doubles (each value within the bounds of ERROR_BOUNDS.md).
struct Centre_expansion {
  double distance;                 // |c - x_s|
  double weighted;                 // |c - x_s| - w_s = d_s(c)
  std::array<double, 3> gradient;  // (c - x_s) / |c - x_s|, or 0 when c = x_s (a subgradient)
  double magnitude;                // |c - x_s| + |w_s|: the scale of the rounding errors of `weighted`
  bool usable;                     // every magnitude lies where the error bounds hold
};

// A witness also needs its distance to the box, rho_j, and the one-sided curvature term H^2 / (2 rho_j).
struct Witness_expansion : Centre_expansion {
  double distance_to_box;  // 0 when x_j lies in the box
  double curvature_term;   // H^2 / (2 rho_j), infinite when rho_j = 0
};

// Sums of squares inside [kTinySquare, kHugeSquare] (or exactly 0) keep the relative error bounds of
// ERROR_BOUNDS.md: underflowed terms are then negligible and nothing overflows.
constexpr double kTinySquare = 0x1p-960, kHugeSquare = 0x1p960, kHugeWeight = 0x1p480;
inline bool in_error_bound_range(double sum_of_squares) {
  return sum_of_squares == 0 || (sum_of_squares >= kTinySquare && sum_of_squares <= kHugeSquare);
}

// Inline: the refinement expands every candidate of every box.
inline Centre_expansion expand_at_centre(const Site& s, const Box_frame& frame) {
  Centre_expansion e;
  const double offset[3] = {frame.centre[0] - s.x, frame.centre[1] - s.y, frame.centre[2] - s.z};
  const double squared = offset[0] * offset[0] + offset[1] * offset[1] + offset[2] * offset[2];
  e.usable = frame.usable && in_error_bound_range(squared) && std::fabs(s.w) <= kHugeWeight;
  e.distance = std::sqrt(squared);
  e.weighted = e.distance - s.w;
  e.magnitude = e.distance + std::fabs(s.w);
  const double inverse = e.distance > 0 ? 1 / e.distance : 0;
  for (int a = 0; a < 3; ++a) e.gradient[a] = offset[a] * inverse;
  return e;
}

Witness_expansion expand_witness(const Site& s, const Box_frame& frame);

// The computed distance from x_s to the box of `frame` (rho_s), or -1 out of range.
double distance_to_box(const Site& s, const Box_frame& frame);

// The second stage of expansion_dominates: two-sided curvature and the Lipschitz bound. rho_i is
// distance_to_box(i, frame), computed once per candidate by the caller.
bool dominates_beyond_first_order(const Site& j, const Witness_expansion& at_j, const Site& i,
                                  const Centre_expansion& at_i, double rho_i, const Box_frame& frame, double linear);

// Whether f(c) = gap certainly exceeds `bound`, computed in doubles from expansions whose magnitudes
// sum to `scale` (reach + |c - x_i| + |w_i| + |c - x_j| + |w_j| + gap): the slack covers the rounding
// errors of f(c) and of the bound (ERROR_BOUNDS.md "Centre expansion", item 6).
inline bool certainly_exceeds(double gap, double bound, double scale) {
  constexpr double kUnit = 0x1p-53;
  return bound + 64 * kUnit * (bound + scale) < gap;
}

// The first stage of the test: the first-order term sum_a |g_a| h_a with the one-sided curvature
// 1 / rho_j, decisive for most boxes. Returns whether it certifies, and sets `linear`.
inline bool first_order_dominates(const Witness_expansion& at_j, const Centre_expansion& at_i, const Box_frame& frame,
                                  double& linear) {
  const double gap = at_i.weighted - at_j.weighted;  // f(c)
  linear = 0;
  for (int a = 0; a < 3; ++a) linear += std::fabs(at_i.gradient[a] - at_j.gradient[a]) * frame.half_extent[a];
  return gap > 0 && at_i.usable && at_j.usable &&
         certainly_exceeds(gap, linear + at_j.curvature_term, frame.reach + at_i.magnitude + at_j.magnitude + gap);
}

// True only if j is certainly strictly closer than i at every point of the box of `frame`. `rho_i`
// holds distance_to_box(i, frame) once computed (negative before), for the second stage.
inline bool expansion_dominates(const Site& j, const Witness_expansion& at_j, const Site& i,
                                const Centre_expansion& at_i, const Box_frame& frame, double& rho_i) {
  double linear;
  if (first_order_dominates(at_j, at_i, frame, linear)) return true;
  // Both other bounds are at least `linear`.
  if (!(at_i.weighted - at_j.weighted > linear) || !at_i.usable || !at_j.usable) return false;
  if (rho_i < 0) rho_i = distance_to_box(i, frame);
  return dominates_beyond_first_order(j, at_j, i, at_i, rho_i, frame, linear);
}

}  // namespace apollonius
