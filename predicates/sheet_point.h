// The point where the bisector sheet of two sites a, b crosses the segment between their centres,
// p_a + (1/2 + (w_a - w_b) / (2 D)) (p_b - p_a) with r = D / 2 - (w_a + w_b) / 2, D = |p_b - p_a|: a point
// of every sheet (non-hidden sites have D > |w_a - w_b|), in Q(sqrt(D^2)). It is the witness of a face with
// no edge, which is then the whole sheet. Predicates on it, filtered in intervals, exact with
// CGAL::Sqrt_extension:
//  - axis_point_conflict(a, b, s): the sign of d_s - r there (as vertex_conflict);
//  - axis_point_in_box(a, b, box): whether it lies in the closed box;
//  - enclose_axis_point(a, b): its coordinates' enclosure in doubles.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include <CGAL/Sqrt_extension.h>

#include "predicates/axis_box.h"
#include "predicates/filtered_predicate.h"
#include "predicates/rounding_guard.h"
#include "predicates/site.h"

namespace apollonius {

struct Axis_point_predicates {
  using Extension = CGAL::Sqrt_extension<Rational, Rational, CGAL::Tag_true, CGAL::Tag_false>;

  // x, y, z, r of the point in F (Interval or Extension).
  template <class NT>
  static auto point(const Site& a, const Site& b) {
    using F = std::conditional_t<std::is_same_v<NT, Rational>, Extension, Interval>;
    const NT dx = NT(b.x) - NT(a.x), dy = NT(b.y) - NT(a.y), dz = NT(b.z) - NT(a.z);
    const NT squared = dx * dx + dy * dy + dz * dz;
    F distance;
    if constexpr (std::is_same_v<NT, Rational>)
      distance = Extension(Rational(0), Rational(1), squared);
    else
      distance = CGAL::sqrt(squared);
    const F t = F(NT(1) / NT(2)) + F((NT(a.w) - NT(b.w)) / NT(2)) / distance;
    return std::array<F, 4>{F(NT(a.x)) + t * F(dx), F(NT(a.y)) + t * F(dy), F(NT(a.z)) + t * F(dz),
                            distance / F(NT(2)) - F((NT(a.w) + NT(b.w)) / NT(2))};
  }

  template <class F>
  static Sign sign(const F& x) {
    if constexpr (std::is_same_v<F, Interval>)
      return certain_sign(x);
    else
      return static_cast<Sign>(CGAL::sign(x));
  }
};

struct Axis_point_conflict_predicate : Axis_point_predicates {
  static constexpr const char* name = "axis_point_conflict";
  using Exact_number = Rational;

  template <class NT>
  static Sign evaluate(const Site& a, const Site& b, const Site& s) {
    const auto p = point<NT>(a, b);
    using F = std::decay_t<decltype(p[0])>;
    const F reach = p[3] + F(NT(s.w));  // r + w_s
    if (sign(reach) == Sign::NEGATIVE) return Sign::POSITIVE;
    const F dx = p[0] - F(NT(s.x)), dy = p[1] - F(NT(s.y)), dz = p[2] - F(NT(s.z));
    return sign(dx * dx + dy * dy + dz * dz - reach * reach);
  }
};

struct Axis_point_in_box_predicate : Axis_point_predicates {
  static constexpr const char* name = "axis_point_in_box";
  using Exact_number = Rational;

  template <class NT>
  static bool evaluate(const Site& a, const Site& b, const Axis_box& box) {
    const auto p = point<NT>(a, b);
    using F = std::decay_t<decltype(p[0])>;
    for (int k = 0; k < 3; ++k)
      if (sign(p[k] - F(NT(box.lo[k]))) == Sign::NEGATIVE || sign(p[k] - F(NT(box.hi[k]))) == Sign::POSITIVE) return false;
    return true;
  }
};

inline const Filtered_predicate<Axis_point_conflict_predicate> axis_point_conflict{};
inline const Filtered_predicate<Axis_point_in_box_predicate> axis_point_in_box{};

// An enclosure of the point's x, y, z, rounded outwards: the centres' bounding box (the point lies on the
// segment between them), narrowed to its intervals where those are finite. The box alone let every ball
// tangent to one circle reach the sheet point of two balls far apart (topology/reaching_sites.h).
inline std::array<Interval, 3> enclose_axis_point(const Site& a, const Site& b) {
  Rounding_guard guard;
  const std::array<Interval, 4> point = Axis_point_predicates::point<Interval>(a, b);
  std::array<Interval, 3> box;
  for (int k = 0; k < 3; ++k) {
    double lo = std::min(centre_coordinate(a, k), centre_coordinate(b, k));
    double hi = std::max(centre_coordinate(a, k), centre_coordinate(b, k));
    if (std::isfinite(point[k].inf()) && std::isfinite(point[k].sup())) {  // both hold the point
      lo = std::max(lo, point[k].inf());
      hi = std::min(hi, point[k].sup());
    }
    box[k] = Interval(lo, hi);
  }
  return box;
}

}  // namespace apollonius
