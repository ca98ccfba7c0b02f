// The linear part of the vertex equations of a quadruple (SPEC section 2), for any number type NT.
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

#include <array>

#include "number_types.h"
#include "site.h"

namespace apollonius {

template <class NT>
using Vector4 = std::array<NT, 4>;

template <class NT>
NT lorentz_product(const Vector4<NT>& x, const Vector4<NT>& y) {
  return x[0] * y[0] + x[1] * y[1] + x[2] * y[2] - x[3] * y[3];
}

template <class NT>
NT determinant3(const std::array<NT, 3>& c0, const std::array<NT, 3>& c1, const std::array<NT, 3>& c2) {
  return c0[0] * (c1[1] * c2[2] - c1[2] * c2[1]) - c1[0] * (c0[1] * c2[2] - c0[2] * c2[1]) +
         c2[0] * (c0[1] * c1[2] - c0[2] * c1[1]);
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

template <class NT>
Relative_site<NT> relative_site(const Site& origin, const Site& s) {
  Relative_site<NT> r;
  r.row = {NT(s.x) - NT(origin.x), NT(s.y) - NT(origin.y), NT(s.z) - NT(origin.z), NT(s.w) - NT(origin.w)};
  r.rhs = r.row[0] * r.row[0] + r.row[1] * r.row[1] + r.row[2] * r.row[2] - r.row[3] * r.row[3];
  return r;
}

template <class NT>
Quadruple_line<NT> quadruple_line(const std::array<Site, 4>& sites) {
  std::array<Relative_site<NT>, 3> rel;
  for (int m = 0; m < 3; ++m) rel[m] = relative_site<NT>(sites[0], sites[m + 1]);
  // Columns of M, and c.
  std::array<std::array<NT, 3>, 4> column;
  std::array<NT, 3> c;
  for (int m = 0; m < 3; ++m) {
    for (int j = 0; j < 4; ++j) column[j][m] = rel[m].row[j];
    c[m] = rel[m].rhs;
  }
  // The three columns other than `skip`, in order, with column `replace` (if any) swapped for c.
  auto minor = [&](int skip, int replace) {
    std::array<std::array<NT, 3>, 3> cols;
    for (int j = 0, t = 0; j < 4; ++j)
      if (j != skip) cols[t++] = (j == replace) ? c : column[j];
    return determinant3(cols[0], cols[1], cols[2]);
  };

  Quadruple_line<NT> line;
  for (int j = 0; j < 4; ++j) line.n[j] = (j % 2 == 0) ? minor(j, -1) : -minor(j, -1);
  for (int k : {3, 0, 1, 2}) {
    if (certain_sign(line.n[k]) != Sign::ZERO) {
      line.pivot = k;
      break;
    }
  }
  if (line.pivot < 0) return line;
  const int k = line.pivot;
  // Cramer on the columns other than k: Q_j = n_k * Y_j = (-1)^k det(M_{-k} with column j replaced by c).
  for (int j = 0; j < 4; ++j) line.Q[j] = (j == k) ? NT(0) : ((k % 2 == 0) ? minor(k, j) : -minor(k, j));
  line.A = lorentz_product(line.n, line.n);
  line.B = lorentz_product(line.Q, line.n);
  line.C = lorentz_product(line.Q, line.Q);
  line.discriminant = line.B * line.B - line.A * line.C;
  return line;
}

}  // namespace apollonius
