#include "predicates/arc_witness.h"

#include <stdexcept>

#include "predicates/rational_between.h"

namespace apollonius {
namespace {

Field_point<Rational> exact_point_of(const Trisector& t, const Arc_end& end) {
  if (const auto* v = std::get_if<const Vertex*>(&end)) return field_point_on<Rational>(t, **v);
  return std::get<const Curve_point*>(end)->coordinates<Rational>();
}

// <X, y> as the Euclidean cut (J y) . X.
Vector4<Rational> lorentz_cut(const Vector4<Rational>& y) { return {y[0], y[1], y[2], -y[3]}; }

Root_number<Rational> plus(const Root_number<Rational>& x, int k) {
  return {x.a + Rational(k) * x.denominator, x.b, x.d, x.denominator};
}

// The curve point on the sheet where <X, y> = value, among those the cut gives, that satisfies `keep`.
template <class Keep>
Curve_point point_where(const Trisector& t, const Vector4<Rational>& y, const Rational& value, Keep keep) {
  for (const Curve_point& p : curve_points(t, lorentz_cut(y), value))
    if (on_sheet(p) && keep(p.coordinates<Rational>())) return p;
  throw std::logic_error("arc_witness: the cut misses the arc");
}

// The ellipse's order key (trisector_predicates.h): the half, and the value that increases within it.
struct Ellipse_key {
  int half;
  Root_number<Rational> value;
};

Ellipse_key key_of(const Trisector_geometry<Rational>& g, const Field_point<Rational>& p) {
  const Root_number<Rational> s = lorentz_value(p, g.e1), t = lorentz_value(p, g.e2);
  const Sign ts = sign_of_number(t);
  const int half = ts == Sign::POSITIVE || (ts == Sign::ZERO && sign_of_number(s) == Sign::POSITIVE) ? 0 : 1;
  return {half, half == 0 ? Root_number<Rational>{-s.a, -s.b, s.d, s.denominator} : s};
}

}  // namespace

Curve_point arc_witness(const Trisector& t, std::optional<Arc_end> from, std::optional<Arc_end> to) {
  const Trisector_geometry<Rational>& g = t.geometry<Rational>();
  const auto any = [](const Field_point<Rational>&) { return true; };
  if (g.kind == Trisector_kind::hyperbola || g.kind == Trisector_kind::parabola) {
    std::optional<Root_number<Rational>> low, high;
    if (from) low = lorentz_value(exact_point_of(t, *from), g.monotone);
    if (to) high = lorentz_value(exact_point_of(t, *to), g.monotone);
    const Rational value = low && high ? rational_between(*low, *high)
                           : low       ? rational_between(*low, plus(*low, 1))
                           : high      ? rational_between(plus(*high, -1), *high)
                                       : Rational(0);
    return point_where(t, g.monotone, value, any);
  }
  if (g.kind != Trisector_kind::ellipse) throw std::logic_error("arc_witness: the trisector is no curve");

  // The axis points: theta = 0 (<X, e1> > 0, first in half 0) and theta = pi (first in half 1).
  const auto axis_point = [&](int half) {
    return point_where(t, g.e2, Rational(0), [&, half](const Field_point<Rational>& p) {
      return sign_of_number(lorentz_value(p, g.e1)) == (half == 0 ? Sign::POSITIVE : Sign::NEGATIVE);
    });
  };
  if (!from || !to) return axis_point(0);
  const Ellipse_key a = key_of(g, exact_point_of(t, *from)), b = key_of(g, exact_point_of(t, *to));
  // A point of a's half whose key value is `value`: <X, e1> = -value in half 0, value in half 1.
  const auto in_half = [&](int half, const Rational& value) {
    return point_where(t, g.e1, half == 0 ? Rational(-value) : value, [&, half](const Field_point<Rational>& p) {
      return key_of(g, p).half == half;
    });
  };
  if (a.half == b.half && compare(a.value, b.value) == Sign::NEGATIVE) return in_half(a.half, rational_between(a.value, b.value));
  // The arc passes the axis point that starts the next half, unless it ends there.
  const int next = 1 - a.half;
  const Ellipse_key axis = key_of(g, axis_point(next).coordinates<Rational>());
  if (b.half != next || compare(b.value, axis.value) != Sign::ZERO) return axis_point(next);
  // It ends there: between a and the end of a's half, where the key value is that of the axis point
  // seen from a's half, sqrt(K gamma1) (the same absolute <X, e1>).
  const Root_number<Rational> end_of_half{-axis.value.a, -axis.value.b, axis.value.d, axis.value.denominator};
  if (compare(a.value, end_of_half) != Sign::NEGATIVE)
    return axis_point(a.half);  // a is the axis point itself and the arc is the whole curve but it
  return in_half(a.half, rational_between(a.value, end_of_half));
}

}  // namespace apollonius
