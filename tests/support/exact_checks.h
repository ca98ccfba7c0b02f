// Small exact helpers shared by the tests.
#pragma once

#include <cmath>

#include "predicates/correct_rounding.h"
#include "diagram/diagram.h"
#include "predicates/vertex.h"

namespace apollonius::testing {

inline Root_number<Exact> dyadic(double v) { return {Exact(v), Exact(0), Exact(0), Exact(1)}; }

// (a + b sqrt d) / den for doubles a, b, d, den (den > 0).
inline Root_number<Exact> root_number(double a, double b, double d, double den) {
  return {Exact(a), Exact(b), Exact(d), Exact(den)};
}

inline bool exactly_equal(const Root_number<Exact>& x, const Root_number<Exact>& y) { return compare(x, y) == Sign::ZERO; }

// x + t for a dyadic t.
inline Root_number<Exact> plus(const Root_number<Exact>& x, double t) {
  return {x.a + Exact(t) * x.denominator, x.b, x.d, x.denominator};
}

// The weighted distance d_s(p) - r at the rounded vertex, in long double: an independent plausibility check.
inline long double rounded_residual(const std::array<double, 4>& p, const Site& s) {
  const long double dx = static_cast<long double>(p[0]) - s.x, dy = static_cast<long double>(p[1]) - s.y,
                    dz = static_cast<long double>(p[2]) - s.z;
  return std::sqrt(dx * dx + dy * dy + dz * dz) - s.w - p[3];
}

// The correctly rounded point by the exact path alone (to_nearest_double): the oracle for the printed
// values, independent of the double-double stage of rounded_coordinates.
inline std::array<double, 4> exactly_rounded_point(const Vertex& v) {
  const auto p = exact_point(v);
  return {to_nearest_double(p[0]), to_nearest_double(p[1]), to_nearest_double(p[2]), to_nearest_double(p[3])};
}

}  // namespace apollonius::testing
