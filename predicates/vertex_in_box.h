// Predicate vertex_in_box(v, box, closed_above): whether the vertex centre lies in the half-open box
// [lo, hi) on each axis, or [lo, hi] on the axes where closed_above is set (the upper faces of the root
// box). Leaves of a subdivision are half-open, so every vertex belongs to exactly one of them.
#pragma once

#include "axis_box.h"
#include "compare_vertices.h"

namespace apollonius {

inline Sign compare_numbers(const Interval& x, double y) { return certain_sign(x - Interval(y)); }
inline Sign compare_numbers(const Root_number<Exact>& x, double y) {
  return compare(x, Root_number<Exact>{Exact(y), Exact(0), Exact(0), Exact(1)});
}

struct Vertex_in_box_predicate {
  static constexpr const char* name = "vertex_in_box";

  template <class NT>
  static bool evaluate(const Vertex& v, const Axis_box& box, const std::array<bool, 3>& closed_above) {
    const auto p = absolute_point<NT>(v);
    for (int a = 0; a < 3; ++a) {
      if (compare_numbers(p[a], box.lo[a]) == Sign::NEGATIVE) return false;
      const Sign above = compare_numbers(p[a], box.hi[a]);
      if (above == Sign::POSITIVE || (above == Sign::ZERO && !closed_above[a])) return false;
    }
    return true;
  }
};

inline const Filtered_predicate<Vertex_in_box_predicate> vertex_in_box{};

}  // namespace apollonius
