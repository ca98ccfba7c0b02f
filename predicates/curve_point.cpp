#include "predicates/curve_point.h"

#include <stdexcept>

#include "predicates/rounding_guard.h"

namespace apollonius {
namespace {

// The line of L inside the cut, as X = base + s direction, and the quadratic A s^2 + 2 B s + C of
// <X, X> along it. Empty when the cut is parallel to L.
template <class NT>
struct Cut_line {
  Vector4<NT> base, direction;
  NT A, B, C;
};

template <class NT>
std::optional<Cut_line<NT>> cut_line(const Trisector_geometry<NT>& g, const Vector4<NT>& cut, const NT& offset) {
  const NT along1 = euclidean_product(cut, g.e1), along2 = euclidean_product(cut, g.e2);
  const NT rest = offset - euclidean_product(cut, g.point);
  Cut_line<NT> line;
  if (certain_sign(along2) != Sign::ZERO) {
    line.base = combination(NT(1), g.point, rest / along2, g.e2);
    line.direction = combination(NT(1), g.e1, -(along1 / along2), g.e2);
  } else if (certain_sign(along1) != Sign::ZERO) {
    line.base = combination(NT(1), g.point, rest / along1, g.e1);
    line.direction = g.e2;
  } else {
    return std::nullopt;
  }
  line.A = lorentz_product(line.direction, line.direction);
  line.B = lorentz_product(line.base, line.direction);
  line.C = lorentz_product(line.base, line.base);
  return line;
}

template <class NT>
Vector4<NT> to_vector(const Vector4<Rational>& x) {
  if constexpr (std::is_same_v<NT, Rational>) {
    return x;
  } else {
    Vector4<NT> y;
    for (int j = 0; j < 4; ++j) y[j] = Interval(CGAL::to_interval(x[j]));
    return y;
  }
}

}  // namespace

template <>
Field_point<Rational> Curve_point::coordinates<Rational>() const {
  const std::optional<Cut_line<Rational>> line = cut_line(trisector_->geometry<Rational>(), cut_, offset_);
  if (!line) throw std::logic_error("curve point of a cut parallel to its trisector's plane");
  const Cut_line<Rational>& l = *line;
  Field_point<Rational> p;
  Rational denominator, a_factor, b_factor;  // s = (a_factor + sigma sqrt d) / denominator
  if (certain_sign(l.A) != Sign::ZERO) {
    denominator = l.A;
    a_factor = -l.B;
    p.discriminant = root_ == Root::SINGLE ? Rational(0) : l.B * l.B - l.A * l.C;
  } else {
    denominator = Rational(2) * l.B;
    a_factor = -l.C;
    p.discriminant = 0;
  }
  const Rational sigma(static_cast<int>(root_));
  const bool flip = certain_sign(denominator) == Sign::NEGATIVE;
  for (int j = 0; j < 4; ++j) {
    Rational a = denominator * l.base[j] + a_factor * l.direction[j], b = sigma * l.direction[j];
    p.scaled[j] = flip ? Quadratic<Rational>{-a, -b} : Quadratic<Rational>{a, b};
  }
  p.denominator = flip ? -denominator : denominator;
  return p;
}

template <>
Field_point<Interval> Curve_point::coordinates<Interval>() const {
  const std::optional<Cut_line<Interval>> line =
      cut_line(trisector_->geometry<Interval>(), to_vector<Interval>(cut_), Interval(CGAL::to_interval(offset_)));
  if (!line) throw Uncertain_sign();
  const Cut_line<Interval>& l = *line;
  Interval s;
  if (certain_sign(l.A) != Sign::ZERO) {
    const Interval root = root_ == Root::SINGLE ? Interval(0) : CGAL::sqrt(l.B * l.B - l.A * l.C);
    s = (-l.B + Interval(static_cast<int>(root_)) * root) / l.A;
  } else {
    s = -l.C / (Interval(2) * l.B);
  }
  Field_point<Interval> p;
  for (int j = 0; j < 4; ++j) p.X[j] = l.base[j] + s * l.direction[j];
  return p;
}

std::vector<Curve_point> curve_points(const Trisector& trisector, const Vector4<Rational>& cut, const Rational& offset) {
  std::vector<Curve_point> points;
  const std::optional<Cut_line<Rational>> line = cut_line(trisector.geometry<Rational>(), cut, offset);
  if (!line) return points;
  const Sign a = certain_sign(line->A);
  if (a == Sign::ZERO) {
    if (certain_sign(line->B) != Sign::ZERO) points.emplace_back(trisector, cut, offset, Root::SINGLE);
    return points;
  }
  const Sign d = certain_sign(line->B * line->B - line->A * line->C);
  if (d == Sign::ZERO) points.emplace_back(trisector, cut, offset, Root::SINGLE);
  if (d == Sign::POSITIVE)
    for (const Root r : {Root::MINUS, Root::PLUS}) points.emplace_back(trisector, cut, offset, r);
  return points;
}

bool parallel_to_plane(const Trisector& trisector, const Vector4<Rational>& cut) {
  const Trisector_geometry<Rational>& g = trisector.geometry<Rational>();
  return certain_sign(euclidean_product(cut, g.e1)) == Sign::ZERO && certain_sign(euclidean_product(cut, g.e2)) == Sign::ZERO;
}

bool on_sheet(const Curve_point& p) {
  {
    Rounding_guard guard;
    try {
      return certain_sign(p.coordinates<Interval>().X[3]) == Sign::POSITIVE;
    } catch (const Uncertain_sign&) {
    }
  }
  const Field_point<Rational> x = p.coordinates<Rational>();
  return sign_of_root_number(x.scaled[3].a, x.scaled[3].b, x.discriminant) == Sign::POSITIVE;
}

}  // namespace apollonius
