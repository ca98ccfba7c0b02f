// A double with a certified bound on its distance to the real number it stands for, propagated by running
// error analysis (Higham, Accuracy and Stability of Numerical Algorithms, 3.3): the first, cheapest filter
// stage of vertices_of. Each operation is a few branch-free flops, against the sign cases of an interval
// product; no rounding-mode change. The bounds are derived in docs/ERROR_BOUNDS.md ("Doubles with error").
#pragma once

#include <cmath>
#include <limits>
#include <optional>

#include "predicates/number_types.h"
#include "predicates/unit_roundoff.h"

namespace apollonius {

// Invariant: the real number x it stands for satisfies |x - value| <= error * kChain. Each operation
// rounds its bound by at most a factor 1 + 8u below the true one; kChain = 1 + 2^-39 >= (1 + 8u)^1000
// covers chains of up to 1000 operations (vertices_of has a few hundred).
struct Double_with_error {
  double value = 0, error = 0;

  Double_with_error() = default;
  explicit Double_with_error(double v) : value(v) {}
  Double_with_error(double v, double e) : value(v), error(e) {}

  // Added to every bound: covers a result that underflowed, and keeps products of bounds normal.
  static constexpr double kUnderflow = 0x1p-511;
  static constexpr double kChain = 1 + 0x1p-39;
};

inline Double_with_error operator+(const Double_with_error& a, const Double_with_error& b) {
  const double z = a.value + b.value;
  return {z, a.error + b.error + kUnitRoundoff * std::fabs(z) + Double_with_error::kUnderflow};
}
inline Double_with_error operator-(const Double_with_error& a) { return {-a.value, a.error}; }
inline Double_with_error operator-(const Double_with_error& a, const Double_with_error& b) {
  const double z = a.value - b.value;
  return {z, a.error + b.error + kUnitRoundoff * std::fabs(z) + Double_with_error::kUnderflow};
}
inline Double_with_error operator*(const Double_with_error& a, const Double_with_error& b) {
  const double z = a.value * b.value;
  return {z, std::fabs(a.value) * b.error + std::fabs(b.value) * a.error + a.error * b.error +
                 kUnitRoundoff * std::fabs(z) + Double_with_error::kUnderflow};
}
inline Double_with_error operator/(const Double_with_error& a, const Double_with_error& b) {
  // |a/b - z| <= (|a - z b| + e_a + |z| e_b) / (|b| - e_b), |a - z b| <= u |a| for z = fl(a / b).
  const double least = std::fabs(b.value) - b.error * Double_with_error::kChain;
  if (!(least > 0)) throw Uncertain_sign();
  const double z = a.value / b.value;
  return {z, (kUnitRoundoff * std::fabs(a.value) + a.error + std::fabs(z) * b.error) / least *
                 (1 + 4 * kUnitRoundoff) + Double_with_error::kUnderflow};
}

// For a real argument known to be positive: |sqrt(a_r) - sqrt(a)| <= e_a / sqrt(a), plus the rounding.
inline Double_with_error sqrt(const Double_with_error& a) {
  if (!(a.value > 0)) throw Uncertain_sign();
  const double z = std::sqrt(a.value);
  return {z, a.error / z * (1 + 4 * kUnitRoundoff) + kUnitRoundoff * z + Double_with_error::kUnderflow};
}

// The sign of every number within the bound, or nothing (never ZERO: every operation rounds; NaN included).
inline std::optional<Sign> sign_if_certain(const Double_with_error& x) {
  if (!(std::fabs(x.value) > x.error * Double_with_error::kChain)) return std::nullopt;
  return x.value > 0 ? Sign::POSITIVE : Sign::NEGATIVE;
}

// The same, or Uncertain_sign.
inline Sign certain_sign(const Double_with_error& x) {
  if (const std::optional<Sign> s = sign_if_certain(x)) return *s;
  throw Uncertain_sign();
}

// An interval holding every number within the bound, valid in any rounding mode: the margin 2u |value|
// and the factor 1 + 4u cover the roundings of the two bounds' computation (error >= kUnderflow > 0).
inline Interval enclosing_interval(const Double_with_error& x) {
  constexpr double u = kUnitRoundoff;
  const double reach = (x.error * Double_with_error::kChain + 2 * u * std::fabs(x.value)) * (1 + 4 * u);
  return Interval(x.value - reach, x.value + reach);
}

}  // namespace apollonius
