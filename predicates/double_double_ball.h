// Double-double numbers that carry a certified bound on their distance to the real number they stand
// for: a cheap, rigorous way to locate a vertex to about 100 bits, enough to round it correctly almost
// always (correct_rounding.h). Plain round-to-nearest doubles, no rounding-mode change; every bound is
// derived in docs/ERROR_BOUNDS.md ("Double-double balls").
#pragma once

#include <cmath>
#include <optional>

#include "predicates/sign.h"
#include "predicates/unit_roundoff.h"

namespace apollonius {

// Invariant: the real number x it stands for satisfies |x - (hi + lo)| <= error, and |lo| <= ulp(hi) / 2.
struct Double_double_ball {
  double hi = 0, lo = 0, error = 0;

  Double_double_ball() = default;
  explicit Double_double_ball(double x) : hi(x) {}
  Double_double_ball(double h, double l, double e) : hi(h), lo(l), error(e) {}

  double magnitude() const { return std::fabs(hi) + std::fabs(lo); }  // >= |hi + lo|
  // Finite, and error at most a small fraction of the scale where the bounds hold.
  bool usable() const { return std::isfinite(hi) && std::isfinite(lo) && std::isfinite(error); }
};

// The building blocks of the operations below.
namespace double_double {

constexpr double kUnitSquared = kUnitRoundoff * kUnitRoundoff;
// Added to every bound: covers any part of a result that underflowed (below 2^-1022), yet the product of
// two of them is still normal (subnormal operands are very slow).
constexpr double kUnderflow = 0x1p-511;

// Error-free transformations (Knuth, Dekker): s + e == a + b and p + e == a * b exactly.
inline void two_sum(double a, double b, double& s, double& e) {
  s = a + b;
  const double bb = s - a;
  e = (a - (s - bb)) + (b - bb);
}
inline void fast_two_sum(double a, double b, double& s, double& e) {  // |a| >= |b| or a == 0
  s = a + b;
  e = b - (s - a);
}
inline void split(double a, double& high, double& low) {
  const double c = 134217729.0 * a;  // 2^27 + 1
  high = c - (c - a);
  low = a - high;
}
inline void two_product(double a, double b, double& p, double& e) {
  p = a * b;
  double ah, al, bh, bl;
  split(a, ah, al);
  split(b, bh, bl);
  e = ((ah * bh - p) + ah * bl + al * bh) + al * bl;
}

// The computed bound e, enlarged to cover its own rounding (a sum or product of a few non-negative terms).
inline double rounded_up(double e) { return e * (1 + 8 * kUnitRoundoff); }

}  // namespace double_double

// Joldes, Muller, Popescu (2017), Algorithm 6 (AccurateDWPlusDW): relative error at most 3u^2 / (1 - 4u).
inline Double_double_ball operator+(const Double_double_ball& a, const Double_double_ball& b) {
  double sh, sl, th, tl, vh, vl, zh, zl;
  using namespace double_double;
  two_sum(a.hi, b.hi, sh, sl);
  two_sum(a.lo, b.lo, th, tl);
  fast_two_sum(sh, sl + th, vh, vl);
  fast_two_sum(vh, tl + vl, zh, zl);
  const double error = a.error + b.error + 4 * kUnitSquared * (std::fabs(zh) + std::fabs(zl)) + kUnderflow;
  return {zh, zl, rounded_up(error)};
}

inline Double_double_ball operator-(const Double_double_ball& a) { return {-a.hi, -a.lo, a.error}; }
inline Double_double_ball operator-(const Double_double_ball& a, const Double_double_ball& b) { return a + (-b); }

// The exact product of the high parts, the two cross terms rounded, the product of the low parts
// dropped: relative error at most 8u^2 (docs/ERROR_BOUNDS.md), taken as 10u^2 of the result.
inline Double_double_ball operator*(const Double_double_ball& a, const Double_double_ball& b) {
  double ph, pl, zh, zl;
  using namespace double_double;
  two_product(a.hi, b.hi, ph, pl);
  fast_two_sum(ph, pl + (a.hi * b.lo + a.lo * b.hi), zh, zl);
  const double error = a.magnitude() * b.error + b.magnitude() * a.error + a.error * b.error +
                       10 * kUnitSquared * (std::fabs(zh) + std::fabs(zl)) + kUnderflow;
  return {zh, zl, rounded_up(error)};
}

// a / b and sqrt(a), with a posteriori bounds from their residuals. An unusable ball (error infinite) when
// b may vanish or a may be negative.
Double_double_ball quotient(const Double_double_ball& a, const Double_double_ball& b);
Double_double_ball square_root(const Double_double_ball& a);

// The sign of every number of the ball, or nothing (zero is never certain): |hi + lo| >= |hi| - |lo| > error.
inline std::optional<Sign> sign_if_certain(const Double_double_ball& x) {
  if (!x.usable()) return std::nullopt;
  const double least = (std::fabs(x.hi) - std::fabs(x.lo)) * (1 - 0x1p-50);
  if (!(least > x.error)) return std::nullopt;
  return x.hi > 0 ? Sign::POSITIVE : Sign::NEGATIVE;
}

inline bool certainly_nonzero(const Double_double_ball& x) { return sign_if_certain(x).has_value(); }

// The same, or Uncertain_sign.
inline Sign certain_sign(const Double_double_ball& x) {
  if (const std::optional<Sign> s = sign_if_certain(x)) return *s;
  throw Uncertain_sign();
}

}  // namespace apollonius
