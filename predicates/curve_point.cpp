#include "predicates/curve_point.h"

#include <stdexcept>

#include "predicates/rounding_guard.h"

namespace apollonius {
namespace {

// The line of L inside the cut, as X = base + s direction, and the quadratic A s^2 + 2 B s + C of
// <X, X> along it. With X = point + u e1 + v e2 the cut reads alpha u + beta v = rho; the line is
// (u, v) = rho (alpha, beta) / (alpha^2 + beta^2) + s (-beta, alpha), one formula with no case, so that
// the filter and the exact stage name the roots alike. Empty when the cut is parallel to L.
template <class NT>
struct Cut_line {
  Vector4<NT> base, direction;
  NT A, B, C;
};

template <class NT>
std::optional<Cut_line<NT>> cut_line(const Trisector_geometry<NT>& g, const Vector4<NT>& cut, const NT& offset) {
  const NT alpha = euclidean_product(cut, g.e1), beta = euclidean_product(cut, g.e2);
  const NT norm = alpha * alpha + beta * beta;
  if (certain_sign(norm) == Sign::ZERO) return std::nullopt;
  const NT rho = (offset - euclidean_product(cut, g.point)) / norm;
  Cut_line<NT> line;
  line.base = combination(NT(1), g.point, NT(1), combination(rho * alpha, g.e1, rho * beta, g.e2));
  line.direction = combination(-beta, g.e1, alpha, g.e2);
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

template <class NT>
NT to_number(const Rational& x) {
  if constexpr (std::is_same_v<NT, Rational>)
    return x;
  else
    return Interval(CGAL::to_interval(x));
}

}  // namespace

template <>
Field_point<Rational> Curve_point::coordinates<Rational>() const {
  return exact_.get_or_compute([&] {
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
  });
}

template <>
Field_point<Interval> Curve_point::coordinates<Interval>() const {
  if (!enclosure_) throw Uncertain_sign();
  return *enclosure_;
}

namespace {

// The cut's line in intervals (throws Uncertain_sign where they cannot tell).
std::optional<Cut_line<Interval>> interval_cut_line(const Trisector& trisector, const Vector4<Rational>& cut,
                                                    const Rational& offset) {
  return cut_line(trisector.geometry<Interval>(), to_vector<Interval>(cut), Interval(CGAL::to_interval(offset)));
}

// The point at `root` of the cut's line, in intervals; nothing where they cannot construct it.
std::optional<Field_point<Interval>> point_at_root(const std::optional<Cut_line<Interval>>& line, Root root) {
  if (!line) return std::nullopt;
  try {
    const Cut_line<Interval>& l = *line;
    Interval s;
    if (certain_sign(l.A) != Sign::ZERO) {
      const Interval root_of_discriminant = root == Root::SINGLE ? Interval(0) : CGAL::sqrt(l.B * l.B - l.A * l.C);
      s = (-l.B + Interval(static_cast<int>(root)) * root_of_discriminant) / l.A;
    } else {
      s = -l.C / (Interval(2) * l.B);
    }
    Field_point<Interval> p;
    for (int j = 0; j < 4; ++j) p.X[j] = l.base[j] + s * l.direction[j];
    return p;
  } catch (const Uncertain_sign&) {
    return std::nullopt;
  }
}

// Which roots the cut's line leaves: none, SINGLE, or MINUS and PLUS, in NT (Interval throws when unsure).
template <class NT>
std::vector<Root> roots_of_cut(const std::optional<Cut_line<NT>>& line) {
  if (!line) {
    if constexpr (std::is_same_v<NT, Interval>) throw Uncertain_sign();  // parallel only if exactly so
    return {};
  }
  if (certain_sign(line->A) == Sign::ZERO) {
    if (certain_sign(line->B) != Sign::ZERO) return {Root::SINGLE};
    return {};
  }
  const Sign d = certain_sign(line->B * line->B - line->A * line->C);
  if (d == Sign::ZERO) return {Root::SINGLE};
  if (d == Sign::POSITIVE) return {Root::MINUS, Root::PLUS};
  return {};
}

// The point's interval coordinates, on their own (curve_points has the line already).
std::optional<Field_point<Interval>> enclosure_of(const Trisector& trisector, const Vector4<Rational>& cut,
                                                  const Rational& offset, Root root) {
  Rounding_guard guard;
  try {
    return point_at_root(interval_cut_line(trisector, cut, offset), root);
  } catch (const Uncertain_sign&) {
    return std::nullopt;
  }
}

}  // namespace

Curve_point::Curve_point(const Trisector& trisector, const Vector4<Rational>& cut, const Rational& offset, Root root)
    : Curve_point(trisector, cut, offset, root, enclosure_of(trisector, cut, offset, root)) {}

Curve_point::Curve_point(const Trisector& trisector, const Vector4<Rational>& cut, const Rational& offset, Root root,
                         std::optional<Field_point<Interval>> enclosure)
    : trisector_(&trisector), cut_(cut), offset_(offset), root_(root), enclosure_(std::move(enclosure)) {}

std::vector<Curve_point> curve_points(const Trisector& trisector, const Vector4<Rational>& cut, const Rational& offset) {
  std::vector<Root> roots;
  std::optional<Cut_line<Interval>> line;  // converted once, for the roots and the points
  bool decided = false;
  {
    Rounding_guard guard;
    try {
      line = interval_cut_line(trisector, cut, offset);
      roots = roots_of_cut<Interval>(line);
      decided = true;
    } catch (const Uncertain_sign&) {
    }
  }
  if (!decided) roots = roots_of_cut<Rational>(cut_line(trisector.geometry<Rational>(), cut, offset));
  std::vector<Curve_point> points;
  Rounding_guard guard;
  for (const Root r : roots) points.push_back(Curve_point(trisector, cut, offset, r, point_at_root(line, r)));
  return points;
}

namespace {

// The canonical point's enclosure from a geometry in NT, Interval or Wide_interval, in that geometry's frame
// (the cut <X, y> = 0 by a direction y of L is the same set in every frame: trisector.h).
template <class NT>
std::optional<Vector4<NT>> canonical_point_enclosure(const Trisector_geometry<NT>& g) {
  using CGAL::sqrt;
  const bool closed = g.kind == Trisector_kind::ellipse;
  const Vector4<NT>& y = closed ? g.e2 : g.monotone;  // the cut <X, y> = 0 (arc_witness.cpp)
  const std::optional<Cut_line<NT>> line = cut_line(g, Vector4<NT>{y[0], y[1], y[2], -y[3]}, NT(0));
  if (!line) return std::nullopt;
  std::vector<Vector4<NT>> points;
  if (certain_sign(line->A) == Sign::ZERO) {
    const NT s = -line->C / (NT(2) * line->B);
    points.push_back(combination(NT(1), line->base, s, line->direction));
  } else {
    if (certain_sign(line->B * line->B - line->A * line->C) != Sign::POSITIVE) return std::nullopt;
    const NT root = sqrt(line->B * line->B - line->A * line->C);
    for (const int sigma : {-1, 1})
      points.push_back(combination(NT(1), line->base, (-line->B + NT(sigma) * root) / line->A, line->direction));
  }
  std::optional<Vector4<NT>> chosen;
  for (const Vector4<NT>& x : points) {
    if (certain_sign(x[3]) != Sign::POSITIVE) continue;  // the other branch
    if (closed && certain_sign(lorentz_product(x, g.e1)) != Sign::POSITIVE) continue;  // theta = pi
    if (chosen) return std::nullopt;
    chosen = x;
  }
  return chosen;
}

}  // namespace

std::optional<Vector4<Interval>> enclosed_canonical_point(const Trisector& t) {
  try {
    return canonical_point_enclosure(t.geometry<Interval>());
  } catch (const Uncertain_sign&) {
    return std::nullopt;
  }
}

template <class NT>
std::optional<Framed_curve_point<NT>> framed_enclosed_canonical_point(const Trisector& t) {
  try {
    const Framed_trisector_geometry<NT>& g = t.framed_geometry<NT>();
    Rounding_guard guard;  // Wide_interval's; Mpfr_interval rounds by itself
    if (const std::optional<Vector4<NT>> X = canonical_point_enclosure(g.geometry))
      return Framed_curve_point<NT>{*X, g.origin};
    return std::nullopt;
  } catch (const Uncertain_sign&) {
    return std::nullopt;
  }
}

template std::optional<Framed_curve_point<Wide_interval>> framed_enclosed_canonical_point(const Trisector&);
template std::optional<Framed_curve_point<Mpfr_interval>> framed_enclosed_canonical_point(const Trisector&);

bool parallel_to_plane(const Trisector& trisector, const Vector4<Rational>& cut) {
  {  // The interval e1, e2 enclose positive multiples of the exact ones (trisector.h): a certainly nonzero
     // product decides.
    Rounding_guard guard;
    try {
      const Trisector_geometry<Interval>& g = trisector.geometry<Interval>();
      const Vector4<Interval> c = to_vector<Interval>(cut);
      if (certain_sign(euclidean_product(c, g.e1)) != Sign::ZERO || certain_sign(euclidean_product(c, g.e2)) != Sign::ZERO)
        return false;
    } catch (const Uncertain_sign&) {
    }
  }
  const Trisector_geometry<Rational>& g = trisector.geometry<Rational>();
  return certain_sign(euclidean_product(cut, g.e1)) == Sign::ZERO && certain_sign(euclidean_product(cut, g.e2)) == Sign::ZERO;
}

bool level_asymptote(const Trisector& trisector, const Vector4<Rational>& cut) {
  const auto value = [&](const auto& g, const auto& c) {
    const auto a = euclidean_product(c, g.e1), b = euclidean_product(c, g.e2);
    return a * a * g.gamma2 + b * b * g.gamma1;
  };
  {
    Rounding_guard guard;
    try {
      const Trisector_geometry<Interval>& g = trisector.geometry<Interval>();
      if (g.kind != Trisector_kind::hyperbola) return false;
      if (certain_sign(value(g, to_vector<Interval>(cut))) != Sign::ZERO) return false;
    } catch (const Uncertain_sign&) {
    }
  }
  const Trisector_geometry<Rational>& g = trisector.geometry<Rational>();
  return g.kind == Trisector_kind::hyperbola && certain_sign(value(g, cut)) == Sign::ZERO;
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
