// Predicate curve_point_in_box(p, box): whether a point of a trisector (curve_point.h) lies in the closed
// box: its x, y, z are X / 2 + p_o in the trisector's frame, compared exactly with the box's doubles.
#pragma once

#include "predicates/curve_point.h"
#include "predicates/filtered_predicate.h"

namespace apollonius {

struct Curve_point_in_box_predicate {
  static constexpr const char* name = "curve_point_in_box";
  using Exact_number = Rational;

  template <class NT>
  static bool evaluate(const Curve_point& p, const Axis_box& box) {
    const Field_point<NT> x = p.coordinates<NT>();
    const Site& o = p.trisector().origin();
    const double origin[3] = {o.x, o.y, o.z};
    for (int k = 0; k < 3; ++k) {
      Vector4<NT> unit{NT(0), NT(0), NT(0), NT(0)};
      unit[k] = NT(1) / NT(2);
      // x_k - bound = X_k / 2 + o_k - bound
      for (const int side : {0, 1}) {
        const double bound = side == 0 ? box.lo[k] : box.hi[k];
        const Sign s = sign_of_number(euclidean_value(x, unit, NT(origin[k]) - NT(bound)));
        if ((side == 0 && s == Sign::NEGATIVE) || (side == 1 && s == Sign::POSITIVE)) return false;
      }
    }
    return true;
  }
};

inline const Filtered_predicate<Curve_point_in_box_predicate> curve_point_in_box{};

}  // namespace apollonius
