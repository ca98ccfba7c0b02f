#include "predicates/double_double_ball.h"

#include <limits>

namespace apollonius {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

}  // namespace

using namespace double_double;

// q ~ a / b, then |a / b - q| = |a - q b| / |b| <= (|r| + error(r)) / (|b| - error(b)), r = a - q b as a ball.
Double_double_ball quotient(const Double_double_ball& a, const Double_double_ball& b) {
  const double b_least = (std::fabs(b.hi) - std::fabs(b.lo) - b.error) * (1 - 4 * kUnitRoundoff);
  if (!(b_least > 0)) return {0, 0, kInfinity};
  const double q1 = a.hi / b.hi;
  const Double_double_ball first_residual = a - Double_double_ball(q1) * b;
  double qh, ql;
  fast_two_sum(q1, first_residual.hi / b.hi, qh, ql);
  const Double_double_ball q(qh, ql, 0);
  const Double_double_ball residual = a - q * b;
  return {qh, ql, rounded_up((residual.magnitude() + residual.error) / b_least)};
}

// s ~ sqrt(a), then |sqrt(a) - s| = |a - s^2| / (sqrt(a) + s) <= (|r| + error(r)) / s, r = a - s^2.
Double_double_ball square_root(const Double_double_ball& a) {
  if (!(a.hi - std::fabs(a.lo) - a.error > 0)) return {0, 0, kInfinity};
  const double s1 = std::sqrt(a.hi);
  const Double_double_ball first_residual = a - Double_double_ball(s1) * Double_double_ball(s1);
  double sh, sl;
  fast_two_sum(s1, first_residual.hi / (2 * s1), sh, sl);
  const Double_double_ball s(sh, sl, 0);
  const Double_double_ball residual = a - s * s;
  const double s_least = (sh - std::fabs(sl)) * (1 - 4 * kUnitRoundoff);
  if (!(s_least > 0)) return {0, 0, kInfinity};
  return {sh, sl, rounded_up((residual.magnitude() + residual.error) / s_least)};
}

}  // namespace apollonius
