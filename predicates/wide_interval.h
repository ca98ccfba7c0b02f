// Wide_interval: an interval times a power of two, [inf, sup] 2^exponent, for filter stages whose values
// leave the double range. Sites from 5e-324 to 1e266 give a quadruple's line polynomials (degree up to 14)
// of 2^-12000 to 2^+12000: plain intervals overflow or underflow there, and every such quadruple went to
// the exact stage with thousands of bits. Operations round outward; signs that the interval cannot decide
// throw Uncertain_sign (never ZERO for an uncertain value), as Interval's do.
// Precondition of every operation: a Rounding_guard (upward rounding, CGAL's convention).
#pragma once

#include <algorithm>
#include <cmath>

#include "predicates/number_types.h"

namespace apollonius {

class Wide_interval {
 public:
  Wide_interval() = default;
  Wide_interval(int x) : Wide_interval(static_cast<double>(x)) {}  // NOLINT: as Interval converts
  Wide_interval(double x) : mantissa_(x), exponent_(0) { normalize(); }  // NOLINT; x finite

  // mantissa 2^exponent. Throws Uncertain_sign if the mantissa is not finite.
  static Wide_interval with_exponent(const Interval& mantissa, long exponent) { return {mantissa, exponent}; }

  const Interval& mantissa() const { return mantissa_; }
  long exponent() const { return exponent_; }

  // The enclosure as a plain interval times 2^-shift: bounds that leave the double range become infinite
  // (or round outward into the subnormals).
  Interval scaled_down(long shift) const { return scaled(mantissa_, exponent_ - shift); }
  Interval to_interval() const { return scaled_down(0); }

  friend Wide_interval operator-(const Wide_interval& x) { return Wide_interval(-x.mantissa_, x.exponent_); }
  friend Wide_interval operator+(const Wide_interval& x, const Wide_interval& y) {
    if (is_zero(x.mantissa_)) return y;
    if (is_zero(y.mantissa_)) return x;
    const long e = std::max(x.exponent_, y.exponent_);
    return Wide_interval(scaled(x.mantissa_, x.exponent_ - e) + scaled(y.mantissa_, y.exponent_ - e), e);
  }
  friend Wide_interval operator-(const Wide_interval& x, const Wide_interval& y) { return x + (-y); }
  friend Wide_interval operator*(const Wide_interval& x, const Wide_interval& y) {
    return Wide_interval(x.mantissa_ * y.mantissa_, x.exponent_ + y.exponent_);
  }
  // Throws Uncertain_sign when y may be 0.
  friend Wide_interval operator/(const Wide_interval& x, const Wide_interval& y) {
    if (certain_sign(y.mantissa_) == Sign::ZERO) throw Uncertain_sign();
    return Wide_interval(x.mantissa_ / y.mantissa_, x.exponent_ - y.exponent_);
  }
  // The square root of the non-negative part (CGAL's convention for Interval).
  friend Wide_interval sqrt(const Wide_interval& x) {
    // An even exponent halves exactly; the mantissa, at most 2 after the doubling, stays normal.
    const bool odd = x.exponent_ % 2 != 0;
    const Interval m = odd ? x.mantissa_ * Interval(2) : x.mantissa_;
    const long e = odd ? x.exponent_ - 1 : x.exponent_;
    return Wide_interval(CGAL::sqrt(m), e / 2);
  }
  friend std::optional<Sign> sign_if_certain(const Wide_interval& x) { return sign_if_certain(x.mantissa_); }
  friend Sign certain_sign(const Wide_interval& x) { return certain_sign(x.mantissa_); }

 private:
  Wide_interval(const Interval& mantissa, long exponent) : mantissa_(mantissa), exponent_(exponent) { normalize(); }

  static bool is_zero(const Interval& x) { return x.inf() == 0 && x.sup() == 0; }

  // x 2^k, rounded outward by Interval's multiplication (number_types.h). Beyond 2^+-2200 a mantissa is
  // infinite or at most the smallest subnormal either way.
  static Interval scaled(const Interval& x, long k) {
    return times_power_of_two(x, static_cast<int>(std::clamp(k, -2200L, 2200L)));
  }

  // Invariant: the larger bound's magnitude lies in [1/2, 1), or the mantissa is [0, 0] with exponent 0,
  // so products and sums of two mantissas stay far from overflow and underflow.
  void normalize() {
    const double magnitude = std::max(-mantissa_.inf(), mantissa_.sup());
    if (!std::isfinite(magnitude)) throw Uncertain_sign();  // a quotient by a mantissa near 0: give up
    if (magnitude == 0) {
      exponent_ = 0;
      return;
    }
    int e;
    std::frexp(magnitude, &e);
    mantissa_ = scaled(mantissa_, -e);
    exponent_ += e;
  }

  Interval mantissa_{0};
  long exponent_ = 0;
};

}  // namespace apollonius
