// Predicate power_lift_outside_span(basis, s): whether (x_s, y_s, z_s, w_s, x_s^2 + y_s^2 + z_s^2 - w_s^2)
// in R^5 lies outside the affine span of the same points of a basis of four sites whose lifts (x, y, z, w)
// span a 3-space. A point X = (x, r) ties sites a and b when 2 X.(L_b - L_a) = h_b - h_a (h = |x|^2 - w^2,
// L = (x, w)); the sites tie all along one line, that of any quadruple of them with a discrete set of
// roots, exactly when their points (L, h) span a 3-space too: then every such quadruple has that line and
// the same polynomial on it (vertices_of.h), hence the same roots as points.
#pragma once

#include <array>
#include <cstddef>

#include "predicates/filtered_predicate.h"
#include "predicates/lift_outside_span.h"
#include "predicates/site.h"

namespace apollonius {

struct Power_lift_outside_span_predicate {
  static constexpr const char* name = "power_lift_outside_span";

  // The 4 x 5 matrix of the three basis differences and s's has rank 4 exactly when one of its five 4 x 4
  // minors is not zero. With Interval, an uncertain minor sends the predicate to Exact unless another
  // answers; Exact is exact (products and sums of doubles, no division).
  template <class NT>
  static bool evaluate(const std::array<Site, 4>& basis, const Site& s) {
    const Site& o = basis[0];
    const auto power = [](const Site& p) { return NT(p.x) * NT(p.x) + NT(p.y) * NT(p.y) + NT(p.z) * NT(p.z) - NT(p.w) * NT(p.w); };
    const NT power_o = power(o);
    const auto row = [&](const Site& p) {
      return std::array<NT, 5>{NT(p.x) - NT(o.x), NT(p.y) - NT(o.y), NT(p.z) - NT(o.z), NT(p.w) - NT(o.w), power(p) - power_o};
    };
    const std::array<std::array<NT, 5>, 4> rows = {row(basis[1]), row(basis[2]), row(basis[3]), row(s)};
    bool uncertain = false;
    for (std::size_t skipped = 0; skipped < 5; ++skipped) {
      std::array<std::array<NT, 4>, 4> square;
      for (std::size_t i = 0; i < 4; ++i)
        for (std::size_t j = 0, t = 0; j < 5; ++j)
          if (j != skipped) square[i][t++] = rows[i][j];
      try {
        if (certain_sign(Lift_outside_span_predicate::minor<NT>(square, {0, 1, 2, 3}, 4)) != Sign::ZERO) return true;
      } catch (const Uncertain_sign&) {
        uncertain = true;
      }
    }
    if (uncertain) throw Uncertain_sign();
    return false;
  }
};

inline const Filtered_predicate<Power_lift_outside_span_predicate> power_lift_outside_span{};

}  // namespace apollonius
