// Numbers of a vertex's field Q(sqrt d) as values one can compute with: an Interval for the filter, a
// CGAL::Sqrt_extension over Rational (exact: sign, +, -, *) for the exact stage. The predicates that need
// products of field numbers (orders around edges and vertices) work in these.
#pragma once

#include <CGAL/Sqrt_extension.h>

#include <array>
#include <type_traits>

#include "predicates/trisector.h"

namespace apollonius {

using Field_extension = CGAL::Sqrt_extension<Rational, Rational, CGAL::Tag_true, CGAL::Tag_false>;

template <class NT>
using Field_value = std::conditional_t<std::is_same_v<NT, Rational>, Field_extension, Interval>;

inline Field_extension to_field_value(const Root_number<Rational>& x) {
  return Field_extension(x.a / x.denominator, x.b / x.denominator, x.d);
}
inline Interval to_field_value(const Interval& x) { return x; }
inline Field_extension to_field_value(const Rational& x) { return Field_extension(x); }

// Certain for Interval (throws Uncertain_sign), exact for Field_extension.
inline Sign sign_of_field_value(const Interval& x) { return certain_sign(x); }
inline Sign sign_of_field_value(const Field_extension& x) { return static_cast<Sign>(CGAL::sign(x)); }

// The coordinates X = 2 (v - p_o, r + w_o) of a field point (X_3 is 2 (r + w_o), not Lorentz-dualled).
template <class NT>
std::array<Field_value<NT>, 4> field_coordinates(const Field_point<NT>& p) {
  if constexpr (std::is_same_v<NT, Rational>) {
    std::array<Field_value<NT>, 4> X;
    for (int j = 0; j < 4; ++j)
      X[j] = Field_extension(p.scaled[j].a / p.denominator, p.scaled[j].b / p.denominator, p.discriminant);
    return X;
  } else {
    return {p.X[0], p.X[1], p.X[2], p.X[3]};
  }
}

template <class F>
F determinant(const std::array<F, 3>& x, const std::array<F, 3>& y, const std::array<F, 3>& z) {
  return x[0] * (y[1] * z[2] - y[2] * z[1]) - x[1] * (y[0] * z[2] - y[2] * z[0]) + x[2] * (y[0] * z[1] - y[1] * z[0]);
}

}  // namespace apollonius
