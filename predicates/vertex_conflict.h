// Predicate vertex_conflict(v, s): the sign of d_s(v) - r(v). NEGATIVE means s is strictly closer than the
// vertex's own sites (the vertex is not in the diagram), ZERO means s ties with them.
//
// If r + w_s < 0, then d_s(v) >= -w_s > r: POSITIVE. Otherwise the sign is that of
// |v - p_s|^2 - (r + w_s)^2, which on the cone |U| = X_3 (quadruple_line.h) is the linear form
// |a_s|^2 - b_s^2 - <(a_s, b_s), X>  with a_s = p_s - p_0, b_s = w_s - w_0: one square root, one squaring.
//
// Its interval stage answers nothing rather than throw: where tests go exact in bulk (ties, lattices off by
// an ulp), the exception costs more than the test.
#pragma once

#include <array>
#include <optional>

#include "predicates/filtered_predicate.h"
#include "predicates/vertex.h"
#include "predicates/wide_interval.h"

namespace apollonius {

struct Vertex_conflict_predicate {
  static constexpr const char* name = "vertex_conflict";

  template <class NT>
  static Sign evaluate(const Vertex& v, const Site& s) {
    const auto& X = coordinates_for<NT>(v);
    const Relative_site<NT> a = relative_site<NT>(v.origin(), s);
    if (X.sign(X.scaled[3] + X.denominator * (NT(2) * a.row[3])) == Sign::NEGATIVE) return Sign::POSITIVE;
    return X.sign(X.denominator * a.rhs - (X.scaled[0] * a.row[0] + X.scaled[1] * a.row[1] +
                                           X.scaled[2] * a.row[2] + X.scaled[3] * a.row[3]));
  }

  // evaluate<Interval>, with both tests multiplied by 2^-k for a vertex with a Scaled_box (X in
  // scaled 2^k): X beyond the double range then meets the sites' terms within it.
  static std::optional<Sign> interval_stage(const Vertex& v, const Site& s) {
    const Scaled_box* scaled = v.scaled_box();
    const std::array<Interval, 4>& X = scaled != nullptr ? scaled->scaled : v.coordinates<Interval>().scaled;
    const int k = scaled != nullptr ? static_cast<int>(scaled->exponent) : 0;
    const Relative_site<Interval> a = relative_site<Interval>(v.origin(), s);
    const std::optional<Sign> valid = sign_if_certain(X[3] + times_power_of_two(Interval(2) * a.row[3], -k));
    if (!valid) return std::nullopt;
    if (*valid == Sign::NEGATIVE) return Sign::POSITIVE;
    Interval rhs = a.rhs;
    if (k != 0) {  // |a_s|^2 - b_s^2 as products of factors times 2^-h and 2^-(k - h), none overflowing
      const int h = k / 2;
      const auto term = [&](int j) { return times_power_of_two(a.row[j], -h) * times_power_of_two(a.row[j], h - k); };
      rhs = term(0) + term(1) + term(2) - term(3);
    }
    return sign_if_certain(rhs - (X[0] * a.row[0] + X[1] * a.row[1] + X[2] * a.row[2] + X[3] * a.row[3]));
  }

  // evaluate<Wide_interval>, for sites whose rows squared leave the double range (1e-260 beside 1e265),
  // relative to the vertex's site q nearest to s instead of its origin (move_origin, quadruple_line.h):
  // |v - p_s|^2 - (r + w_s)^2 does not depend on the origin, and an error e in X then costs only
  // |p_s - p_q| e. A site a hair from one of the vertex's sites (a cluster 1e-9 wide beside balls of
  // radius 1) is then decided without the exact stage.
  static std::optional<Sign> wide_stage(const Vertex& v, const Site& s) {
    const Scaled_box* scaled = v.scaled_box();
    const std::array<Interval, 4>& box = scaled != nullptr ? scaled->scaled : v.coordinates<Interval>().scaled;
    const long k = scaled != nullptr ? scaled->exponent : 0;
    const std::array<Site, 4>& sites = v.quadruple().sites;
    int nearest = 0;
    for (int m = 1; m < 4; ++m)
      if (coarse_distance(s, sites[m]) < coarse_distance(s, sites[nearest])) nearest = m;
    const Site& q = sites[nearest];
    try {
      std::array<Wide_interval, 4> X;
      for (int j = 0; j < 4; ++j) X[j] = Wide_interval::with_exponent(box[j], k);
      if (nearest != 0) move_origin(X, sites[0], q);
      const Relative_site<Wide_interval> a = relative_site<Wide_interval>(q, s);
      const std::optional<Sign> valid = sign_if_certain(X[3] + Wide_interval(2) * a.row[3]);
      if (!valid) return std::nullopt;
      if (*valid == Sign::NEGATIVE) return Sign::POSITIVE;
      return sign_if_certain(a.rhs - (X[0] * a.row[0] + X[1] * a.row[1] + X[2] * a.row[2] + X[3] * a.row[3]));
    } catch (const Uncertain_sign&) {
      return std::nullopt;
    }
  }

  // The same two tests on the vertex's balls, where the intervals cannot tell (vertex_ball.h).
  static std::optional<Sign> ball_stage(const Vertex& v, const Site& s) {
    const Ball_coordinates* X = v.ball_coordinates();
    if (X == nullptr) return std::nullopt;
    const Nearest_rounding_guard nearest;
    const Site& o = v.origin();
    const Ball_coordinates a = {ball_difference(s.x, o.x), ball_difference(s.y, o.y), ball_difference(s.z, o.z),
                                ball_difference(s.w, o.w)};
    const std::optional<Sign> valid = sign_if_certain((*X)[3] + (a[3] + a[3]));
    if (!valid) return std::nullopt;
    if (*valid == Sign::NEGATIVE) return Sign::POSITIVE;
    const Double_double_ball rhs = a[0] * a[0] + a[1] * a[1] + a[2] * a[2] - a[3] * a[3];
    return sign_if_certain(rhs - ((*X)[0] * a[0] + (*X)[1] * a[1] + (*X)[2] * a[2] + (*X)[3] * a[3]));
  }
};

inline const Filtered_predicate<Vertex_conflict_predicate> vertex_conflict{};

}  // namespace apollonius
