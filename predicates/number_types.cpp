#include "predicates/number_types.h"

#include <CGAL/FPU.h>

#include <cmath>
#include <limits>

namespace apollonius {

Exact exact_integer(const CGAL::Gmpz& z) {
  if (z == 0) return Exact(0);
  const Exact magnitude(CGAL::abs(z));
  return z < 0 ? -magnitude : magnitude;
}

// Where both bounds of x's enclosure are normal doubles of one binade, x lies in it too; else (beyond the
// double range, subnormal, or an enclosure across a power of two) the exponent comes from the exact rational.
long binary_exponent(const Exact& x) {
  const Interval enclosure = enclosing_interval(x);
  const double least = enclosure.inf() > 0 ? enclosure.inf() : -enclosure.sup();
  const double most = enclosure.inf() > 0 ? enclosure.sup() : -enclosure.inf();
  if (least >= std::numeric_limits<double>::min() && std::isfinite(most) && std::ilogb(least) == std::ilogb(most))
    return std::ilogb(least);
  const Rational q = static_cast<Rational>(x);  // denominator a power of two
  return static_cast<long>(mpz_sizeinbase(mpq_numref(q.mpq()), 2)) - static_cast<long>(mpz_sizeinbase(mpq_denref(q.mpq()), 2));
}

// CGAL::Mpzf::to_interval keeps the mantissa's top 53 bits exactly and the next integer up, then scales
// both by std::ldexp(1, e) in interval arithmetic. That scale must be rounded to nearest: under a
// Rounding_guard's upward rounding a scale below the subnormal range becomes denorm_min instead of 0, and
// the lower bound then exceeds the value (test_vertices_of, "beyond the double range"). The mode is switched
// and restored through CGAL's own FPU control, the one Rounding_guard uses: std::fegetround reads the x87
// control word, which CGAL's SSE2 rounding does not set, so restoring what it returned left the caller's
// intervals rounded to nearest (the brute force then reported a vertex at 9.7e90 that a site is closer to;
// test_vertices_of, "keeps the caller's rounding").
Interval enclosing_interval(const Exact& x) {
  const CGAL::Protect_FPU_rounding<true> to_nearest(CGAL_FE_TONEAREST);
  return Interval(x.to_interval());
}

}  // namespace apollonius
