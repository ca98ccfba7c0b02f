// Predicate is_hidden(i, j): ball i lies inside ball j, tangency included: |x_i - x_j| <= w_j - w_i.
// Such a site has a cell without interior (docs/contract.md, "The diagram"). Of two identical sites the
// later index is the hidden one, so that exactly one of them stays.
#pragma once

#include <optional>

#include "predicates/filtered_predicate.h"
#include "predicates/site.h"
#include "predicates/wide_interval.h"

namespace apollonius {

struct Is_hidden_predicate {
  static constexpr const char* name = "is_hidden";

  template <class NT>
  static bool evaluate(const Site& i, Site_index index_i, const Site& j, Site_index index_j) {
    if (i == j) return index_i > index_j;
    const NT gap = NT(j.w) - NT(i.w);
    if (certain_sign(gap) == Sign::NEGATIVE) return false;
    const NT dx = NT(i.x) - NT(j.x), dy = NT(i.y) - NT(j.y), dz = NT(i.z) - NT(j.z);
    return certain_sign(dx * dx + dy * dy + dz * dz - gap * gap) != Sign::POSITIVE;
  }

  // For sites whose squared distance leaves the double range (1e-260 beside 1e265).
  static std::optional<bool> wide_stage(const Site& i, Site_index index_i, const Site& j, Site_index index_j) {
    try {
      return evaluate<Wide_interval>(i, index_i, j, index_j);
    } catch (const Uncertain_sign&) {
      return std::nullopt;
    }
  }
};

inline const Filtered_predicate<Is_hidden_predicate> is_hidden{};

}  // namespace apollonius
