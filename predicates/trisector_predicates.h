// The predicates of the diagram's edges (paper section 5.3), each one formula on a trisector and the
// vertices on it (trisector.h), filtered in intervals and exact in Q(sqrt d):
//  - classify_trisector(T): the kind and shape of the curve;
//  - compare_along_trisector(T, u, v): the order of two of its vertices, forward along the curve;
//  - departure_sign(T, v, s): whether site s gets farther (POSITIVE) or nearer going forward from v;
//  - sides_near_vertex(T, v, s): the sign of d_s - r just after v and just before it, to second order.
#pragma once

#include <algorithm>
#include <optional>
#include <utility>
#include <vector>

#include "predicates/compare_vertices.h"
#include "predicates/filtered_predicate.h"
#include "predicates/curve_point.h"
#include "predicates/field_value.h"
#include "predicates/trisector.h"

namespace apollonius {

struct Classify_trisector_predicate {
  static constexpr const char* name = "classify_trisector";
  using Exact_number = Rational;

  template <class NT>
  static std::pair<Trisector_kind, Curve_shape> evaluate(const Trisector& t) {
    const Trisector_geometry<NT>& g = t.geometry<NT>();
    return {g.kind, g.shape};
  }

  // The kind and shape are the same in every frame (trisector.h).
  static std::optional<std::pair<Trisector_kind, Curve_shape>> wide_stage(const Trisector& t) {
    return framed<Wide_interval>(t);
  }
  static std::optional<std::pair<Trisector_kind, Curve_shape>> precise_stage(const Trisector& t) {
    return framed<Mpfr_interval>(t);
  }
  template <class NT>
  static std::optional<std::pair<Trisector_kind, Curve_shape>> framed(const Trisector& t) {
    try {
      const Trisector_geometry<NT>& g = t.framed_geometry<NT>().geometry;
      return std::pair{g.kind, g.shape};
    } catch (const Uncertain_sign&) {
      return std::nullopt;
    }
  }
};

// Forward is counterclockwise in (e1, e2) on a closed curve, increasing <X, monotone> on an open one.
// On the ellipse gamma1 s^2 + gamma2 t^2 = K (gamma_i > 0) a point's angle from +e1 orders it: the half
// t > 0 (with the point t = 0, s > 0) comes first, and s = <X, e1> / gamma1 falls in it and rises in the
// other (trisector.h: <centre, e_i> = 0, so <X, e_i> = gamma_i times the coordinate).
struct Compare_along_trisector_predicate {
  static constexpr const char* name = "compare_along_trisector";
  using Exact_number = Rational;

  template <class NT, class U, class V>
  static Sign evaluate(const Trisector& t, const U& u, const V& v) {
    const Trisector_geometry<NT>& g = t.geometry<NT>();
    const Field_point<NT> p = field_point_on<NT>(t, u), q = field_point_on<NT>(t, v);
    if (g.kind != Trisector_kind::ellipse)
      return compare_numbers(lorentz_value(p, g.monotone), lorentz_value(q, g.monotone));
    const int half_p = half(g, p), half_q = half(g, q);
    if (half_p != half_q) return half_p < half_q ? Sign::NEGATIVE : Sign::POSITIVE;
    const Sign by_s = compare_numbers(lorentz_value(p, g.e1), lorentz_value(q, g.e1));
    return half_p == 0 ? -by_s : by_s;
  }

  template <class NT>
  static int half(const Trisector_geometry<NT>& g, const Field_point<NT>& p) {
    const Sign t = sign_of_number(lorentz_value(p, g.e2));
    if (t != Sign::ZERO) return t == Sign::POSITIVE ? 0 : 1;
    return sign_of_number(lorentz_value(p, g.e1)) == Sign::POSITIVE ? 0 : 1;
  }
};

// Along the curve through v the tangent is tau0 = <X, e1> e2 - <X, e2> e1 (<X, tau0> = 0: it stays on the
// cone), which is forward on a closed curve and forward times sign(<tau0, monotone>) on an open one. Site s
// gets farther at the rate -(R_s . tau) / (2 (r + w_s)), R_s = (p_s - p_a, w_s - w_a): the paper's F'(0)
// (eqs. 26-28) in the coordinates X, one linear form in X. R_s . tau0 = <X, y> with y = (R_s . e2) e1 -
// (R_s . e1) e2, and <tau0, monotone> = <X, z> with z = <e2, monotone> e1 - <e1, monotone> e2.
struct Departure_sign_predicate {
  static constexpr const char* name = "departure_sign";
  using Exact_number = Rational;

  template <class NT, class P>
  static Sign evaluate(const Trisector& t, const P& v, const Site& s) {
    const Trisector_geometry<NT>& g = t.geometry<NT>();
    const Field_point<NT> p = field_point_on<NT>(t, v);
    const Vector4<NT> r = relative_site<NT>(t.origin(), s).row;
    const Vector4<NT> y = combination(euclidean_product(r, g.e2), g.e1, -euclidean_product(r, g.e1), g.e2);
    const Sign along_tau0 = -sign_of_number(lorentz_value(p, y));
    if (g.kind == Trisector_kind::ellipse) return along_tau0;
    const Vector4<NT> z =
        combination(lorentz_product(g.e2, g.monotone), g.e1, -lorentz_product(g.e1, g.monotone), g.e2);
    return along_tau0 * sign_of_number(lorentz_value(p, z));
  }
};

// The sign of d_s - r on the curve just after v (forward) and just before it, for a site s that ties at v.
// On the cone, d_s - r has the sign of phi(X) = h_s - R_s . X (vertex_conflict.h), an affine function that
// vanishes at v: its first derivative along the curve is departure_sign's; if that vanishes (R_s . tau = 0),
// the second is -R_s . X'' with <X, X''> = -<tau, tau> (the curve stays on the cone), which for any
// direction n of L with <X, n> != 0 gives sign(phi'') = sign(<tau, tau>) sign(R_s . n) sign(<X, n>); and
// <tau, tau> > 0, as tau is orthogonal to the null vector X and not parallel to it (L misses the apex). If
// that vanishes too, R_s . n = 0 for every direction of L, so phi is 0 on the whole curve: s ties along it.
struct Sides_near_vertex_predicate {
  static constexpr const char* name = "sides_near_vertex";
  using Exact_number = Rational;

  template <class NT, class P>
  static std::pair<Sign, Sign> evaluate(const Trisector& t, const P& v, const Site& s) {
    const Sign first = Departure_sign_predicate::evaluate<NT>(t, v, s);
    if (first != Sign::ZERO) return {first, -first};
    const Trisector_geometry<NT>& g = t.geometry<NT>();
    const Field_point<NT> p = field_point_on<NT>(t, v);
    const Vector4<NT> r = relative_site<NT>(t.origin(), s).row;
    Sign along = sign_of_number(lorentz_value(p, g.e1));
    Sign across = certain_sign(euclidean_product(r, g.e1));
    if (along == Sign::ZERO) {
      along = sign_of_number(lorentz_value(p, g.e2));
      across = certain_sign(euclidean_product(r, g.e2));
    }
    // With R_s . tau = 0, R_s . n has one sign for every n independent of tau, or is 0 for all of them.
    const Sign second = across * along;
    return {second, second};
  }
};

// Predicate curve_point_conflict(p, s): the sign of d_s(p) - r(p) at a point of a trisector, as
// vertex_conflict for a vertex: POSITIVE if r + w_s < 0, else the sign of h_s - R_s . X.
struct Curve_point_conflict_predicate {
  static constexpr const char* name = "curve_point_conflict";
  using Exact_number = Rational;

  template <class NT>
  static Sign evaluate(const Curve_point& c, const Site& s) {
    const Trisector& t = c.trisector();
    const Field_point<NT> p = c.coordinates<NT>();
    const Relative_site<NT> r = relative_site<NT>(t.origin(), s);
    // r + w_s = X_3 / 2 + (w_s - w_a).
    if (sign_of_number(euclidean_value(p, Vector4<NT>{NT(0), NT(0), NT(0), NT(1)}, NT(2) * r.row[3])) == Sign::NEGATIVE)
      return Sign::POSITIVE;
    const Vector4<NT> minus_row{-r.row[0], -r.row[1], -r.row[2], -r.row[3]};
    return sign_of_number(euclidean_value(p, minus_row, r.rhs));
  }
};

// The cyclic order of the sites tied along an edge (4 or more: a degenerate edge), around it: at a
// point v of the edge (a vertex, or a curve point when it has none), the order of the directions v - p_s around the edge's forward tangent (positive
// turns counterclockwise seen from its head). Consecutive sites in it, and only they, share a face
// along the edge. Returns the positions in `sites` in that order, starting with the first.
struct Order_around_edge_predicate {
  static constexpr const char* name = "order_around_edge";
  using Exact_number = Rational;

  template <class NT, class P>
  static std::vector<std::size_t> evaluate(const Trisector& t, const P& v, const std::vector<Site>& sites) {
    using F = Field_value<NT>;
    const Trisector_geometry<NT>& g = t.geometry<NT>();
    const Field_point<NT> p = field_point_on<NT>(t, v);
    const std::array<F, 4> X = field_coordinates<NT>(p);
    const F s = to_field_value(lorentz_value(p, g.e1)), u = to_field_value(lorentz_value(p, g.e2));
    std::array<F, 3> tangent;  // tau0 = <X, e1> e2 - <X, e2> e1, spatial part
    for (int j = 0; j < 3; ++j) tangent[j] = s * F(g.e2[j]) - u * F(g.e1[j]);
    const Site& a = t.origin();
    std::vector<std::array<F, 3>> direction(sites.size());  // v - p_s = X / 2 + p_a - p_s
    for (std::size_t k = 0; k < sites.size(); ++k) {
      const Vector4<NT> shift = relative_site<NT>(sites[k], a).row;  // p_a - p_s, w_a - w_s
      for (int j = 0; j < 3; ++j) direction[k][j] = X[j] / F(2) + F(shift[j]);
    }
    const auto turn = [&](std::size_t i, std::size_t j) {
      return sign_of_field_value(determinant(tangent, direction[i], direction[j]));
    };
    // Half 0: the first direction and those a positive turn from it; half 1: the rest (the opposite one
    // first). The directions are distinct (distinct tangent points of one sphere) and no two opposite but
    // possibly the first's.
    const auto half = [&](std::size_t k) { return k == 0 || turn(0, k) == Sign::POSITIVE ? 0 : 1; };
    std::vector<std::size_t> order(sites.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::vector<int> halves(sites.size());
    for (std::size_t k = 0; k < sites.size(); ++k) halves[k] = half(k);
    std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
      if (halves[i] != halves[j]) return halves[i] < halves[j];
      if (i == j) return false;
      if (i == 0) return true;
      if (j == 0) return false;
      const Sign s_ij = turn(i, j);
      if (s_ij == Sign::ZERO) return turn(0, i) == Sign::ZERO;  // the one opposite the first comes first
      return s_ij == Sign::POSITIVE;
    });
    return order;
  }
};

// Predicate face_side(p, a, b, c, level, across): at a point p of an edge where sites a, b, c tie, on which
// side of the edge, moving on the bisector sheet of a and b within the plane level . v = constant, the
// face of a and b lies: POSITIVE when it lies where across . v grows. There c is farther than a and b.
// In X = 2 (v - p_a, r + w_a), the move xi keeps d_a = d_b (R_b . xi = 0), stays on the cone
// (<X, xi> = 0) and in the level plane (level . xi = 0): xi is their 4D cross product, and c gets farther
// along it where -R_c . xi > 0. Precondition: the edge crosses the level plane transversally at p.
struct Face_side_predicate {
  static constexpr const char* name = "face_side";
  using Exact_number = Rational;

  template <class NT>
  static Sign evaluate(const Curve_point& p, const Site& a, const Site& b, const Site& c,
                       const std::array<Rational, 3>& level, const std::array<Rational, 3>& across) {
    using F = Field_value<NT>;
    const Trisector& t = p.trisector();
    // X in a's frame: X_o + 2 (p_o - p_a, w_a - w_o).
    std::array<F, 4> X = field_coordinates<NT>(p.coordinates<NT>());
    const Vector4<NT> shift = relative_site<NT>(a, t.origin()).row;
    for (int j = 0; j < 4; ++j) X[j] = X[j] + F(NT(2) * (j < 3 ? shift[j] : -shift[j]));
    const Vector4<NT> rb = relative_site<NT>(a, b).row, rc = relative_site<NT>(a, c).row;
    const auto number = [](const Rational& q) -> F {
      if constexpr (std::is_same_v<NT, Rational>)
        return F(q);
      else
        return Interval(CGAL::to_interval(q));
    };
    const std::array<std::array<F, 4>, 3> rows{{{F(rb[0]), F(rb[1]), F(rb[2]), F(rb[3])},
                                                 {X[0], X[1], X[2], -X[3]},
                                                 {number(level[0]), number(level[1]), number(level[2]), F(0)}}};
    std::array<F, 4> xi;
    for (int i = 0; i < 4; ++i) {
      std::array<int, 3> c3{};
      for (int j = 0, k = 0; j < 4; ++j)
        if (j != i) c3[k++] = j;
      const F minor = rows[0][c3[0]] * (rows[1][c3[1]] * rows[2][c3[2]] - rows[1][c3[2]] * rows[2][c3[1]]) -
                      rows[0][c3[1]] * (rows[1][c3[0]] * rows[2][c3[2]] - rows[1][c3[2]] * rows[2][c3[0]]) +
                      rows[0][c3[2]] * (rows[1][c3[0]] * rows[2][c3[1]] - rows[1][c3[1]] * rows[2][c3[0]]);
      xi[i] = i % 2 == 0 ? minor : -minor;
    }
    const auto sign = [](const F& v) { return sign_of_field_value(v); };
    const Sign along = sign(number(across[0]) * xi[0] + number(across[1]) * xi[1] + number(across[2]) * xi[2]);
    const Sign farther = sign(-(F(rc[0]) * xi[0] + F(rc[1]) * xi[1] + F(rc[2]) * xi[2] + F(rc[3]) * xi[3]));
    return along * farther;
  }
};

inline const Filtered_predicate<Classify_trisector_predicate> classify_trisector{};
inline const Filtered_predicate<Face_side_predicate> face_side{};
inline const Filtered_predicate<Order_around_edge_predicate> order_around_edge{};
inline const Filtered_predicate<Curve_point_conflict_predicate> curve_point_conflict{};
inline const Filtered_predicate<Compare_along_trisector_predicate> compare_along_trisector{};
inline const Filtered_predicate<Departure_sign_predicate> departure_sign{};
inline const Filtered_predicate<Sides_near_vertex_predicate> sides_near_vertex{};

}  // namespace apollonius
