// The trisector of three sites a < b < c: the points equidistant from them with a valid r, a planar conic
// of R^3 (paper Theorem 5; docs/design.md, "Trisectors"). In the coordinates X = 2 (v - p_a, r + w_a) of
// quadruple_line.h it is the plane
//     L = {X : R_m . X = h_m, m = b, c},  R_m = (p_m - p_a, w_m - w_a),  h_m = |p_m - p_a|^2 - (w_m - w_a)^2
// (Euclidean products) cut by the cone <X, X> = 0 (<,> the Lorentz product of quadruple_line.h) on the
// sheet X_3 > 0. For pairwise non-hidden sites r + w_m > 0 holds on that whole sheet, and L misses the
// apex, so the curve is one conic with no singular point:
//  - L's directions carry a restriction of <,> that is definite (an ellipse; a circle in R^3 when the
//    centres are collinear), indefinite (a hyperbola, one branch on the sheet; a line in R^3 when the
//    three weights are equal) or of rank 1 (a parabola);
//  - in a basis (e1, e2) of L's directions orthogonal for <,>, with centre C (<C, e1> = <C, e2> = 0), the
//    conic is gamma1 s^2 + gamma2 t^2 = K for X = C + s e1 + t e2, gamma_i = <e_i, e_i>, K = -<C, C>.
// Everything here is a rational function of the input doubles: NT is Interval (the filter), Wide_interval
// (for sites whose products leave the double range: wide_interval.h), Mpfr_interval (for signs a hair
// from zero: mpfr_interval.h) or Rational.
#pragma once

#include <array>
#include <optional>
#include <type_traits>

#include "predicates/computed_once.h"
#include "predicates/quadratic.h"
#include "predicates/quadruple_line.h"
#include "predicates/rational.h"
#include "predicates/root_sign.h"
#include "predicates/site.h"
#include "predicates/vertex.h"
#include "predicates/mpfr_interval.h"
#include "predicates/wide_interval.h"

namespace apollonius {

enum class Trisector_kind : signed char {
  empty,      // no point with a valid r (an ellipse on the other sheet, or no real point; or rank < 2)
  point,      // a single point: three balls with one common tangent sphere, an isolated tie
  ellipse,    // closed
  hyperbola,  // open, one branch
  parabola    // open
};

// What the curve looks like in R^3, for output.
enum class Curve_shape : signed char { none, point, ellipse, hyperbola, parabola, line, circle };
const char* to_string(Curve_shape shape);

// A filter's e1, e2 and monotone are the exact ones up to a positive factor each (trisector.cpp), which no
// predicate sees: each is a sign, homogeneous in each of them.
// Invariants: for ellipse and hyperbola, <e1, e2> = 0, gamma_i = <e_i, e_i> != 0, <centre, e_i> = 0,
// K = -<centre, centre>. For parabola, <e1, y> = 0 for every direction y of L (e1 is the axis) and
// gamma2 = <e2, e2> != 0. `monotone` orders open curves: <X, monotone> is strictly increasing along
// the branch in the direction called forward; closed curves go forward counterclockwise in (e1, e2).
template <class NT>
struct Trisector_geometry {
  Trisector_kind kind = Trisector_kind::empty;
  Curve_shape shape = Curve_shape::none;
  std::array<Vector4<NT>, 2> rows;  // R_b, R_c
  std::array<NT, 2> heights;        // h_b, h_c
  Vector4<NT> point;                // a point of L
  Vector4<NT> e1, e2, centre, monotone;
  NT gamma1, gamma2, K;
  // Hyperbola: the branch on the sheet has this sign of s (branch_axis 1) or of t (branch_axis 2).
  int branch_axis = 0;
  Sign branch_sign = Sign::ZERO;
};

template <class NT>
NT euclidean_product(const Vector4<NT>& x, const Vector4<NT>& y) {
  return x[0] * y[0] + x[1] * y[1] + x[2] * y[2] + x[3] * y[3];
}

template <class NT>
Vector4<NT> combination(const NT& s, const Vector4<NT>& x, const NT& t, const Vector4<NT>& y) {
  return {s * x[0] + t * y[0], s * x[1] + t * y[1], s * x[2] + t * y[2], s * x[3] + t * y[3]};
}

// The geometry of the trisector of the sites (a, b, c), in NT; signs that NT cannot decide throw
// Uncertain_sign. The sites must be pairwise non-hidden.
template <class NT>
Trisector_geometry<NT> trisector_geometry(const std::array<Site, 3>& sites);


// A point of a vertex's field Q(sqrt d) in the coordinates X = 2 (v - p_a, r + w_a) of a trisector: an
// Interval vector for the filter, exact over a common positive denominator for the exact stage.
template <class NT>
struct Field_point {
  Vector4<NT> X;
};
template <>
struct Field_point<Rational> {
  std::array<Quadratic<Rational>, 4> scaled;
  Rational denominator;  // > 0
  Rational discriminant;
};

// A number of that field: an Interval, or a Root_number.
template <class NT>
using Field_number = std::conditional_t<std::is_same_v<NT, Rational>, Root_number<Rational>, NT>;

inline Sign sign_of_number(const Interval& x) { return certain_sign(x); }
inline Sign sign_of_number(const Root_number<Rational>& x) { return sign_of_root_number(x.a, x.b, x.d); }
inline Sign compare_numbers(const Root_number<Rational>& x, const Root_number<Rational>& y) { return compare(x, y); }

// <X, y> (Lorentz) and R . X + c (Euclidean, affine) at a field point.
inline Interval lorentz_value(const Field_point<Interval>& p, const Vector4<Interval>& y) { return lorentz_product(p.X, y); }
Root_number<Rational> lorentz_value(const Field_point<Rational>& p, const Vector4<Rational>& y);
inline Interval euclidean_value(const Field_point<Interval>& p, const Vector4<Interval>& y, const Interval& c) {
  return euclidean_product(p.X, y) + c;
}
Root_number<Rational> euclidean_value(const Field_point<Rational>& p, const Vector4<Rational>& y, const Rational& c);


// The geometry in a later filter's number type (Wide_interval, Mpfr_interval), relative to sites[origin], the
// first site of the closest pair: two sites a hair apart beside a far one (a deep input) give rows from the
// far one that are equal to within the hair, and rows of their own sizes from one of the two. Frames differ
// by a translation s with <s, y> = 0 for every direction y of L (on L the sites' cones agree), and the basis
// depends only on L's directions and the pivot, whose minors scale by one nonzero factor: so kind, shape,
// gamma signs and K are those of every frame, e1, e2 and monotone those of every frame up to a positive
// factor each (trisector.cpp: a filter may take its basis from a larger minor), and a cut <X, y> = 0 by such
// a y is the same set in every frame. Only point, centre, rows and heights are relative to the origin
// (X_origin = X_a + 2 (p_a - p_origin, w_origin - w_a)).
template <class NT>
struct Framed_trisector_geometry {
  Trisector_geometry<NT> geometry;
  int origin = 0;  // 0, 1 or 2
};

// The trisector as the diagram uses it: its sites and its geometry, computed once in intervals when they
// decide and exactly on first use, like Vertex.
class Trisector {
 public:
  Trisector(const std::array<Site_index, 3>& indices, const std::array<Site, 3>& sites);

  const std::array<Site_index, 3>& indices() const { return indices_; }
  const std::array<Site, 3>& sites() const { return sites_; }
  const Site& origin() const { return sites_[0]; }

  // Throws Uncertain_sign for Interval when the interval geometry could not decide.
  template <class NT>
  const Trisector_geometry<NT>& geometry() const;

  // The geometry in Wide_interval or Mpfr_interval (Framed_trisector_geometry), for the filters where the
  // intervals could not decide; computed on first use; throws Uncertain_sign when it does not decide either.
  template <class NT>
  const Framed_trisector_geometry<NT>& framed_geometry() const;

 private:
  std::array<Site_index, 3> indices_;
  std::array<Site, 3> sites_;
  std::optional<Trisector_geometry<Interval>> interval_;                  // empty: undecided in intervals
  Computed_once<std::optional<Framed_trisector_geometry<Wide_interval>>> wide_;     // empty: undecided
  Computed_once<std::optional<Framed_trisector_geometry<Mpfr_interval>>> precise_;  // empty: undecided
  Computed_once<Trisector_geometry<Rational>> rational_;                 // computed on first use, by any thread
};

template <>
const Trisector_geometry<Interval>& Trisector::geometry<Interval>() const;
template <>
const Trisector_geometry<Rational>& Trisector::geometry<Rational>() const;
template <>
const Framed_trisector_geometry<Wide_interval>& Trisector::framed_geometry<Wide_interval>() const;
template <>
const Framed_trisector_geometry<Mpfr_interval>& Trisector::framed_geometry<Mpfr_interval>() const;

// The vertex in the trisector's coordinates X = 2 (v - p_a, r + w_a): X_o + 2 (p_o - p_a, w_a - w_o) for
// the vertex's own origin o.
template <class NT>
Field_point<NT> field_point(const Vertex& v, const Site& a);

}  // namespace apollonius
