#include "predicates/correct_rounding.h"

#include <mpfr.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace apollonius {
namespace {

constexpr mpfr_prec_t kPrecision = 256;

class Mpfr {
 public:
  Mpfr() { mpfr_init2(value_, kPrecision); }
  explicit Mpfr(const Exact& x) : Mpfr() { mpfr_set_q(value_, static_cast<Rational>(x).mpq(), MPFR_RNDN); }
  ~Mpfr() { mpfr_clear(value_); }
  Mpfr(const Mpfr&) = delete;
  Mpfr& operator=(const Mpfr&) = delete;
  mpfr_ptr get() { return value_; }

 private:
  mpfr_t value_;
};

bool is_even(double g) {
  std::uint64_t bits;
  static_assert(sizeof bits == sizeof g);
  std::memcpy(&bits, &g, sizeof g);
  return (bits & 1u) == 0;
}

// The exact midpoint between g and its neighbour towards `direction` (+-infinity).
Exact midpoint_towards(double g, double direction) {
  const double neighbour = std::nextafter(g, direction);
  if (std::isinf(neighbour)) {
    const double inner = std::nextafter(g, -direction);
    return Exact(g) + (Exact(g) - Exact(inner)) * Exact(0.5);
  }
  return (Exact(g) + Exact(neighbour)) * Exact(0.5);
}

Sign compare_with(const Root_number<Exact>& x, const Exact& m) {
  return compare(x, Root_number<Exact>{m, Exact(0), Exact(0), Exact(1)});
}

// x in `result`, rounded to 256 bits, with at most 128 of them lost to cancellation (then within 2^-120 of
// x): the direct sum, unless a and b sqrt(d) cancel further, and then (a^2 - b^2 d) / (a - b sqrt d), whose
// exact numerator costs three products of the longest numbers.
void approximate_into(const Root_number<Exact>& x, Mpfr& result) {
  Mpfr a(x.a), b(x.b), d(x.d), den(x.denominator);
  const Sign sa = certain_sign(x.a), sb = certain_sign(x.b);
  mpfr_sqrt(d.get(), d.get(), MPFR_RNDN);
  mpfr_fma(result.get(), b.get(), d.get(), a.get(), MPFR_RNDN);  // a + b sqrt d
  if (sb != Sign::ZERO && sa != Sign::ZERO && sa != sb && certain_sign(x.d) != Sign::ZERO) {
    Mpfr term;
    mpfr_mul(term.get(), b.get(), d.get(), MPFR_RNDN);
    const mpfr_exp_t largest = std::max(mpfr_get_exp(a.get()), mpfr_get_exp(term.get()));
    if (mpfr_zero_p(result.get()) || mpfr_get_exp(result.get()) < largest - 128) {
      // a and -b sqrt d have the same sign: the conjugate adds without cancellation.
      Mpfr numerator(x.a * x.a - x.b * x.b * x.d);
      mpfr_sub(term.get(), a.get(), term.get(), MPFR_RNDN);
      mpfr_div(result.get(), numerator.get(), term.get(), MPFR_RNDN);
    }
  }
  mpfr_div(result.get(), result.get(), den.get(), MPFR_RNDN);
}

}  // namespace

double approximate(const Root_number<Exact>& x) {
  Mpfr result;
  approximate_into(x, result);
  return mpfr_get_d(result.get(), MPFR_RNDN);
}

std::optional<long> binary_exponent(const Root_number<Exact>& x) {
  Mpfr result;
  approximate_into(x, result);
  if (mpfr_zero_p(result.get())) return std::nullopt;
  return static_cast<long>(mpfr_get_exp(result.get()));
}

double to_nearest_double(const Root_number<Exact>& x) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  double g = approximate(x);
  if (std::isinf(g)) g = std::copysign(std::numeric_limits<double>::max(), g);
  for (;;) {
    const Sign below = compare_with(x, midpoint_towards(g, -inf));
    if (below == Sign::NEGATIVE || (below == Sign::ZERO && !is_even(g))) {
      if (g == -std::numeric_limits<double>::max()) return -inf;
      g = std::nextafter(g, -inf);
      continue;
    }
    const Sign above = compare_with(x, midpoint_towards(g, inf));
    if (above == Sign::POSITIVE || (above == Sign::ZERO && !is_even(g))) {
      if (g == std::numeric_limits<double>::max()) return inf;
      g = std::nextafter(g, inf);
      continue;
    }
    return g == 0 ? 0.0 : g;
  }
}

}  // namespace apollonius
