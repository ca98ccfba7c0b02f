// The two number types of the staged evaluation, and the sign function each stage uses (plus plain doubles,
// for the floating path).
//  - Interval: CGAL::Interval_nt<false>, valid only inside a Rounding_guard. Its sign is certain or throws.
//  - Exact: CGAL::Gmpzf, a GMP mantissa times 2^exponent. Every double is one exactly, and +, -, * are
//    exact, so the vertex predicates are written division-free.
//  - Rational: CGAL::Gmpq, for the exact stage of the few predicates that divide (rational.h).
#pragma once

#include <CGAL/Gmpq.h>
#include <CGAL/Gmpzf.h>
#include <CGAL/Interval_nt.h>

#include "predicates/sign.h"

namespace apollonius {

using Interval = CGAL::Interval_nt<false>;
using Exact = CGAL::Gmpzf;
using Rational = CGAL::Gmpq;

inline Sign certain_sign(const Interval& x) {
  if (x.inf() > 0) return Sign::POSITIVE;
  if (x.sup() < 0) return Sign::NEGATIVE;
  if (x.inf() == 0 && x.sup() == 0) return Sign::ZERO;
  throw Uncertain_sign();
}

inline Sign certain_sign(const Exact& x) { return static_cast<Sign>(static_cast<int>(x.sign())); }
inline Sign certain_sign(const Rational& x) { return static_cast<Sign>(CGAL::sign(x)); }

// The floating path (`--arith float`, no filter and no exact stage): the computed sign, taken as it is.
inline Sign certain_sign(double x) { return x > 0 ? Sign::POSITIVE : x < 0 ? Sign::NEGATIVE : Sign::ZERO; }

// An interval that contains x, valid in any rounding mode and beyond the double range (then one bound is
// infinite or zero). CGAL's own to_interval(Gmpzf) is not used: it maps values above the double range to
// [inf, inf] and truncates exponents to int, so its lower bound can exceed the value.
Interval enclosing_interval(const Exact& x);

}  // namespace apollonius
