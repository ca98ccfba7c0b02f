// binary_exponent (number_types.h) reads the exponent off Mpzf's interval where both bounds lie in one binade
// of normal doubles, and off the exact rational elsewhere: 2^e <= |x| < 2^(e+1), checked exactly, at the double range's edges
// (2^1023, 2^1024, the subnormals), on powers of two and numbers just below them (whose top bits would
// round up), and on sums of products spread over the whole range.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "predicates/number_types.h"

using namespace apollonius;

namespace {

bool is_binary_exponent(const Exact& x, long e) {
  const Exact magnitude = x.sign() == CGAL::NEGATIVE ? -x : x;
  return !(magnitude < times_power_of_two(Exact(1), static_cast<int>(e))) &&
         magnitude < times_power_of_two(Exact(1), static_cast<int>(e + 1));
}

}  // namespace

TEST_CASE("binary_exponent is floor(log2 |x|) at powers of two and just beside them, across the range") {
  for (int k = -1300; k <= 1300; ++k) {
    CAPTURE(k);
    const Exact power = times_power_of_two(Exact(1), k);
    CHECK(is_binary_exponent(power, k));
    CHECK(is_binary_exponent(-power, k));
    CHECK(binary_exponent(power - times_power_of_two(Exact(1), k - 80)) == k - 1);  // 80 ones: a top limb of ones
    CHECK(binary_exponent(power + times_power_of_two(Exact(1), k - 60)) == k);
    CHECK(binary_exponent(-(power * Exact(0x1.fffffffffffffp0))) == k);
  }
}

TEST_CASE("binary_exponent is floor(log2 |x|) on sums of products of doubles from 5e-324 to 1e300") {
  std::mt19937_64 random(20261202);
  std::uniform_int_distribution<int> exponent(-1074, 1000), sign(0, 1);
  std::uniform_real_distribution<double> mantissa(1, 2);
  int checked = 0;
  for (int trial = 0; trial < 5000; ++trial) {
    CAPTURE(trial);
    Exact x(0);
    for (int term = 0; term < 3; ++term) {
      Exact product(sign(random) ? 1 : -1);
      const int degree = 1 + static_cast<int>(random() % 12);
      for (int k = 0; k < degree; ++k)  // a 53-bit mantissa, or a subnormal where the exponent is below -1022
        product = product * Exact(std::ldexp(std::round(std::ldexp(mantissa(random), 52)), exponent(random) - 52));
      x = x + product;
    }
    if (x.sign() == CGAL::ZERO) continue;
    CHECK(is_binary_exponent(x, binary_exponent(x)));
    ++checked;
  }
  CHECK(checked > 4900);
}
