// Predicate vertex_in_box(v, box, closed_above): whether the vertex centre lies in the half-open box
// [lo, hi) on each axis, or [lo, hi] on the axes where closed_above is set (the upper faces of the root
// box). Leaves of a subdivision are half-open, so every vertex belongs to exactly one of them.
#pragma once

#include <optional>

#include "predicates/axis_box.h"
#include "predicates/compare_vertices.h"
#include "predicates/vertex_rounding.h"

namespace apollonius {

inline Sign compare_numbers(const Interval& x, double y) { return certain_sign(x - Interval(y)); }
inline Sign compare_numbers(const Root_number<Exact>& x, double y) {
  return compare(x, Root_number<Exact>{Exact(y), Exact(0), Exact(0), Exact(1)});
}

// The vertex's coordinates against doubles, in NT. Exact compares the correctly rounded coordinate first:
// rounding to nearest is monotone and leaves doubles as they are, so round(x) < y gives x < y and
// round(x) > y gives x > y. Only round(x) = y needs x in Q(sqrt d), whose arithmetic is slow on sites
// spread over many binades (fuzz inputs spent seconds there, one box bound at a time).
template <class NT>
class Coordinates_against_doubles {
 public:
  explicit Coordinates_against_doubles(const Vertex& v) : point_(absolute_point<NT>(v)) {}
  Sign compare(int axis, double y) const { return compare_numbers(point_[axis], y); }

 private:
  decltype(absolute_point<NT>(std::declval<const Vertex&>())) point_;
};

template <>
class Coordinates_against_doubles<Exact> {
 public:
  explicit Coordinates_against_doubles(const Vertex& v) : vertex_(v) {}
  Sign compare(int axis, double y) {
    const double rounded = vertex_.rounded()[axis];
    if (rounded != y) return rounded < y ? Sign::NEGATIVE : Sign::POSITIVE;
    return vertex_.rounding_sides()[axis];  // x - y = x - round(x)
  }

 private:
  const Vertex& vertex_;
};

struct Vertex_in_box_predicate {
  static constexpr const char* name = "vertex_in_box";

  // Once an exact stage has rounded the vertex, its rounded point decides every bound it differs from, with
  // no interval (whose failure costs an exception: a fuzz input spent seconds throwing them).
  // With the rounding sides too, every bound (vertex.h).
  static std::optional<bool> static_filter(const Vertex& v, const Axis_box& box, const std::array<bool, 3>& closed_above) {
    const std::array<double, 4>* rounded = v.rounded_if_computed();
    if (rounded == nullptr) return std::nullopt;
    const std::array<Sign, 3>* sides = v.rounding_sides_if_computed();
    bool inside = true;
    for (int a = 0; a < 3; ++a) {
      const double x = (*rounded)[a];
      if (x == box.lo[a] || x == box.hi[a]) {
        if (sides == nullptr) return std::nullopt;
        const Sign side = (*sides)[a];  // the sign of the coordinate minus x
        if (x == box.lo[a] && side == Sign::NEGATIVE) return false;
        if (x == box.hi[a] && (side == Sign::POSITIVE || (side == Sign::ZERO && !closed_above[a]))) return false;
        if (x != box.lo[a] && !(box.lo[a] < x)) return false;
        if (x != box.hi[a] && !(x < box.hi[a])) return false;
        continue;
      }
      inside = inside && box.lo[a] < x && x < box.hi[a];
    }
    return inside;
  }

  // evaluate<Interval> without exceptions (a vertex on a box bound, as on a lattice, always goes on), and
  // outside as soon as one axis shows it, whatever the others.
  static std::optional<bool> interval_stage(const Vertex& v, const Axis_box& box, const std::array<bool, 3>& closed_above) {
    const std::array<Interval, 4> p = v.point_interval();
    bool certain = true;
    for (int a = 0; a < 3; ++a) {
      const std::optional<Sign> below = sign_if_certain(p[a] - Interval(box.lo[a]));
      const std::optional<Sign> above = sign_if_certain(p[a] - Interval(box.hi[a]));
      if (below == Sign::NEGATIVE) return false;
      if (above == Sign::POSITIVE || (above == Sign::ZERO && !closed_above[a])) return false;
      certain = certain && below && above;
    }
    if (!certain) return std::nullopt;
    return true;
  }

  // The same on the vertex's balls (vertex_ball.h): vertices a few ulps from a bound (sites one ulp off a
  // lattice, whose planes the dyadic boxes share). A ball never shows a vertex on a bound, so closed_above
  // does not enter.
  static std::optional<bool> ball_stage(const Vertex& v, const Axis_box& box, const std::array<bool, 3>&) {
    const Ball_coordinates* X = v.ball_coordinates();
    if (X == nullptr) return std::nullopt;
    const Nearest_rounding_guard nearest;
    bool certain = true;
    const auto side = [](const Double_double_ball& p, double bound) -> std::optional<Sign> {  // of p - bound
      if (std::isinf(bound) && p.usable()) return bound > 0 ? Sign::NEGATIVE : Sign::POSITIVE;
      return sign_if_certain(p - Double_double_ball(bound));
    };
    for (int a = 0; a < 3; ++a) {
      const Double_double_ball p = absolute_coordinate(v.origin(), *X, a);
      const std::optional<Sign> below = side(p, box.lo[a]);
      const std::optional<Sign> above = side(p, box.hi[a]);
      if (below == Sign::NEGATIVE || above == Sign::POSITIVE) return false;
      certain = certain && below && above;
    }
    if (!certain) return std::nullopt;
    return true;
  }

  template <class NT>
  static bool evaluate(const Vertex& v, const Axis_box& box, const std::array<bool, 3>& closed_above) {
    Coordinates_against_doubles<NT> p(v);
    for (int a = 0; a < 3; ++a) {
      if (p.compare(a, box.lo[a]) == Sign::NEGATIVE) return false;
      const Sign above = p.compare(a, box.hi[a]);
      if (above == Sign::POSITIVE || (above == Sign::ZERO && !closed_above[a])) return false;
    }
    return true;
  }
};

inline const Filtered_predicate<Vertex_in_box_predicate> vertex_in_box{};

}  // namespace apollonius
