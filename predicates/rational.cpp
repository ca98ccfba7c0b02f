#include "predicates/rational.h"

#include <gmp.h>

namespace apollonius {

Rational to_rational(const Exact& x) {
  Rational r(CGAL::Gmpz(x.man()));
  const long exponent = x.exp();
  if (exponent > 0) mpq_mul_2exp(r.mpq(), r.mpq(), static_cast<mp_bitcnt_t>(exponent));
  if (exponent < 0) mpq_div_2exp(r.mpq(), r.mpq(), static_cast<mp_bitcnt_t>(-exponent));
  return r;
}

}  // namespace apollonius
