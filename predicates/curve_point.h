// A point of a trisector that is no vertex: where the trisector's plane L meets the hyperplane
// cut . X = offset (Euclidean product, rational cut and offset) on the cone. Like a vertex it lies in
// Q(sqrt d), d the discriminant of the quadratic that the cut leaves, and it is held symbolically: the
// predicates on trisectors take it as they take a vertex (field_point). Used for witness points of
// vertex-free curves and for the crossings that group a face's boundaries.
#pragma once

#include <optional>

#include "predicates/trisector.h"

namespace apollonius {

class Curve_point {
 public:
  // Precondition: `root` names an existing root of the cut (curve_points).
  Curve_point(const Trisector& trisector, const Vector4<Rational>& cut, const Rational& offset, Root root);

  const Trisector& trisector() const { return *trisector_; }
  Root root() const { return root_; }

  template <class NT>
  Field_point<NT> coordinates() const;

 private:
  // With its interval coordinates already known (curve_points).
  Curve_point(const Trisector& trisector, const Vector4<Rational>& cut, const Rational& offset, Root root,
              std::optional<Field_point<Interval>> enclosure);
  friend std::vector<Curve_point> curve_points(const Trisector&, const Vector4<Rational>&, const Rational&);

  const Trisector* trisector_;
  Vector4<Rational> cut_;
  Rational offset_;
  Root root_;
  // The interval coordinates, computed with the point: every use of a point asks for them first, and
  // converting the rational cut to intervals on each request was most of their cost. Empty: intervals
  // could not construct the point (coordinates<Interval> throws Uncertain_sign).
  std::optional<Field_point<Interval>> enclosure_;
  // The exact coordinates, computed on first use, by any thread (computed_once.h).
  Computed_once<Field_point<Rational>> exact_;
};

// The points where the cut meets the cone within L (on either sheet, valid or not): none, one (SINGLE),
// or MINUS and PLUS. Exact. Nothing when the cut contains all of L or misses it.
std::vector<Curve_point> curve_points(const Trisector& trisector, const Vector4<Rational>& cut, const Rational& offset);

// An interval enclosure, in the trisector's frame, of the point that arc_witness(t, nothing, nothing)
// gives, for the filters of the vertex-free curves; nothing when intervals cannot decide which root it is.
// Precondition: a Rounding_guard; the trisector is an ellipse, hyperbola or parabola.
std::optional<Vector4<Interval>> enclosed_canonical_point(const Trisector& t);

// The same in Wide_interval or Mpfr_interval (Trisector::framed_geometry), where the intervals did not
// decide: X relative to the trisector's site `origin` (X_origin = X_a + 2 (p_a - p_origin, w_origin - w_a)).
template <class NT>
struct Framed_curve_point {
  Vector4<NT> X;
  int origin;
};
template <class NT>
std::optional<Framed_curve_point<NT>> framed_enclosed_canonical_point(const Trisector& t);

// Whether the point is on the sheet X_3 > 0 (a point of the trisector, not of the other branch).
bool on_sheet(const Curve_point& p);

// Whether the hyperplane cut . X = offset contains the trisector's plane L or misses it for every offset
// but one (the cut's normal is orthogonal to L's directions). Exact.
bool parallel_to_plane(const Trisector& trisector, const Vector4<Rational>& cut);

// Whether cut . X tends to a finite limit along an end of the trisector, a hyperbola: an asymptote of the
// branch is parallel to the hyperplanes cut . X = offset, so those on one side of the limit miss that end.
// In trisector.h's basis, X = C + s e1 + t e2 with gamma1 s^2 + gamma2 t^2 = K tends to the asymptotes
// t = +-sqrt(-gamma1 / gamma2) s, along which cut . X - cut . C = (a + b t / s) s, a = cut . e1, b = cut . e2,
// stays bounded iff a^2 gamma2 + b^2 gamma1 = 0. Exact.
bool level_asymptote(const Trisector& trisector, const Vector4<Rational>& cut);

// The coordinates of a point of the trisector t (a vertex on it, or a curve point of it) in t's frame.
template <class NT>
Field_point<NT> field_point_on(const Trisector& t, const Vertex& v) {
  return field_point<NT>(v, t.origin());
}
template <class NT>
Field_point<NT> field_point_on(const Trisector&, const Curve_point& p) {
  return p.coordinates<NT>();
}

}  // namespace apollonius
