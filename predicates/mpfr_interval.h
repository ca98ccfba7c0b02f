// Mpfr_interval: an interval whose bounds are MPFR numbers of 256 bits, rounded outward by MPFR's own
// directed modes (the FPU's mode does not matter: no Rounding_guard). The filter stage after intervals and
// wide intervals for trisectors whose signs lie a hair from zero: sites one ulp off a lattice, whose exact
// stage on Gmpq cost about half a millisecond a trisector. 256 bits decide values down to about 2^-200 of
// their terms; MPFR's exponent range (2^+-(2^62)) never overflows. A value computed exactly all the way (an
// exact zero of degree-2 terms) is [0, 0], and only then is ZERO certain; other uncertain signs throw
// Uncertain_sign, as Interval's do.
#pragma once

#include <mpfr.h>

#include <optional>

#include "predicates/number_types.h"

namespace apollonius {

// Invariant: lo <= hi, both numbers (never NaN); the real number it stands for lies in [lo, hi].
class Mpfr_interval {
 public:
  static constexpr mpfr_prec_t kBits = 256;

  Mpfr_interval() : Mpfr_interval(0.0) {}
  Mpfr_interval(int x) : Mpfr_interval(static_cast<double>(x)) {}  // NOLINT: as Interval converts
  Mpfr_interval(double x);                                         // NOLINT; exact; x finite
  Mpfr_interval(const Mpfr_interval& other);
  Mpfr_interval(Mpfr_interval&& other) noexcept;  // leaves other NaN, to be assigned or destroyed only
  Mpfr_interval& operator=(const Mpfr_interval& other);
  Mpfr_interval& operator=(Mpfr_interval&& other) noexcept;  // a swap
  ~Mpfr_interval();

  friend Mpfr_interval operator+(const Mpfr_interval& x, const Mpfr_interval& y);
  friend Mpfr_interval operator-(const Mpfr_interval& x, const Mpfr_interval& y);
  friend Mpfr_interval operator-(const Mpfr_interval& x);
  friend Mpfr_interval operator*(const Mpfr_interval& x, const Mpfr_interval& y);
  // Throws Uncertain_sign when y may be 0.
  friend Mpfr_interval operator/(const Mpfr_interval& x, const Mpfr_interval& y);
  // The square root of the non-negative part (CGAL's convention for Interval).
  friend Mpfr_interval sqrt(const Mpfr_interval& x);

  friend std::optional<Sign> sign_if_certain(const Mpfr_interval& x);
  friend Sign certain_sign(const Mpfr_interval& x);

  // The bounds rounded outward to doubles (infinite beyond the double range).
  Interval to_interval() const;
  mpfr_srcptr lower() const { return lo_; }
  mpfr_srcptr upper() const { return hi_; }

 private:
  struct Uninitialized {};
  explicit Mpfr_interval(Uninitialized);

  mpfr_t lo_, hi_;
};

}  // namespace apollonius
