// A double with the magnitude of its computation, for a priori error analysis (Higham, Accuracy and
// Stability of Numerical Algorithms, 3.1-3.3): the magnitude is the same computation on absolute values,
// and |computed - exact| <= gamma_{3 k} magnitude for a computation of depth k. The polynomial part of
// vertices_of's first stage (quadruple_line.h) runs in it, cheaper than Double_with_error's running bound
// (no bound per operation), then hands Double_with_error its values and bounds for the divisions and
// square roots. Only +, - and *. The bound and the depth are derived in docs/ERROR_BOUNDS.md ("Doubles with
// magnitude").
#pragma once

#include <algorithm>
#include <cmath>

#include "predicates/double_with_error.h"

namespace apollonius {

// The depth of quadruple_line's deepest value (the discriminant), computed once, at start-up, by running
// quadruple_line on Depth_count (below): not counted by hand, and not tracked per value on the hot path.
extern const int kQuadrupleLineDepth;

// Invariant: |x - value| <= gamma_{3 kQuadrupleLineDepth} magnitude for the real x it stands for, and
// magnitude >= |x|, for every value of quadruple_line.
struct Double_with_magnitude {
  double value = 0, magnitude = 0;

  Double_with_magnitude() = default;
  explicit Double_with_magnitude(double v) : value(v), magnitude(std::fabs(v)) {}
  Double_with_magnitude(double v, double m) : value(v), magnitude(m) {}

  // x - y for doubles x, y: one rounding of the difference itself, |fl(x - y) - (x - y)| <= u |x - y|, so
  // its magnitude is |fl(x - y)| (1 + 4u) >= |x - y|, not |x| + |y|: the sites' coordinates may be far
  // larger than their differences.
  static Double_with_magnitude difference(double x, double y) {
    const double z = x - y;
    return {z, std::fabs(z) * (1 + 4 * kUnitRoundoff)};
  }

  // Added to the magnitude of every product: u kUnderflow exceeds the error 2^-1075 of a product that
  // underflowed, and keeps every magnitude normal.
  static constexpr double kUnderflow = 0x1p-1000;

  // gamma_{3 k} magnitude, rounded up: (3 k + 1) u magnitude (1 + 2^-40) covers gamma's denominator and the
  // roundings of its own computation.
  double error_bound() const {
    return (3.0 * kQuadrupleLineDepth + 1) * kUnitRoundoff * (1 + 0x1p-40) * magnitude;
  }
};

inline Double_with_magnitude operator+(const Double_with_magnitude& a, const Double_with_magnitude& b) {
  return {a.value + b.value, a.magnitude + b.magnitude};
}
inline Double_with_magnitude operator-(const Double_with_magnitude& a) { return {-a.value, a.magnitude}; }
inline Double_with_magnitude operator-(const Double_with_magnitude& a, const Double_with_magnitude& b) {
  return {a.value - b.value, a.magnitude + b.magnitude};
}
inline Double_with_magnitude operator*(const Double_with_magnitude& a, const Double_with_magnitude& b) {
  return {a.value * b.value, a.magnitude * b.magnitude + Double_with_magnitude::kUnderflow};
}

// Whether every number within the bound is nonzero (no exception: for the pivot rule of exact_quadruple_line.h).
inline bool certainly_nonzero(const Double_with_magnitude& x) { return std::fabs(x.value) > x.error_bound(); }

// The sign of every number within the bound, or Uncertain_sign (never ZERO; NaN and infinity included).
inline Sign certain_sign(const Double_with_magnitude& x) {
  if (!certainly_nonzero(x)) throw Uncertain_sign();
  return x.value > 0 ? Sign::POSITIVE : Sign::NEGATIVE;
}

// The same number with a running bound, for the operations that follow.
inline Double_with_error with_error(const Double_with_magnitude& x) { return {x.value, x.error_bound()}; }

// The depth of a computation without its values (docs/ERROR_BOUNDS.md): 0 for an input double, 1 for a
// difference of two, max + 1 for a sum, sum + 1 for a product. Its signs are never 0, so that
// quadruple_line takes its full path.
struct Depth_count {
  int depth = 0;
  Depth_count() = default;
  explicit Depth_count(double) {}
  explicit Depth_count(int d, int) : depth(d) {}
  static Depth_count difference(double, double) { return Depth_count(1, 0); }
};
inline Depth_count operator+(Depth_count a, Depth_count b) { return Depth_count(std::max(a.depth, b.depth) + 1, 0); }
inline Depth_count operator-(Depth_count a, Depth_count b) { return a + b; }
inline Depth_count operator-(Depth_count a) { return a; }
inline Depth_count operator*(Depth_count a, Depth_count b) { return Depth_count(a.depth + b.depth + 1, 0); }
inline Sign certain_sign(const Depth_count&) { return Sign::POSITIVE; }

}  // namespace apollonius
