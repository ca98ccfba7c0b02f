// The two number types of the staged evaluation, and the sign function each stage uses (plus plain doubles,
// for the floating path).
//  - Interval: CGAL::Interval_nt<false>, valid only inside a Rounding_guard. Its sign is certain or throws.
//  - Exact: CGAL::Mpzf, an integer of 64-bit limbs times 2^(64 exponent), with a few limbs stored inline
//    (no allocation for most predicate terms). Every double is one exactly, and +, -, * are exact, so the
//    vertex predicates are written division-free.
//  - Rational: CGAL::Gmpq, for the exact stage of the few predicates that divide (rational.h).
#pragma once

#include <CGAL/Gmpq.h>
#include <CGAL/Gmpz.h>
#include <CGAL/Mpzf.h>
#include <CGAL/Interval_nt.h>

#include <cmath>
#include <optional>

#include "predicates/sign.h"

namespace apollonius {

using Interval = CGAL::Interval_nt<false>;
using Exact = CGAL::Mpzf;
using Rational = CGAL::Gmpq;

// The sign of every number of x, or nothing: for stages where uncertainty is common (filtered_predicate.h).
inline std::optional<Sign> sign_if_certain(const Interval& x) {
  if (x.inf() > 0) return Sign::POSITIVE;
  if (x.sup() < 0) return Sign::NEGATIVE;
  if (x.inf() == 0 && x.sup() == 0) return Sign::ZERO;
  return std::nullopt;
}

inline Sign certain_sign(const Interval& x) {
  if (const std::optional<Sign> s = sign_if_certain(x)) return *s;
  throw Uncertain_sign();
}

// Whether x is certainly not 0 (Pivot_exact_where_uncertain's test, as for the other filter types).
inline bool certainly_nonzero(const Interval& x) { return x.inf() > 0 || x.sup() < 0; }

inline Sign certain_sign(const Exact& x) { return static_cast<Sign>(static_cast<int>(x.sign())); }
inline Sign certain_sign(const Rational& x) { return static_cast<Sign>(CGAL::sign(x)); }

// The floating path (`--arith float`, no filter and no exact stage): the computed sign, taken as it is.
inline Sign certain_sign(double x) { return x > 0 ? Sign::POSITIVE : x < 0 ? Sign::NEGATIVE : Sign::ZERO; }

// Exact and floating signs are always certain: so that one template serves every stage.
inline std::optional<Sign> sign_if_certain(const Exact& x) { return certain_sign(x); }
inline std::optional<Sign> sign_if_certain(double x) { return certain_sign(x); }

// The integer z as an Exact. CGAL 5.5's Mpzf(const Gmpz&) drops the sign (it sizes the number by
// mpz_size, the magnitude's) and mishandles 0 (mpz_scan1 finds no bit): use this instead.
Exact exact_integer(const CGAL::Gmpz& z);

// x 2^k for any k, one normal power of two at a time: exact for Exact (no exponent range), certified for
// Interval inside a Rounding_guard (an overflow goes to infinity, an underflow outward).
template <class NT>
NT times_power_of_two(NT x, int k) {
  while (k != 0) {
    const int step = k < -1000 ? -1000 : k > 1000 ? 1000 : k;
    x = x * NT(std::ldexp(1.0, step));
    k -= step;
  }
  return x;
}

// floor(log2 |x|) for x != 0, at any magnitude.
long binary_exponent(const Exact& x);

// An interval that contains x, valid in any rounding mode and beyond the double range (then one bound is
// infinite or zero; tests/data/regression/gmpzf_to_interval_beyond_double_range).
Interval enclosing_interval(const Exact& x);

}  // namespace apollonius
