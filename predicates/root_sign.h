// Exact signs of numbers with square roots, the only irrational numbers of the diagram (docs/design.md, "Algebra").
// Every vertex coordinate lies in Q(sqrt(d)) for the discriminant d of its quadruple; comparing two
// vertices therefore involves two different roots.
//
// The rules are written once for any number type NT: with Interval they are the filter (certain_sign
// throws when an interval straddles zero), with Exact they are the exact stage.
#pragma once

#include "predicates/number_types.h"

namespace apollonius {

// Precondition d >= 0. One squaring: when a and b*sqrt(d) have opposite signs,
// sign(a + b sqrt d) = sign(a) * sign(a^2 - b^2 d).
template <class NT>
Sign sign_of_root_number(const NT& a, const NT& b, const NT& d) {
  const Sign sa = certain_sign(a);
  const Sign sb = certain_sign(b);
  if (sb == Sign::ZERO) return sa;
  if (certain_sign(d) == Sign::ZERO) return sa;
  if (sa == Sign::ZERO || sa == sb) return sb;
  return sa * certain_sign(a * a - b * b * d);
}

// Precondition d1, d2 >= 0. sign(a + b1 sqrt d1 + b2 sqrt d2) with two squarings: with
// s = a + b1 sqrt d1 and t = b2 sqrt d2 of opposite signs, sign(s + t) = sign(s) * sign(s^2 - t^2), and
// s^2 - t^2 = (a^2 + b1^2 d1 - b2^2 d2) + 2 a b1 sqrt d1 is again a one-root number.
template <class NT>
Sign sign_of_two_root_sum(const NT& a, const NT& b1, const NT& d1, const NT& b2, const NT& d2) {
  const Sign ss = sign_of_root_number(a, b1, d1);
  const Sign st = certain_sign(d2) == Sign::ZERO ? Sign::ZERO : certain_sign(b2);
  if (st == Sign::ZERO) return ss;
  if (ss == Sign::ZERO || ss == st) return st;
  return ss * sign_of_root_number(a * a + b1 * b1 * d1 - b2 * b2 * d2, NT(2) * a * b1, d1);
}

// The real number (a + b sqrt(d)) / denominator, with d >= 0 and denominator > 0.
template <class NT>
struct Root_number {
  NT a, b, d, denominator;
};

// sign(x - y) for root numbers with possibly different discriminants.
template <class NT>
Sign compare(const Root_number<NT>& x, const Root_number<NT>& y) {
  return sign_of_two_root_sum(x.a * y.denominator - y.a * x.denominator, x.b * y.denominator, x.d,
                              -(y.b * x.denominator), y.d);
}

}  // namespace apollonius
