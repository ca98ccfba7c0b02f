#include "predicates/number_types.h"

#include <cfenv>
#include <utility>

namespace apollonius {

Exact exact_integer(const CGAL::Gmpz& z) {
  if (z == 0) return Exact(0);
  const Exact magnitude(CGAL::abs(z));
  return z < 0 ? -magnitude : magnitude;
}

// CGAL::Mpzf::to_interval keeps the mantissa's top 53 bits exactly and the next integer up, then scales
// both by std::ldexp(1, e) in interval arithmetic. That scale must be rounded to nearest: under a
// Rounding_guard's upward rounding a scale below the subnormal range becomes denorm_min instead of 0, and
// the lower bound then exceeds the value (test_vertices_of, "beyond the double range").
Interval enclosing_interval(const Exact& x) {
  const int mode = std::fegetround();
  std::fesetround(FE_TONEAREST);
  const std::pair<double, double> bounds = x.to_interval();
  std::fesetround(mode);
  return Interval(bounds);
}

}  // namespace apollonius
