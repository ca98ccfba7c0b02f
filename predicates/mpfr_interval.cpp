#include "predicates/mpfr_interval.h"

namespace apollonius {

Mpfr_interval::Mpfr_interval(Uninitialized) { mpfr_inits2(kBits, lo_, hi_, static_cast<mpfr_ptr>(nullptr)); }

Mpfr_interval::Mpfr_interval(double x) : Mpfr_interval(Uninitialized{}) {
  mpfr_set_d(lo_, x, MPFR_RNDN);  // exact: 53 <= kBits
  mpfr_set_d(hi_, x, MPFR_RNDN);
}

Mpfr_interval::Mpfr_interval(const Mpfr_interval& other) : Mpfr_interval(Uninitialized{}) {
  mpfr_set(lo_, other.lo_, MPFR_RNDN);
  mpfr_set(hi_, other.hi_, MPFR_RNDN);
}

Mpfr_interval::Mpfr_interval(Mpfr_interval&& other) noexcept : Mpfr_interval(Uninitialized{}) {
  mpfr_swap(lo_, other.lo_);
  mpfr_swap(hi_, other.hi_);
}

Mpfr_interval& Mpfr_interval::operator=(const Mpfr_interval& other) {
  mpfr_set(lo_, other.lo_, MPFR_RNDN);
  mpfr_set(hi_, other.hi_, MPFR_RNDN);
  return *this;
}

Mpfr_interval& Mpfr_interval::operator=(Mpfr_interval&& other) noexcept {
  mpfr_swap(lo_, other.lo_);
  mpfr_swap(hi_, other.hi_);
  return *this;
}

Mpfr_interval::~Mpfr_interval() { mpfr_clears(lo_, hi_, static_cast<mpfr_ptr>(nullptr)); }

Mpfr_interval operator+(const Mpfr_interval& x, const Mpfr_interval& y) {
  Mpfr_interval r(Mpfr_interval::Uninitialized{});
  mpfr_add(r.lo_, x.lo_, y.lo_, MPFR_RNDD);
  mpfr_add(r.hi_, x.hi_, y.hi_, MPFR_RNDU);
  return r;
}

Mpfr_interval operator-(const Mpfr_interval& x, const Mpfr_interval& y) {
  Mpfr_interval r(Mpfr_interval::Uninitialized{});
  mpfr_sub(r.lo_, x.lo_, y.hi_, MPFR_RNDD);
  mpfr_sub(r.hi_, x.hi_, y.lo_, MPFR_RNDU);
  return r;
}

Mpfr_interval operator-(const Mpfr_interval& x) {
  Mpfr_interval r(Mpfr_interval::Uninitialized{});
  mpfr_neg(r.lo_, x.hi_, MPFR_RNDN);  // exact
  mpfr_neg(r.hi_, x.lo_, MPFR_RNDN);
  return r;
}

namespace {

// The least and the greatest of op(a, b) over the four pairs of bounds, rounded down and up: the hull of
// op over two intervals, for op monotone in each argument on each (for * and / by an interval without 0).
template <class Operation>
void hull(mpfr_ptr lo, mpfr_ptr hi, mpfr_srcptr a_lo, mpfr_srcptr a_hi, mpfr_srcptr b_lo, mpfr_srcptr b_hi,
          Operation op) {
  mpfr_t down, up;
  mpfr_inits2(Mpfr_interval::kBits, down, up, static_cast<mpfr_ptr>(nullptr));
  bool first = true;
  for (mpfr_srcptr a : {a_lo, a_hi})
    for (mpfr_srcptr b : {b_lo, b_hi}) {
      op(down, a, b, MPFR_RNDD);
      op(up, a, b, MPFR_RNDU);
      if (first || mpfr_less_p(down, lo)) mpfr_set(lo, down, MPFR_RNDN);
      if (first || mpfr_greater_p(up, hi)) mpfr_set(hi, up, MPFR_RNDN);
      first = false;
    }
  mpfr_clears(down, up, static_cast<mpfr_ptr>(nullptr));
}

}  // namespace

Mpfr_interval operator*(const Mpfr_interval& x, const Mpfr_interval& y) {
  Mpfr_interval r(Mpfr_interval::Uninitialized{});
  hull(r.lo_, r.hi_, x.lo_, x.hi_, y.lo_, y.hi_, mpfr_mul);
  return r;
}

Mpfr_interval operator/(const Mpfr_interval& x, const Mpfr_interval& y) {
  if (mpfr_sgn(y.lo_) <= 0 && mpfr_sgn(y.hi_) >= 0) throw Uncertain_sign();
  Mpfr_interval r(Mpfr_interval::Uninitialized{});
  hull(r.lo_, r.hi_, x.lo_, x.hi_, y.lo_, y.hi_, mpfr_div);
  return r;
}

Mpfr_interval sqrt(const Mpfr_interval& x) {
  Mpfr_interval r(Mpfr_interval::Uninitialized{});
  if (mpfr_sgn(x.lo_) > 0) mpfr_sqrt(r.lo_, x.lo_, MPFR_RNDD);
  else mpfr_set_zero(r.lo_, 1);
  if (mpfr_sgn(x.hi_) > 0) mpfr_sqrt(r.hi_, x.hi_, MPFR_RNDU);
  else mpfr_set_zero(r.hi_, 1);
  return r;
}

std::optional<Sign> sign_if_certain(const Mpfr_interval& x) {
  if (mpfr_sgn(x.lo_) > 0) return Sign::POSITIVE;
  if (mpfr_sgn(x.hi_) < 0) return Sign::NEGATIVE;
  if (mpfr_zero_p(x.lo_) && mpfr_zero_p(x.hi_)) return Sign::ZERO;
  return std::nullopt;
}

Sign certain_sign(const Mpfr_interval& x) {
  if (const std::optional<Sign> s = sign_if_certain(x)) return *s;
  throw Uncertain_sign();
}

Interval Mpfr_interval::to_interval() const { return Interval(mpfr_get_d(lo_, MPFR_RNDD), mpfr_get_d(hi_, MPFR_RNDU)); }

}  // namespace apollonius
