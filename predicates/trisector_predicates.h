// The predicates of the diagram's edges (paper section 5.3), each one formula on a trisector and the
// vertices on it (trisector.h), filtered in intervals and exact in Q(sqrt d):
//  - classify_trisector(T): the kind and shape of the curve;
//  - compare_along_trisector(T, u, v): the order of two of its vertices, forward along the curve;
//  - departure_sign(T, v, s): whether site s gets farther (POSITIVE) or nearer going forward from v;
//  - sides_near_vertex(T, v, s): the sign of d_s - r just after v and just before it, to second order.
#pragma once

#include <utility>

#include "predicates/compare_vertices.h"
#include "predicates/filtered_predicate.h"
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
};

// Forward is counterclockwise in (e1, e2) on a closed curve, increasing <X, monotone> on an open one.
// On the ellipse gamma1 s^2 + gamma2 t^2 = K (gamma_i > 0) a point's angle from +e1 orders it: the half
// t > 0 (with the point t = 0, s > 0) comes first, and s = <X, e1> / gamma1 falls in it and rises in the
// other (trisector.h: <centre, e_i> = 0, so <X, e_i> = gamma_i times the coordinate).
struct Compare_along_trisector_predicate {
  static constexpr const char* name = "compare_along_trisector";
  using Exact_number = Rational;

  template <class NT>
  static Sign evaluate(const Trisector& t, const Vertex& u, const Vertex& v) {
    const Trisector_geometry<NT>& g = t.geometry<NT>();
    const Field_point<NT> p = field_point<NT>(u, t.origin()), q = field_point<NT>(v, t.origin());
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

  template <class NT>
  static Sign evaluate(const Trisector& t, const Vertex& v, const Site& s) {
    const Trisector_geometry<NT>& g = t.geometry<NT>();
    const Field_point<NT> p = field_point<NT>(v, t.origin());
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

  template <class NT>
  static std::pair<Sign, Sign> evaluate(const Trisector& t, const Vertex& v, const Site& s) {
    const Sign first = Departure_sign_predicate::evaluate<NT>(t, v, s);
    if (first != Sign::ZERO) return {first, -first};
    const Trisector_geometry<NT>& g = t.geometry<NT>();
    const Field_point<NT> p = field_point<NT>(v, t.origin());
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

inline const Filtered_predicate<Classify_trisector_predicate> classify_trisector{};
inline const Filtered_predicate<Compare_along_trisector_predicate> compare_along_trisector{};
inline const Filtered_predicate<Departure_sign_predicate> departure_sign{};
inline const Filtered_predicate<Sides_near_vertex_predicate> sides_near_vertex{};

}  // namespace apollonius
