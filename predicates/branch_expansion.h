// Two edges of one face that leave a vertex v in the same direction (sheet_fan.h's tangent branches) are
// ordered by their Taylor expansions in the face's bisector plane, exactly.
//
// Let a < b be the face's sites, k a third site of the edge (any site of its tie set but a and b: the
// edge is where a, b and k tie). In X = 2 (x - p_a), T = 2 (r + w_a), with D_m = p_m - p_a, o_m = w_m - w_a,
// h_m = |D_m|^2 - o_m^2, the edge's curve is (trisector.h)
//     D_b . X + o_b T = h_b,   D_k . X + o_k T = h_k,   |X|^2 = T^2.
// Write X = P u + z D_b, u in R^2, with f1, f2 a rational basis of the plane orthogonal to D_b
// (f1 = D_b x e_j, f2 = D_b x f1) and u_i = f_i . X. The two linear equations give z and T as affine
// functions of u (or, when they cannot, a linear equation in u alone), and the cone a conic F(u) = 0 with
// rational coefficients: the curve's projection along D_b. The sheet of a and b is a graph over that plane
// (paper Theorem 3), so near v the projection of the edge is a smooth branch of F = 0 through u_v.
//
// In the frame u = u_v + x t + y n, t the projected tangent and n = t turned by +90 degrees,
// F = D x + E y + A x^2 + B x y + C y^2 with D = 0 (t is tangent) and E != 0 (the branch is smooth), so
//     y = a2 x^2 + a3 x^3 + a4 x^4 + ...,  a2 = -A / E,  a3 = B A / E^2,  a4 = -A (B^2 + C A) / E^3.
// Two distinct conics meet with multiplicity at most 4 (Bezout), so two distinct branches differ in
// (a2, a3, a4). The branch with the larger y lies counterclockwise of the other around the sheet's normal
// N when N . D_b > 0, clockwise otherwise: det(N, t, n) has the sign of N . D_b, since (t, n, D_b) is
// positively oriented (det(f1, f2, D_b) = |f1|^2 |D_b|^2 > 0).
#pragma once

#include <array>
#include <stdexcept>

#include "predicates/field_value.h"

namespace apollonius {

template <class NT>
struct Branch_expansion {
  using F = Field_value<NT>;
  // Numerators over the common denominators E, E^2, E^3 (their sign is sign(E)).
  F E, a2_numerator, a3_numerator, a4_numerator;
};

// The plane orthogonal to D_b and the conic of the curve where a, b and k tie, projected onto it.
template <class NT>
class Bisector_plane_projection {
 public:
  using F = Field_value<NT>;
  using Vector = std::array<F, 3>;

  Bisector_plane_projection(const Site& a, const Site& b) : a_(a) {
    axis_ = spatial(b);
    int j = 0;  // a coordinate axis not parallel to D_b: the one of its smallest component
    for (int i = 1; i < 3; ++i)
      if (abs_less(axis_[i], axis_[j])) j = i;
    std::array<NT, 3> e{NT(0), NT(0), NT(0)};
    e[j] = NT(1);
    f_[0] = cross(axis_, e);
    f_[1] = cross(axis_, f_[0]);
    ob_ = NT(b.w) - NT(a.w);
    hb_ = dot(axis_, axis_) - ob_ * ob_;
  }

  // (f1 . Y, f2 . Y) for a vector Y of field numbers (X coordinates, or a direction).
  std::array<F, 2> project(const Vector& Y) const {
    std::array<F, 2> u;
    for (int i = 0; i < 2; ++i) u[i] = F(f_[i][0]) * Y[0] + F(f_[i][1]) * Y[1] + F(f_[i][2]) * Y[2];
    return u;
  }

  const std::array<NT, 3>& axis() const { return axis_; }

  // The expansion at u_v, along the projected tangent t (u_v on the curve, t tangent to it there).
  Branch_expansion<NT> expansion(const Site& k, const std::array<F, 2>& u_v, const std::array<F, 2>& t) const {
    // F(u) = u^T Q u + L . u + c.
    // Explicit zeros: a default Interval is not zero.
    std::array<std::array<NT, 2>, 2> Q{{{NT(0), NT(0)}, {NT(0), NT(0)}}};
    std::array<NT, 2> L{NT(0), NT(0)};
    const std::array<NT, 3> Dk = spatial(k);
    const NT ok = NT(k.w) - NT(a_.w), hk = dot(Dk, Dk) - ok * ok;
    const NT bb = dot(axis_, axis_), beta = dot(Dk, axis_);
    const std::array<NT, 2> alpha{dot(f_[0], Dk) / dot(f_[0], f_[0]), dot(f_[1], Dk) / dot(f_[1], f_[1])};
    const NT det = bb * ok - ob_ * beta;
    if (certain_sign(det) != Sign::ZERO) {
      // det z = cz + ob alpha . u,  det T = cT - bb alpha . u,
      // F = det^2 |P u|^2 + bb (det z)^2 - (det T)^2, |P u|^2 = u1^2 / |f1|^2 + u2^2 / |f2|^2.
      const NT cz = hb_ * ok - ob_ * hk, cT = bb * hk - beta * hb_;
      for (int i = 0; i < 2; ++i) {
        for (int j = 0; j < 2; ++j) Q[i][j] = (bb * ob_ * ob_ - bb * bb) * alpha[i] * alpha[j];
        Q[i][i] += det * det / dot(f_[i], f_[i]);
        L[i] = NT(2) * bb * cz * ob_ * alpha[i] + NT(2) * cT * bb * alpha[i];
      }
    } else {
      // The linear equations leave bb alpha . u + beta h_b - bb h_k = 0: the projection is a line.
      for (int i = 0; i < 2; ++i) L[i] = bb * alpha[i];
      if (certain_sign(L[0]) == Sign::ZERO && certain_sign(L[1]) == Sign::ZERO)
        throw std::logic_error("branch_expansion: the three sites do not tie along a curve");
    }
    const auto form = [&](const std::array<F, 2>& x, const std::array<F, 2>& y) {
      F s = F(0);
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) s = s + F(Q[i][j]) * x[i] * y[j];
      return s;
    };
    const std::array<F, 2> n{F(0) - t[1], t[0]};
    std::array<F, 2> gradient;  // 2 Q u_v + L
    for (int i = 0; i < 2; ++i) gradient[i] = F(NT(2)) * (F(Q[i][0]) * u_v[0] + F(Q[i][1]) * u_v[1]) + F(L[i]);
    const F E = gradient[0] * n[0] + gradient[1] * n[1];
    if (sign_of_field_value(E) == Sign::ZERO)
      throw std::logic_error("branch_expansion: the edge's projection is singular at the vertex");
    const F A = form(t, t), B = F(NT(2)) * form(t, n), C = form(n, n);
    return {E, F(0) - A, B * A, F(0) - A * (B * B + C * A)};
  }

 private:
  std::array<NT, 3> spatial(const Site& s) const {
    return {NT(s.x) - NT(a_.x), NT(s.y) - NT(a_.y), NT(s.z) - NT(a_.z)};
  }
  static NT dot(const std::array<NT, 3>& x, const std::array<NT, 3>& y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; }
  static std::array<NT, 3> cross(const std::array<NT, 3>& x, const std::array<NT, 3>& y) {
    return {x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
  }
  // |x| < |y|, used only to pick a coordinate axis: any answer gives a valid basis unless D_b is parallel
  // to that axis, which the smallest component rules out.
  static bool abs_less(const NT& x, const NT& y) {
    if constexpr (std::is_same_v<NT, Interval>)
      return CGAL::abs(x).sup() < CGAL::abs(y).inf();
    else
      return CGAL::abs(x) < CGAL::abs(y);
  }

  Site a_;
  std::array<NT, 3> axis_;        // D_b
  std::array<std::array<NT, 3>, 2> f_;
  NT ob_, hb_;
};

// The sign of y_i - y_j for small x > 0: the first nonzero of the differences of a2, a3, a4 (ZERO only if
// the two expansions agree to fourth order, which two distinct branches cannot).
template <class NT>
Sign compare_expansions(const Branch_expansion<NT>& i, const Branch_expansion<NT>& j) {
  using F = Field_value<NT>;
  const Sign Ei = sign_of_field_value(i.E), Ej = sign_of_field_value(j.E);
  const Sign s2 = sign_of_field_value(i.a2_numerator * j.E - j.a2_numerator * i.E);
  if (s2 != Sign::ZERO) return s2 * Ei * Ej;
  const F Ei2 = i.E * i.E, Ej2 = j.E * j.E;
  const Sign s3 = sign_of_field_value(i.a3_numerator * Ej2 - j.a3_numerator * Ei2);
  if (s3 != Sign::ZERO) return s3;
  const Sign s4 = sign_of_field_value(i.a4_numerator * Ej2 * j.E - j.a4_numerator * Ei2 * i.E);
  return s4 * Ei * Ej;
}

}  // namespace apollonius
