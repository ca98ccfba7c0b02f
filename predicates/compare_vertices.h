// Predicate compare_vertices(u, v): lexicographic order of the exact (x, y, z, r); ZERO means u and v are
// the same point of the diagram (built from different quadruples, or from different roots that coincide).
// Two vertices lie in different fields Q(sqrt d_u), Q(sqrt d_v): each comparison costs two squarings.
#pragma once

#include "predicates/filtered_predicate.h"
#include "predicates/vertex.h"

namespace apollonius {

inline Sign compare_numbers(double x, double y) { return certain_sign(x - y); }
inline Sign compare_numbers(const Interval& x, const Interval& y) { return certain_sign(x - y); }
inline Sign compare_numbers(const Root_number<Exact>& x, const Root_number<Exact>& y) { return compare(x, y); }

template <class NT>
auto absolute_point(const Vertex& v) {
  if constexpr (std::is_same_v<NT, Interval>) {
    return v.point_interval();
  } else if constexpr (std::is_same_v<NT, double>) {
    const auto X = coordinates_for<double>(v);
    const Site& o = v.origin();
    return std::array<double, 4>{o.x + X.scaled[0] / 2, o.y + X.scaled[1] / 2, o.z + X.scaled[2] / 2, X.scaled[3] / 2 - o.w};
  } else {
    return exact_point(v);
  }
}

struct Compare_vertices_predicate {
  static constexpr const char* name = "compare_vertices";

  template <class NT>
  static Sign evaluate(const Vertex& u, const Vertex& v) {
    const auto p = absolute_point<NT>(u);
    const auto q = absolute_point<NT>(v);
    for (int j = 0; j < 4; ++j)
      if (const Sign s = compare_numbers(p[j], q[j]); s != Sign::ZERO) return s;
    return Sign::ZERO;
  }

  // evaluate<Interval> without exceptions: most comparisons are of one vertex found from two quadruples
  // of its tie set, which only the exact stage can show equal.
  static std::optional<Sign> interval_stage(const Vertex& u, const Vertex& v) {
    const std::array<Interval, 4> p = u.point_interval(), q = v.point_interval();
    for (int j = 0; j < 4; ++j) {
      const std::optional<Sign> s = sign_if_certain(p[j] - q[j]);
      if (!s) return std::nullopt;
      if (*s != Sign::ZERO) return s;
    }
    return Sign::ZERO;
  }
};

inline const Filtered_predicate<Compare_vertices_predicate> compare_vertices{};

}  // namespace apollonius
