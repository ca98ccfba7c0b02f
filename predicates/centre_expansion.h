// Certified tests for removing a candidate site i from a box: site j (the witness) is strictly closer than
// i at every point of the box. With c the box centre, u_k = grad d_k(c) and y the eight corners:
//
//  (A) Corners. With W = w_j - w_i and T(x) = |x - x_j| - W, so that d_i - d_j = |x - x_i| - T,
//          G(x) = |x - x_i|^2 - |x - x_j|^2 + 2W |x - x_j| - W^2 = |x - x_i|^2 - T(x)^2,
//      and G > 0 on the box gives |x - x_i| > |T| >= T there: j dominates i. The first two terms of G
//      differ by an affine function of x, and 2W |x - x_j| is bounded below by a function affine in each
//      coordinate: for W > 0 by 2W b_j(x), b_j(x) = |c - x_j| + u_j.(x - c) the tangent plane of the convex
//      |x - x_j|; for W <= 0 by 2W times the trilinear interpolation of |y - x_j| (Jensen). That bound of G
//      is least at a corner, so j dominates i on the box if at each corner y
//          |y - x_i|^2 - |y - x_j|^2 + 2W b_j(y) - W^2 > 0      (W > 0),
//          |y - x_i|^2 - (|y - x_j| - W)^2 > 0                  (W <= 0).
//      W <= 0, a witness no larger than i, is paper Theorem 8.1, and exact up to rounding: G is concave, so
//      least at a corner, and d_i(y) > d_j(y) gives |y - x_i| > T(y) >= 0, hence G(y) > 0. W > 0 replaces
//      Theorem 8.2 (the bisector's tangent plane) and gives away 2W (|x - x_j| - b_j(x)) of G: little
//      while W is small against |c - x_j|, as for the atoms of a molecule.
//  (B) Far boxes. With f = d_i - d_j, g = u_i - u_j, h_a the half-extents and H >= |x - c| on the box,
//          f(c) > min( L H,  sum_a |g_a| h_a + kappa H^2 / 2 )
//      where L = min(2, 2D / (rho_i + rho_j)) bounds |grad f| (Dunkl-Williams; D = |x_i - x_j|, rho_k the
//      distance from x_k to the box) and kappa = D / (rho_i rho_j) + 2D / (rho_j (rho_i + rho_j)) bounds
//      the norm of Hess d_i - Hess d_j: both sites far from the box, their curvatures nearly cancel.
//      f(c) and g are computed from x_j - x_i, not as differences of two large distances or gradients,
//      so that (B) still separates two sites seen from a box a million million times farther away than
//      they are apart (docs/ERROR_BOUNDS.md, "Centre expansion", item 4):
//          |c - x_i| - |c - x_j| = (x_j - x_i).((c - x_i) + (c - x_j)) / (|c - x_i| + |c - x_j|) =: q,
//          u_i - u_j = ((x_j - x_i) - u_j q) / |c - x_i| = ((x_j - x_i) - u_i q) / |c - x_j|.
//
// Before both, the Lipschitz test: |grad d_k| <= 1, so f(c) > 2 reach >= 2 |x - c| gives f > 0 on the box.
// Neither is tried where f(c) - sum_a |g_a| h_a certainly falls below 0 (centre_tests).
//
// All are evaluated in plain doubles with the error bounds of docs/ERROR_BOUNDS.md ("Centre expansion") and
// only ever certify; a site they cannot remove stays a candidate. The `slack` argument multiplies those
// bounds: 1 on the certified path, 0 on the floating path (kernels.h).
//
// Units. Both tests are homogeneous of degree 1 in lengths, so they are evaluated in box units (lengths
// times a power of two that brings the box to size about 1), and (B)'s differences in pair units (times a
// power of two that brings x_j - x_i to size about 1). The squares then stay in the double range for any
// box and any pair of sites within 2^480 box sizes of it: sites 10^160 apart, or at 10^-300, are separated
// as well as sites 1 apart at 1.
#pragma once

#include <array>
#include <cmath>

#include "predicates/axis_box.h"
#include "predicates/sharp_centre_value.h"
#include "predicates/site.h"
#include "predicates/unit_roundoff.h"

namespace apollonius {

// The box seen from its centre, in box units: a length L is L * unit. Invariant: when usable, every point x
// of the box has |x_a - c_a| unit <= half_extent[a] and |x - c| unit <= reach; corner_offset[s][a] is
// (y_a - c_a) unit for the lower (s = 0) or upper (s = 1) bound of axis a.
struct Box_frame {
  Axis_box box;
  std::array<double, 3> centre;  // in the input's units
  int exponent;                  // unit = 2^-exponent; the longest half-extent is about 2^exponent, |exponent| <= 1000
  double unit;
  std::array<double, 3> half_extent;
  std::array<std::array<double, 3>, 2> corner_offset;
  double reach, reach_squared;
  bool usable;
};

Box_frame frame_of(const Axis_box& box);

// d_s near the box centre in box units, as computed in doubles (within the bounds of docs/ERROR_BOUNDS.md).
struct Centre_expansion {
  std::array<double, 3> offset;    // c - x_s
  double distance;                 // |c - x_s|
  double weighted;                 // |c - x_s| - w_s = d_s(c)
  std::array<double, 3> gradient;  // (c - x_s) / |c - x_s|, or 0 when c = x_s (a subgradient)
  double magnitude;                // |c - x_s| + |w_s|: the scale of the rounding errors of `weighted`
  bool usable;                     // every magnitude lies where the error bounds hold
  // |weighted - d_s(c)| <= weighted_error when weighted_known: 8u magnitude when usable (docs/ERROR_BOUNDS.md
  // item 2), or the sharp value's bound where that replaced it (item 8).
  double weighted_error;
  bool weighted_known;
};

// A witness also needs |y - x_j| at the corners (corner_distance[q], corner q having the upper bound on
// axis a when bit a of q is set), computed when first needed (add_corners): test (A) uses them when the
// witness is no larger than the candidate.
struct Witness_expansion : Centre_expansion {
  bool has_corners = false;
  std::array<double, 8> corner_distance;
  double farthest_corner;  // the largest corner_distance
};

// Sums of squares inside [kTinySquare, kHugeSquare] (or exactly 0) keep the relative error bounds of
// docs/ERROR_BOUNDS.md: underflowed terms are then negligible and nothing overflows.
constexpr double kTinySquare = 0x1p-960, kHugeSquare = 0x1p960, kHugeWeight = 0x1p480;
inline bool in_error_bound_range(double sum_of_squares) {
  return sum_of_squares == 0 || (sum_of_squares >= kTinySquare && sum_of_squares <= kHugeSquare);
}

// Where the plain value is unknown, or its error exceeds a 64th of the box's reach, the sharp value replaces
// it (sharp_centre_value.h): the centre tests then still decide about a ball whose sphere, far larger than
// the box, passes near it. Ordinary inputs never come here: their box counts did not change
// (docs/history.md).
constexpr double kSharpenAbove = 0x1p-6;
void sharpen(Centre_expansion& e, const Site& s, const Box_frame& frame);

// Inline: the refinement expands every candidate of every box. Written into `e` in place: keep_undominated
// fills an array of them, where a returned value was built on the stack and copied with 16-byte loads of its
// 8-byte stores, which stall store forwarding.
inline void expand_at_centre(const Site& s, const Box_frame& frame, Centre_expansion& e) {
  e.offset = {(frame.centre[0] - s.x) * frame.unit, (frame.centre[1] - s.y) * frame.unit,
              (frame.centre[2] - s.z) * frame.unit};
  const std::array<double, 3>& offset = e.offset;
  const double squared = offset[0] * offset[0] + offset[1] * offset[1] + offset[2] * offset[2];
  const double weight = s.w * frame.unit;
  e.usable = frame.usable && in_error_bound_range(squared) && std::fabs(weight) <= kHugeWeight;
  e.distance = std::sqrt(squared);
  e.weighted = e.distance - weight;
  e.magnitude = e.distance + std::fabs(weight);
  const double inverse = e.distance > 0 ? 1 / e.distance : 0;
  for (int a = 0; a < 3; ++a) e.gradient[a] = offset[a] * inverse;
  e.weighted_error = 8 * kUnitRoundoff * e.magnitude;
  e.weighted_known = e.usable;
  if (!(e.usable && e.weighted_error <= kSharpenAbove * frame.reach)) sharpen(e, s, frame);
}
inline Centre_expansion expand_at_centre(const Site& s, const Box_frame& frame) {
  Centre_expansion e;
  expand_at_centre(s, frame, e);
  return e;
}

// From the witness's centre expansion, when the caller has it already.
inline Witness_expansion expand_witness(const Centre_expansion& at_centre) {
  Witness_expansion e;
  static_cast<Centre_expansion&>(e) = at_centre;
  return e;
}
void add_corners(Witness_expansion& e, const Site& s, const Box_frame& frame);

// What the tests compute of a candidate i on a box once for all its witnesses, when first needed.
struct Candidate_on_box {
  double rho = -1;                       // distance_to_box(i, frame) once computed, for (B)
  bool has_corner_squares = false;
  std::array<std::array<double, 3>, 2> corner_square{};  // (y_a - x_ia)^2 for the lower and upper bound of axis a, for (A)

  // For another candidate on the same box.
  void reset() { rho = -1, has_corner_squares = false; }
};

// The computed distance from x_s to the box of `frame` (rho_s, box units), or -1 out of range.
double distance_to_box(const Site& s, const Box_frame& frame);

// Test (A). The margins cover the rounding errors of the corner values (docs/ERROR_BOUNDS.md "Centre
// expansion", item 3). Precondition: at_j.has_corners if j.w <= i.w.
inline bool corners_dominate(const Site& j, const Witness_expansion& at_j, const Site& i, const Centre_expansion& at_i,
                             Candidate_on_box& on_box, const Box_frame& frame, double slack) {
  if (!at_i.usable || !at_j.usable) return false;
  const double w = (j.w - i.w) * frame.unit;  // W, of the sign of j.w - i.w
  if (!on_box.has_corner_squares) {
    for (int a = 0; a < 3; ++a)
      for (int side = 0; side < 2; ++side) {
        const double e = frame.corner_offset[side][a] + at_i.offset[a];
        on_box.corner_square[side][a] = e * e;
      }
    on_box.has_corner_squares = true;
  }
  const auto& square_i = on_box.corner_square;
  const double outer_i = at_i.magnitude + frame.reach;
  if (j.w <= i.w) {
    const double outer_j = at_j.farthest_corner - w;
    const double margin = slack * 32 * kUnitRoundoff * (outer_i * outer_i + outer_j * outer_j);
    for (int q = 0; q < 8; ++q) {
      const double t = at_j.corner_distance[q] - w;
      const double value = square_i[q & 1][0] + square_i[q >> 1 & 1][1] + square_i[q >> 2 & 1][2] - t * t;
      if (!(value > margin)) return false;  // a NaN certifies nothing either
    }
    return true;
  }
  double term[2][3];  // the part of axis a: (y_a - x_ia)^2 - (y_a - x_ja)^2 + 2W u_ja (y_a - c_a)
  for (int a = 0; a < 3; ++a)
    for (int side = 0; side < 2; ++side) {
      const double e = frame.corner_offset[side][a] + at_j.offset[a];
      term[side][a] = square_i[side][a] - e * e + 2 * w * (at_j.gradient[a] * frame.corner_offset[side][a]);
    }
  const double constant = 2 * w * at_j.distance - w * w;
  const double outer_j = at_j.magnitude + frame.reach;
  const double margin =
      slack * 48 * kUnitRoundoff * (outer_i * outer_i + outer_j * outer_j + 2 * w * (outer_j + frame.reach) + w * w);
  for (int q = 0; q < 8; ++q) {
    const double value = term[q & 1][0] + term[q >> 1 & 1][1] + term[q >> 2 & 1][2] + constant;
    if (!(value > margin)) return false;
  }
  return true;
}

// d_i(c) - d_j(c) from x_j - x_i as in (B), in pair units: the witnesses' order at the centre when the plain
// difference of the two values is within its rounding error. Not certified: it only chooses witnesses.
double centre_difference(const Site& i, const Centre_expansion& at_i, const Site& j, const Centre_expansion& at_j);

// Whether s is nearer than t at the centre, for choosing witnesses (a wrong choice costs boxes, never a
// vertex). 8u (magnitude_s + magnitude_t) bounds the error of the plain difference (docs/ERROR_BOUNDS.md).
inline bool nearer_at_centre(const Site& s, const Centre_expansion& at_s, const Site& t, const Centre_expansion& at_t) {
  const double difference = at_s.weighted - at_t.weighted;
  if (std::fabs(difference) > at_s.weighted_error + at_t.weighted_error) return difference < 0;
  return centre_difference(s, at_s, t, at_t) < 0;
}

// Test (B); rho_i is distance_to_box(i, frame).
bool far_dominates(const Site& j, const Witness_expansion& at_j, const Site& i, const Centre_expansion& at_i,
                   double rho_i, const Box_frame& frame, double slack);

// What the centre expansions alone decide about whether j dominates i on the box.
enum class Centre_outcome { dominated, kept, undecided };

// The tests that need no corner: i certainly closer at the centre (kept), the Lipschitz test (dominated),
// and the first-order bound f(c) - sum_a |g_a| h_a, g = u_i - u_j. When that bound certainly falls below 0,
// (B) cannot hold (docs/ERROR_BOUNDS.md, "Centre expansion", item 5) and i is kept without trying (A) either:
// there (A) rarely removes and mostly fails, so it is skipped for speed (docs/benchmarks.md). Keeping a
// candidate is always safe.
inline Centre_outcome centre_tests(const Centre_expansion& at_j, const Centre_expansion& at_i, const Box_frame& frame,
                                   double slack) {
  if (!at_i.weighted_known || !at_j.weighted_known) return Centre_outcome::kept;
  const double gap = at_i.weighted - at_j.weighted;
  // The two values' errors bound that of gap (docs/ERROR_BOUNDS.md items 2 and 8): below it, i is certainly
  // closer at the centre, so not dominated.
  const double gap_error = slack * (at_i.weighted_error + at_j.weighted_error);
  if (!(gap > -gap_error)) return Centre_outcome::kept;
  // d_i - d_j is 2-Lipschitz and reach >= |x - c| on the box: f(c) > 2 reach decides without the corners
  // (docs/ERROR_BOUNDS.md, "Centre expansion", item 7).
  if (gap - 2 * frame.reach > 1.125 * gap_error) return Centre_outcome::dominated;
  if (!at_i.usable || !at_j.usable) return Centre_outcome::kept;  // the rest needs the whole expansion
  double linear = 0;
  for (int a = 0; a < 3; ++a) linear += std::fabs(at_i.gradient[a] - at_j.gradient[a]) * frame.half_extent[a];
  if (!(gap - linear > -slack * 16 * kUnitRoundoff * (at_i.magnitude + at_j.magnitude + 2 * frame.reach + linear)))
    return Centre_outcome::kept;
  return Centre_outcome::undecided;
}

// Tests (A) and (B), after centre_tests left the pair undecided. Precondition: at_j.has_corners if
// j.w <= i.w. `on_box` is i's, shared by all its witnesses on this box.
inline bool corners_or_far_dominate(const Site& j, const Witness_expansion& at_j, const Site& i,
                                    const Centre_expansion& at_i, Candidate_on_box& on_box, const Box_frame& frame,
                                    double slack) {
  if (!at_j.usable) return false;  // add_corners found a corner out of range
  if (at_i.weighted > at_j.weighted && corners_dominate(j, at_j, i, at_i, on_box, frame, slack)) return true;
  if (on_box.rho < 0) on_box.rho = distance_to_box(i, frame);
  return far_dominates(j, at_j, i, at_i, on_box.rho, frame, slack);
}

// True only if j is certainly strictly closer than i at every point of the box of `frame`. Precondition:
// at_j.has_corners if j.w <= i.w.
inline bool expansion_dominates(const Site& j, const Witness_expansion& at_j, const Site& i,
                                const Centre_expansion& at_i, Candidate_on_box& on_box, const Box_frame& frame,
                                double slack) {
  const Centre_outcome outcome = centre_tests(at_j, at_i, frame, slack);
  if (outcome != Centre_outcome::undecided) return outcome == Centre_outcome::dominated;
  return corners_or_far_dominate(j, at_j, i, at_i, on_box, frame, slack);
}

}  // namespace apollonius
