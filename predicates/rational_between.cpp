#include "predicates/rational_between.h"

#include <gmp.h>

#include <stdexcept>
#include <utility>

namespace apollonius {
namespace {

// Rational bounds of sqrt(d) within 2^-bits relative: floor and ceil of sqrt(p q 4^bits) / (q 2^bits),
// d = p / q in lowest terms.
std::pair<Rational, Rational> sqrt_bounds(const Rational& d, unsigned long bits) {
  mpz_t scaled, root;
  mpz_inits(scaled, root, nullptr);
  mpz_mul(scaled, mpq_numref(d.mpq()), mpq_denref(d.mpq()));
  mpz_mul_2exp(scaled, scaled, 2 * bits);
  mpz_sqrt(root, scaled);
  const bool exact = mpz_perfect_square_p(scaled) != 0;
  Rational low{CGAL::Gmpz(root)}, high{CGAL::Gmpz(root)};
  if (!exact) high += 1;
  mpz_mul_2exp(scaled, mpq_denref(d.mpq()), bits);  // q 2^bits
  const Rational divisor{CGAL::Gmpz(scaled)};
  mpz_clears(scaled, root, nullptr);
  return {low / divisor, high / divisor};
}

}  // namespace

std::pair<Rational, Rational> rational_bounds(const Root_number<Rational>& x, unsigned long bits) {
  if (certain_sign(x.b) == Sign::ZERO || certain_sign(x.d) == Sign::ZERO) {
    const Rational v = x.a / x.denominator;
    return {v, v};
  }
  const auto [low, high] = sqrt_bounds(x.d, bits);
  Rational one = (x.a + x.b * low) / x.denominator, other = (x.a + x.b * high) / x.denominator;
  if (other < one) std::swap(one, other);
  return {one, other};
}

Rational rational_between(const Root_number<Rational>& x, const Root_number<Rational>& y) {
  if (compare(x, y) != Sign::NEGATIVE) throw std::logic_error("rational_between: the numbers are not in order");
  for (unsigned long bits = 32;; bits *= 2) {
    const Rational below = rational_bounds(x, bits).second, above = rational_bounds(y, bits).first;
    if (below < above) return (below + above) / 2;
  }
}

}  // namespace apollonius
