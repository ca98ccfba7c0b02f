#include "predicates/number_types.h"

#include <cmath>
#include <limits>

namespace apollonius {

Interval enclosing_interval(const Exact& x) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  constexpr double largest = std::numeric_limits<double>::max();
  constexpr double smallest = std::numeric_limits<double>::denorm_min();
  if (x.sign() == CGAL::ZERO) return Interval(0);
  // |mantissa| = m * 2^e with m in [0.5, 1) truncated towards zero, so |x| in [m, m + 2^-53] * 2^e.
  long e = 0;
  const double m = std::fabs(mpz_get_d_2exp(&e, x.man()));
  const long exponent = e + x.exp();
  double low, high;
  if (exponent > std::numeric_limits<double>::max_exponent) {
    low = largest, high = inf;
  } else if (exponent < std::numeric_limits<double>::min_exponent - std::numeric_limits<double>::digits) {
    low = 0, high = smallest;
  } else {
    // ldexp is exact unless it overflows or underflows; one ulp outwards covers both cases.
    low = std::nextafter(std::ldexp(m, static_cast<int>(exponent)), 0.0);
    high = std::nextafter(std::ldexp(m + std::ldexp(1.0, -53), static_cast<int>(exponent)), inf);
  }
  return x.sign() == CGAL::POSITIVE ? Interval(low, high) : Interval(-high, -low);
}

}  // namespace apollonius
