#include "predicates/trisector.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <type_traits>

#include "predicates/rounding_guard.h"
#include "predicates/trisector_rows.h"

namespace apollonius {
namespace {

template <class NT>
Sign sign_of(const NT& x) {
  return certain_sign(x);
}

template <class NT>
Vector4<NT> minus(const Vector4<NT>& x, const Vector4<NT>& y) {
  return {x[0] - y[0], x[1] - y[1], x[2] - y[2], x[3] - y[3]};
}

template <class NT>
Vector4<NT> scaled(const NT& s, const Vector4<NT>& x) {
  return {s * x[0], s * x[1], s * x[2], s * x[3]};
}

// The exact signs that the filters' geometries fall back on (sign_or): division-free polynomials of the input
// in Exact, so that a filter decides the exact ties of a lattice (a parabola, a point, collinear centres, a
// vanishing minor) without the Rational geometry, whose gcds cost about half a millisecond.
class Exact_signs {
 public:
  explicit Exact_signs(const std::array<Site, 3>& sites)
      : sites_(sites), b_(relative_site<Exact>(sites[0], sites[1])), c_(relative_site<Exact>(sites[0], sites[2])) {}

  Sign minor(int i, int j) const { return certain_sign(b_.row[i] * c_.row[j] - b_.row[j] * c_.row[i]); }

  // The sign of g11 g22 - g12^2, the Lorentz form on L's directions: minus that of the rows' Gram
  // determinant (trisector_rows.h).
  Sign determinant() const {
    return -certain_sign(rows_gram_determinant(b_.rhs, c_.rhs, power_gap<Exact>(sites_[1], sites_[2])));
  }

  // The sign of K where g11 g22 - g12^2 != 0, with trisector_geometry's vectors scaled by nonzero factors of
  // known sign: f~_t = m f_t and P~ = m P (m the pivot minor); e~_i = s_i e_i, s_i = m or m^3;
  // gamma~_i = s_i^2 gamma_i. Then, as <C, e_i> = 0,
  //     K gamma1 gamma2 (m s1 s2)^2 = -<P~, P~> gamma~1 gamma~2 + <P~, e~1>^2 gamma~2 + <P~, e~2>^2 gamma~1.
  Sign conic_constant() const {
    const Vector4<Exact>&rb = b_.row, &rc = c_.row;
    int pivot_i = -1, pivot_j = -1;
    Exact m(0);
    for (int i = 0; i < 4 && pivot_i < 0; ++i)
      for (int j = i + 1; j < 4 && pivot_i < 0; ++j)
        if (minor(i, j) != Sign::ZERO) pivot_i = i, pivot_j = j, m = rb[i] * rc[j] - rb[j] * rc[i];
    std::array<int, 2> free{};
    for (int k = 0, t = 0; k < 4; ++k)
      if (k != pivot_i && k != pivot_j) free[t++] = k;
    const auto solve = [&](const Exact& right_b, const Exact& right_c, Vector4<Exact>& x) {  // Cramer, times m
      x[pivot_i] = right_b * rc[pivot_j] - right_c * rb[pivot_j];
      x[pivot_j] = rb[pivot_i] * right_c - rc[pivot_i] * right_b;
    };
    std::array<Vector4<Exact>, 2> f;
    for (int t = 0; t < 2; ++t) {
      f[t] = {Exact(0), Exact(0), Exact(0), Exact(0)};
      f[t][free[t]] = m;
      solve(-rb[free[t]], -rc[free[t]], f[t]);
    }
    Vector4<Exact> point{Exact(0), Exact(0), Exact(0), Exact(0)};
    solve(b_.rhs, c_.rhs, point);
    const Exact g11 = lorentz_product(f[0], f[0]), g12 = lorentz_product(f[0], f[1]), g22 = lorentz_product(f[1], f[1]);
    Vector4<Exact> e1, e2;
    if (certain_sign(g11) != Sign::ZERO) {
      e1 = f[0];
      e2 = combination(g11, f[1], -g12, f[0]);
    } else if (certain_sign(g22) != Sign::ZERO) {
      e1 = f[1];
      e2 = combination(g22, f[0], -g12, f[1]);
    } else {
      e1 = combination(Exact(1), f[0], Exact(1), f[1]);
      e2 = combination(Exact(1), f[0], Exact(-1), f[1]);
    }
    const Exact gamma1 = lorentz_product(e1, e1), gamma2 = lorentz_product(e2, e2);
    const Exact p1 = lorentz_product(point, e1), p2 = lorentz_product(point, e2);
    return certain_sign(gamma1) * certain_sign(gamma2) *
           certain_sign(p1 * p1 * gamma2 + p2 * p2 * gamma1 - lorentz_product(point, point) * gamma1 * gamma2);
  }

  // The components of (p_b - p_a) x (p_c - p_a): minors of the rows' first three columns.
  Sign cross(int k) const { return minor((k + 1) % 3, (k + 2) % 3); }

 private:
  const std::array<Site, 3>& sites_;
  Relative_site<Exact> b_, c_;
};

// The sign of x, or, where the filter type NT cannot tell, exact_sign() (Exact_signs).
template <class NT, class Exact_sign>
Sign sign_or(const NT& x, Exact_sign exact_sign) {
  if constexpr (std::is_same_v<NT, Rational>) {
    return certain_sign(x);
  } else {
    if (const std::optional<Sign> s = sign_if_certain(x)) return *s;
    return exact_sign();
  }
}

// The sign of the permutation (i, j, k, l) of (0, 1, 2, 3), for i < j and k < l.
Sign permutation_sign(int i, int j, int k, int l) {
  const std::array<int, 4> p{i, j, k, l};
  int inversions = 0;
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b) inversions += p[a] > p[b];
  return inversions % 2 == 0 ? Sign::POSITIVE : Sign::NEGATIVE;
}

// The pair of columns whose 2x2 minor of the rows is largest, where the first nonzero one (i, j) is below
// 2^-26 of it; nothing otherwise. In rounded doubles of the rows from the sites in lexicographic order: a
// choice of formula, never a sign, and the same for every number type and every frame (the minors of two
// frames differ by one factor), so that all build the same basis.
std::optional<std::pair<int, int>> larger_pivot(const std::array<Site, 3>& sites, int i, int j) {
  std::array<Site, 3> s = sites;
  const auto key = [](const Site& x) { return std::array<double, 4>{x.x, x.y, x.z, x.w}; };
  std::sort(s.begin(), s.end(), [&](const Site& x, const Site& y) { return key(x) < key(y); });
  std::array<std::array<double, 4>, 2> r;
  for (int m = 0; m < 2; ++m) r[m] = {s[m + 1].x - s[0].x, s[m + 1].y - s[0].y, s[m + 1].z - s[0].z, s[m + 1].w - s[0].w};
  const auto minor = [&](int p, int q) { return std::fabs(r[0][p] * r[1][q] - r[0][q] * r[1][p]); };
  std::pair<int, int> largest{i, j};
  double largest_minor = minor(i, j);
  for (int p = 0; p < 4; ++p)
    for (int q = p + 1; q < 4; ++q)
      if (minor(p, q) > largest_minor) largest = {p, q}, largest_minor = minor(p, q);
  if (!std::isfinite(largest_minor) || !(minor(i, j) < 0x1p-26 * largest_minor)) return std::nullopt;
  return largest;
}

}  // namespace

const char* to_string(Curve_shape shape) {
  switch (shape) {
    case Curve_shape::none: return "none";
    case Curve_shape::point: return "point";
    case Curve_shape::ellipse: return "ellipse";
    case Curve_shape::hyperbola: return "hyperbola";
    case Curve_shape::parabola: return "parabola";
    case Curve_shape::line: return "line";
    case Curve_shape::circle: return "circle";
  }
  return "none";
}

template <class NT>
Trisector_geometry<NT> trisector_geometry(const std::array<Site, 3>& sites) {
  Trisector_geometry<NT> g;
  for (int m = 0; m < 2; ++m) {
    const Relative_site<NT> r = relative_site<NT>(sites[0], sites[m + 1]);
    g.rows[m] = r.row;
    g.heights[m] = r.rhs;
  }
  const Vector4<NT>&rb = g.rows[0], &rc = g.rows[1];

  // The first pair of columns (i, j) whose 2x2 minor is not 0, in a fixed order, so that the filter and the
  // exact stage build the same basis up to positive factors (and so the same forward direction); rank < 2
  // means no point at all (two of the sites would coincide, and they are distinct).
  // A filter's uncertain signs are decided exactly (Exact_signs), computed once on first need.
  std::optional<Exact_signs> exact;
  const auto exact_signs = [&]() -> const Exact_signs& {
    if (!exact) exact.emplace(sites);
    return *exact;
  };
  int pivot_i = -1, pivot_j = -1;
  Sign pivot_sign = Sign::ZERO;
  for (int i = 0; i < 4 && pivot_i < 0; ++i)
    for (int j = i + 1; j < 4 && pivot_i < 0; ++j) {
      const NT m = rb[i] * rc[j] - rb[j] * rc[i];
      pivot_sign = sign_or(m, [&] { return exact_signs().minor(i, j); });
      if (pivot_sign != Sign::ZERO) pivot_i = i, pivot_j = j;
    }
  if (pivot_i < 0) return g;  // empty
  const auto free_columns = [](int i, int j) {
    std::array<int, 2> free{};
    for (int k = 0, t = 0; k < 4; ++k)
      if (k != i && k != j) free[t++] = k;
    return free;
  };
  const std::array<int, 2> free = free_columns(pivot_i, pivot_j);

  // Cramer on the columns (i, j), minor m: the direction f_k has f_k[k] = 1 and 0 in the other free column;
  // the point has 0 in both free columns.
  const auto solve = [&](int i, int j, const NT& m, const NT& right_b, const NT& right_c, Vector4<NT>& x) {
    x[i] = (right_b * rc[j] - right_c * rb[j]) / m;
    x[j] = (rb[i] * right_c - rc[i] * right_b) / m;
  };
  const auto directions = [&](int i, int j, const NT& m) {
    const std::array<int, 2> columns = free_columns(i, j);
    std::array<Vector4<NT>, 2> d;
    for (int t = 0; t < 2; ++t) {
      d[t] = {NT(0), NT(0), NT(0), NT(0)};
      d[t][columns[t]] = NT(1);
      solve(i, j, m, -rb[columns[t]], -rc[columns[t]], d[t]);
    }
    return d;
  };
  // The exact basis is the pivot's f_0, f_1. Where the pivot's minor is tiny beside another (sites 5e-324
  // off a lattice plane beside sites at 4), f_t has entries near 1e324 and the Gram-Schmidt step below
  // cancels them in every filter. There the filters take c f_t instead, one factor c > 0 for both, from the
  // basis f'_t of the larger minor's columns (i', j'): with (k, l) = free, f_0 = (f'_1[l] f'_0 - f'_0[l] f'_1)
  // / det and f_1 = (f'_0[k] f'_1 - f'_1[k] f'_0) / det, det = f'_0[k] f'_1[l] - f'_0[l] f'_1[k], and by the
  // duality of L's directions and the rows' Plucker coordinates det = e e' m / m', e and e' the signs of the
  // permutations (i, j, k, l) and (i', j', k', l'). Then e1, e2 and monotone are positive multiples of the
  // exact ones, and gamma1, gamma2 positive multiples too: every predicate on them is a sign, homogeneous in
  // each (trisector_predicates.h, curve_point.h), and centre and K do not change.
  std::array<Vector4<NT>, 2> f;
  std::optional<std::pair<int, int>> larger;
  if constexpr (!std::is_same_v<NT, Rational>) larger = larger_pivot(sites, pivot_i, pivot_j);
  NT larger_minor(0);
  Sign larger_sign = Sign::ZERO;
  if (larger) {
    const auto [i, j] = *larger;
    larger_minor = rb[i] * rc[j] - rb[j] * rc[i];
    larger_sign = sign_or(larger_minor, [&, i = i, j = j] { return exact_signs().minor(i, j); });
  }
  g.point = {NT(0), NT(0), NT(0), NT(0)};
  if (larger_sign == Sign::ZERO) {
    const NT minor = rb[pivot_i] * rc[pivot_j] - rb[pivot_j] * rc[pivot_i];
    f = directions(pivot_i, pivot_j, minor);
    solve(pivot_i, pivot_j, minor, g.heights[0], g.heights[1], g.point);
  } else {
    // With d_t = m' f'_t (Cramer without the division), the same combinations give m'^2 |det| f_t.
    const auto [i, j] = *larger;
    const std::array<int, 2> larger_free = free_columns(i, j);
    std::array<Vector4<NT>, 2> d;
    for (int t = 0; t < 2; ++t) {
      const int c = larger_free[t];
      d[t] = {NT(0), NT(0), NT(0), NT(0)};
      d[t][c] = larger_minor;
      d[t][i] = rc[c] * rb[j] - rb[c] * rc[j];
      d[t][j] = rc[i] * rb[c] - rb[i] * rc[c];
    }
    const int k = free[0], l = free[1];
    const Sign det_sign = permutation_sign(pivot_i, pivot_j, k, l) *
                          permutation_sign(i, j, larger_free[0], larger_free[1]) * pivot_sign * larger_sign;
    const NT sigma(det_sign == Sign::POSITIVE ? 1 : -1);
    f[0] = combination(sigma * d[1][l], d[0], -sigma * d[0][l], d[1]);
    f[1] = combination(sigma * d[0][k], d[1], -sigma * d[1][k], d[0]);
    f[0][k] = f[1][l] = sigma * (d[0][k] * d[1][l] - d[0][l] * d[1][k]);  // m'^2 |det|
    f[0][l] = f[1][k] = NT(0);
    solve(i, j, larger_minor, g.heights[0], g.heights[1], g.point);
  }

  const NT g11 = lorentz_product(f[0], f[0]), g12 = lorentz_product(f[0], f[1]), g22 = lorentz_product(f[1], f[1]);
  const Sign determinant = sign_or(g11 * g22 - g12 * g12, [&] { return exact_signs().determinant(); });
  const bool equal_weights = sign_of(rb[3]) == Sign::ZERO && sign_of(rc[3]) == Sign::ZERO;
  const Vector4<NT> ab{rb[0], rb[1], rb[2], NT(0)}, ac{rc[0], rc[1], rc[2], NT(0)};
  const bool collinear_centres =
      sign_or(ab[1] * ac[2] - ab[2] * ac[1], [&] { return exact_signs().cross(0); }) == Sign::ZERO &&
      sign_or(ab[2] * ac[0] - ab[0] * ac[2], [&] { return exact_signs().cross(1); }) == Sign::ZERO &&
      sign_or(ab[0] * ac[1] - ab[1] * ac[0], [&] { return exact_signs().cross(2); }) == Sign::ZERO;

  if (determinant == Sign::ZERO) {
    // The axis kappa spans the kernel of the restricted form; e2 completes the basis.
    if (sign_of(g11) != Sign::ZERO) {
      g.e1 = combination(g11, f[1], -g12, f[0]);
      g.e2 = f[0];
    } else if (sign_of(g22) != Sign::ZERO) {
      g.e1 = combination(g22, f[0], -g12, f[1]);
      g.e2 = f[1];
    } else {
      throw std::logic_error("trisector: a plane of directions isotropic for the Lorentz product");
    }
    g.gamma1 = NT(0);
    g.gamma2 = lorentz_product(g.e2, g.e2);
    g.monotone = g.e2;
    // X = point + s e1 + t e2 on the cone: 2 s <point, e1> = -(<point, point> + 2 t <point, e2> + t^2 gamma2),
    // so both ends go to infinity along s e1 with sign(s) = -sign(gamma2) sign(<point, e1>): on the sheet
    // iff that times sign(e1_3) is positive (e1 is null, so e1_3 != 0).
    const Sign axis_side = -(sign_of(g.gamma2) * sign_of(lorentz_product(g.point, g.e1)));
    const Sign axis_height = sign_of(g.e1[3]);
    if (axis_side == Sign::ZERO || axis_height == Sign::ZERO)
      throw std::logic_error("trisector: a parabola through the apex of the cone");
    if (axis_side * axis_height == Sign::POSITIVE) {
      g.kind = Trisector_kind::parabola;
      g.shape = Curve_shape::parabola;
    }
    return g;
  }

  // An orthogonal basis for <,>, by one Gram-Schmidt step (rational: no normalization).
  if (sign_of(g11) != Sign::ZERO) {
    g.e1 = f[0];
    g.e2 = combination(g11, f[1], -g12, f[0]);
  } else if (sign_of(g22) != Sign::ZERO) {
    g.e1 = f[1];
    g.e2 = combination(g22, f[0], -g12, f[1]);
  } else {  // f0 and f1 null, <f0, f1> != 0
    g.e1 = combination(NT(1), f[0], NT(1), f[1]);
    g.e2 = combination(NT(1), f[0], NT(-1), f[1]);
  }
  g.gamma1 = lorentz_product(g.e1, g.e1);
  g.gamma2 = lorentz_product(g.e2, g.e2);
  g.centre = minus(minus(g.point, scaled(lorentz_product(g.point, g.e1) / g.gamma1, g.e1)),
                   scaled(lorentz_product(g.point, g.e2) / g.gamma2, g.e2));
  g.K = -lorentz_product(g.centre, g.centre);
  const Sign k = sign_or(g.K, [&] { return exact_signs().conic_constant(); });

  if (determinant == Sign::POSITIVE) {
    if (sign_of(g.gamma1) != Sign::POSITIVE || sign_of(g.gamma2) != Sign::POSITIVE)
      throw std::logic_error("trisector: a negative definite plane for the Lorentz product");
    // The curve lies on one sheet, and so does its centre.
    if (k == Sign::NEGATIVE || sign_of(g.centre[3]) != Sign::POSITIVE) return g;
    g.kind = k == Sign::ZERO ? Trisector_kind::point : Trisector_kind::ellipse;
    g.shape = k == Sign::ZERO ? Curve_shape::point : collinear_centres ? Curve_shape::circle : Curve_shape::ellipse;
    return g;
  }

  // A hyperbola: its two branches lie on opposite sheets, so at the branch vertices C +- sqrt(K / gamma) e
  // (e the axis whose gamma has the sign of K) X_3 has opposite signs, and the branch on X_3 > 0 is the one
  // on the side of sign(e_3).
  if (k == Sign::ZERO) throw std::logic_error("trisector: a hyperbola through the apex of the cone");
  g.kind = Trisector_kind::hyperbola;
  g.shape = equal_weights ? Curve_shape::line : Curve_shape::hyperbola;
  g.branch_axis = k == sign_of(g.gamma1) ? 1 : 2;
  g.branch_sign = sign_of(g.branch_axis == 1 ? g.e1[3] : g.e2[3]);
  if (g.branch_sign == Sign::ZERO) throw std::logic_error("trisector: both branches on one sheet");
  g.monotone = g.branch_axis == 1 ? g.e2 : g.e1;
  return g;
}

template Trisector_geometry<Interval> trisector_geometry<Interval>(const std::array<Site, 3>&);
template Trisector_geometry<Wide_interval> trisector_geometry<Wide_interval>(const std::array<Site, 3>&);
template Trisector_geometry<Mpfr_interval> trisector_geometry<Mpfr_interval>(const std::array<Site, 3>&);
template Trisector_geometry<Rational> trisector_geometry<Rational>(const std::array<Site, 3>&);

Root_number<Rational> lorentz_value(const Field_point<Rational>& p, const Vector4<Rational>& y) {
  Rational a = 0, b = 0;
  for (int j = 0; j < 4; ++j) {
    const Rational term_a = p.scaled[j].a * y[j], term_b = p.scaled[j].b * y[j];
    a += j < 3 ? term_a : -term_a;
    b += j < 3 ? term_b : -term_b;
  }
  return {a, b, p.discriminant, p.denominator};
}

Root_number<Rational> euclidean_value(const Field_point<Rational>& p, const Vector4<Rational>& y, const Rational& c) {
  Rational a = c * p.denominator, b = 0;
  for (int j = 0; j < 4; ++j) {
    a += p.scaled[j].a * y[j];
    b += p.scaled[j].b * y[j];
  }
  return {a, b, p.discriminant, p.denominator};
}

Trisector::Trisector(const std::array<Site_index, 3>& indices, const std::array<Site, 3>& sites)
    : indices_(indices), sites_(sites) {
  Rounding_guard guard;
  try {
    interval_ = trisector_geometry<Interval>(sites);
  } catch (const Uncertain_sign&) {
  }
}

template <>
const Trisector_geometry<Interval>& Trisector::geometry<Interval>() const {
  if (!interval_) throw Uncertain_sign();
  return *interval_;
}

namespace {

// Framed_trisector_geometry<NT> of the sites, or nothing where NT does not decide.
template <class NT>
std::optional<Framed_trisector_geometry<NT>> framed(const std::array<Site, 3>& sites) {
  const int origin = closest_pair_origin(sites);
  std::array<Site, 3> from_origin = sites;
  std::swap(from_origin[0], from_origin[origin]);  // the other two in any order: the same plane L
  Rounding_guard guard;  // Wide_interval's; Mpfr_interval rounds by itself
  try {
    return Framed_trisector_geometry<NT>{trisector_geometry<NT>(from_origin), origin};
  } catch (const Uncertain_sign&) {
    return std::nullopt;
  }
}

}  // namespace

// Only asked for where the intervals did not decide: deep inputs, whose exact geometry has thousands of
// bits, and signs a hair from zero.
template <>
const Framed_trisector_geometry<Wide_interval>& Trisector::framed_geometry<Wide_interval>() const {
  const auto& g = wide_.get_or_compute([&] { return framed<Wide_interval>(sites_); });
  if (!g) throw Uncertain_sign();
  return *g;
}

template <>
const Framed_trisector_geometry<Mpfr_interval>& Trisector::framed_geometry<Mpfr_interval>() const {
  const auto& g = precise_.get_or_compute([&] { return framed<Mpfr_interval>(sites_); });
  if (!g) throw Uncertain_sign();
  return *g;
}

template <>
const Trisector_geometry<Rational>& Trisector::geometry<Rational>() const {
  return rational_.get_or_compute([&] { return trisector_geometry<Rational>(sites_); });
}

template <>
Field_point<Interval> field_point<Interval>(const Vertex& v, const Site& a) {
  const Vertex_coordinates<Interval>& X = v.coordinates<Interval>();
  const Site& o = v.origin();
  const Interval two(2);
  return {{X.scaled[0] + two * (Interval(o.x) - Interval(a.x)), X.scaled[1] + two * (Interval(o.y) - Interval(a.y)),
           X.scaled[2] + two * (Interval(o.z) - Interval(a.z)), X.scaled[3] + two * (Interval(a.w) - Interval(o.w))}};
}

template <>
Field_point<Rational> field_point<Rational>(const Vertex& v, const Site& a) {
  const Vertex_coordinates<Exact>& X = v.coordinates<Exact>();
  const Site& o = v.origin();
  Field_point<Rational> p;
  p.denominator = to_rational(X.denominator);
  p.discriminant = to_rational(X.discriminant);
  // X_a = X_o + 2 (p_o - p_a, w_a - w_o): the weight enters r + w with the other sign.
  const double shift[4] = {o.x, o.y, o.z, a.w};
  const double base[4] = {a.x, a.y, a.z, o.w};
  for (int j = 0; j < 4; ++j) {
    const Rational offset = Rational(2) * (Rational(shift[j]) - Rational(base[j]));
    p.scaled[j] = {to_rational(X.scaled[j].a) + offset * p.denominator, to_rational(X.scaled[j].b)};
  }
  return p;
}

}  // namespace apollonius
