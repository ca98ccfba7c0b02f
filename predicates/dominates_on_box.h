// Predicate dominates_on_box(j, i, box): site j is strictly closer than site i at every point of the closed
// box, certified by  max_box d_j < min_box d_i, i.e.  sqrt(F_j) - w_j < sqrt(N_i) - w_i  with F_j the
// squared distance from x_j to the farthest corner and N_i from x_i to the box. This is paper Theorem 6
// with the box itself instead of its circumscribed ball; then i owns no point of the box and is no
// candidate there. Exact: sign(sqrt N_i - sqrt F_j - (w_i - w_j)), two square roots.
#pragma once

#include <optional>

#include "box_distance.h"
#include "filtered_predicate.h"
#include "root_sign.h"

namespace apollonius {

struct Dominates_on_box_predicate {
  static constexpr const char* name = "dominates_on_box";

  // L_i > U_j certifies domination, U_i < L_j (least of i certainly below greatest of j) its failure.
  static std::optional<bool> static_filter(const Site& j, const Site& i, const Axis_box& box) {
    const Distance_bounds least_i = least_distance_bounds(i, box), greatest_j = greatest_distance_bounds(j, box);
    if (least_i.lower > greatest_j.upper) return true;
    if (least_i.upper < greatest_j.lower) return false;
    return std::nullopt;
  }

  template <class NT>
  static bool evaluate(const Site& j, const Site& i, const Axis_box& box) {
    const NT near_i = squared_distance_to_box<NT>(i, box);
    const NT far_j = squared_distance_to_farthest_corner<NT>(j, box);
    return sign_of_two_root_sum(NT(j.w) - NT(i.w), NT(1), near_i, NT(-1), far_j) == Sign::POSITIVE;
  }
};

inline const Filtered_predicate<Dominates_on_box_predicate> dominates_on_box{};

}  // namespace apollonius
