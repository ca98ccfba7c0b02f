// The linear part of the vertex equations of a quadruple (docs/design.md, "Algebra"), for any number type NT.
//
// Take site 0 of the quadruple as origin: a_m = p_m - p_0, b_m = w_m - w_0 (m = 1, 2, 3). In the unknown
// X = 2 (v - p_0, r + w_0) in R^4 the tangency equations |v - p_m| = r + w_m become
//     <(a_m, b_m), X> = |a_m|^2 - b_m^2        (m = 1, 2, 3, three linear equations M X = c)
//     X_0^2 + X_1^2 + X_2^2 - X_3^2 = 0,  X_3 + 2 b_m >= 0 (m = 0..3, b_0 = 0).
// When rank M = 3 the linear solutions form the line X = (Q + lambda n) / n_k, where n is the null vector of
// M (signed 3x3 minors), k the pivot (the first of 3, 0, 1, 2 with n_k != 0) and Q the solution with
// Q_k = 0 scaled by n_k, so that X_k = lambda. Substituting into the cone gives
//     A lambda^2 + 2 B lambda + C = 0,  A = <n,n>_L, B = <Q,n>_L, C = <Q,Q>_L,  discriminant B^2 - A C,
// with <x,y>_L = x0 y0 + x1 y1 + x2 y2 - x3 y3. Coplanar quadruples (n_3 = 0) need no special case.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <type_traits>

#include "predicates/double_with_magnitude.h"
#include "predicates/number_types.h"
#include "predicates/site.h"

namespace apollonius {

template <class NT>
using Vector4 = std::array<NT, 4>;

template <class NT>
NT lorentz_product(const Vector4<NT>& x, const Vector4<NT>& y) {
  return x[0] * y[0] + x[1] * y[1] + x[2] * y[2] - x[3] * y[3];
}

// Invariant: pivot == -1 exactly when rank M < 3; otherwise n[pivot] != 0 and Q[pivot] == 0.
template <class NT>
struct Quadruple_line {
  Vector4<NT> n, Q;
  int pivot = -1;
  NT A, B, C, discriminant;
};

// Row m - 1 of M and entry of c for site m relative to the origin site.
template <class NT>
struct Relative_site {
  Vector4<NT> row;  // (a_m, b_m)
  NT rhs;           // |a_m|^2 - b_m^2
};

// x - y for doubles x and y, in NT.
template <class NT>
NT difference_of(double x, double y) {
  if constexpr (std::is_same_v<NT, Double_with_magnitude> || std::is_same_v<NT, Depth_count>)
    return NT::difference(x, y);
  else
    return NT(x) - NT(y);
}

template <class NT>
Relative_site<NT> relative_site(const Site& origin, const Site& s) {
  Relative_site<NT> r;
  r.row = {difference_of<NT>(s.x, origin.x), difference_of<NT>(s.y, origin.y), difference_of<NT>(s.z, origin.z),
           difference_of<NT>(s.w, origin.w)};
  r.rhs = r.row[0] * r.row[0] + r.row[1] * r.row[1] + r.row[2] * r.row[2] - r.row[3] * r.row[3];
  return r;
}

// A vertex's X = 2 (v - p_from, r + w_from) (vertex.h, denominator 1) taken to the origin `to`:
// X - 2 (p_to - p_from, w_from - w_to). What a predicate computes from X and its origin does not depend on
// the origin; an error e in X costs |p_s - p_to| e in a test against site s, so a near origin is cheaper.
template <class NT>
void move_origin(std::array<NT, 4>& X, const Site& from, const Site& to) {
  const Vector4<NT> shift = relative_site<NT>(from, to).row;
  for (int j = 0; j < 3; ++j) X[j] = X[j] - NT(2) * shift[j];
  X[3] = X[3] + NT(2) * shift[3];
}

// max(|dx|, |dy|, |dz|, |dw|) in rounded doubles (infinite where a difference overflows): only for
// choosing an origin, which changes a filter's precision and never a sign.
inline double coarse_distance(const Site& a, const Site& b) {
  return std::max({std::fabs(a.x - b.x), std::fabs(a.y - b.y), std::fabs(a.z - b.z), std::fabs(a.w - b.w)});
}

// The position of the first site of the closest pair of `sites` (coarse_distance), the origin that filters
// take: two sites a hair apart beside far ones (a cluster 1e-9 wide beside balls of radius 1) give rows
// equal to within the hair from a far site, and rows of their own sizes from one of the two.
template <std::size_t N>
int closest_pair_origin(const std::array<Site, N>& sites) {
  int origin = 0;
  double closest = INFINITY;
  for (int i = 0; i < static_cast<int>(N); ++i)
    for (int j = i + 1; j < static_cast<int>(N); ++j)
      if (const double d = coarse_distance(sites[i], sites[j]); d < closest) closest = d, origin = i;
  return origin;
}

// The 3x3 minors of the 3 x 5 matrix [M | c] (columns 0..3 of M, column 4 = c), by Laplace expansion along
// the first row over the ten 2x2 minors of the other two rows, which the seven minors needed share.
template <class NT>
class Minors_of_extended_matrix {
 public:
  explicit Minors_of_extended_matrix(const std::array<std::array<NT, 5>, 3>& rows) : first_(rows[0]) {
    for (int p = 0; p < 5; ++p)
      for (int q = p + 1; q < 5; ++q) lower_[p][q] = rows[1][p] * rows[2][q] - rows[1][q] * rows[2][p];
  }
  // The determinant of columns p < q < s.
  NT operator()(int p, int q, int s) const {
    return first_[p] * lower_[q][s] - first_[q] * lower_[p][s] + first_[s] * lower_[p][q];
  }

 private:
  std::array<NT, 5> first_;
  std::array<std::array<NT, 5>, 5> lower_;  // lower_[p][q], p < q
};

// A, B, C and the discriminant from n and Q (precondition: pivot >= 0).
template <class NT>
void set_cone_terms(Quadruple_line<NT>& line) {
  line.A = lorentz_product(line.n, line.n);
  line.B = lorentz_product(line.Q, line.n);
  line.C = lorentz_product(line.Q, line.Q);
  line.discriminant = line.B * line.B - line.A * line.C;
}

// The pivot rule: the first of 3, 0, 1, 2 with n_k != 0, decided by certain_sign in NT (throws if uncertain).
struct First_nonzero_pivot {
  template <class NT>
  int operator()(const Vector4<NT>& n, const std::array<Site, 4>&) const {
    for (int k : {3, 0, 1, 2})
      if (certain_sign(n[k]) != Sign::ZERO) return k;
    return -1;
  }
};

// `choose_pivot(n, sites)` returns the pivot, or -1 for rank M < 3; it must follow the rule above (the root
// labels of vertex.h depend on the pivot), deciding the signs of n however it can.
template <class NT, class Choose_pivot = First_nonzero_pivot>
Quadruple_line<NT> quadruple_line(const std::array<Site, 4>& sites, Choose_pivot choose_pivot = {}) {
  std::array<std::array<NT, 5>, 3> rows;
  for (int m = 0; m < 3; ++m) {
    const Relative_site<NT> r = relative_site<NT>(sites[0], sites[m + 1]);
    for (int j = 0; j < 4; ++j) rows[m][j] = r.row[j];
    rows[m][4] = r.rhs;
  }
  const Minors_of_extended_matrix<NT> minor(rows);
  // The columns of M other than `skip`, ascending.
  const auto others = [](int skip) {
    std::array<int, 3> c{};
    for (int j = 0, t = 0; j < 4; ++j)
      if (j != skip) c[t++] = j;
    return c;
  };

  Quadruple_line<NT> line;
  for (int j = 0; j < 4; ++j) {
    const std::array<int, 3> c = others(j);
    line.n[j] = (j % 2 == 0) ? minor(c[0], c[1], c[2]) : -minor(c[0], c[1], c[2]);
  }
  line.pivot = choose_pivot(line.n, sites);
  if (line.pivot < 0) return line;
  const int k = line.pivot;
  // Cramer on the columns other than k: Q_j = n_k * Y_j = (-1)^k det(M_{-k} with column j replaced by c).
  // Moving c from position t of the three columns to the last takes 2 - t transpositions.
  const std::array<int, 3> c = others(k);
  for (int t = 0; t < 3; ++t) {
    const int j = c[t];
    const int p = c[t == 0 ? 1 : 0], q = c[t == 2 ? 1 : 2];
    const NT determinant = minor(p, q, 4);
    line.Q[j] = ((k + t) % 2 == 0) ? determinant : -determinant;
  }
  line.Q[k] = NT(0);
  set_cone_terms(line);
  return line;
}

// The same line in another number type, element by element.
template <class To, class NT, class Convert>
Quadruple_line<To> converted_line(const Quadruple_line<NT>& line, Convert convert) {
  Quadruple_line<To> result;
  for (int j = 0; j < 4; ++j) result.n[j] = convert(line.n[j]), result.Q[j] = convert(line.Q[j]);
  result.pivot = line.pivot;
  result.A = convert(line.A);
  result.B = convert(line.B);
  result.C = convert(line.C);
  result.discriminant = convert(line.discriminant);
  return result;
}

}  // namespace apollonius
