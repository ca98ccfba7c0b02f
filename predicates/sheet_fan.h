// A face's edges at a vertex where it has more than two (a vertex with 5 or more tied sites, paper section
// 4.1): on the bisector sheet of sites a and b near the vertex v, each edge is a branch of a trisector
// leaving v, and the face is the union of every other sector between consecutive branches. In R^3 at v,
// with D_s = v - p_s and rho_s = r + w_s > 0 (the gradient of d_s is D_s / rho_s):
//  - the sheet's normal N = rho_b D_a - rho_a D_b is a positive multiple of grad d_a - grad d_b;
//  - a branch's tangent tau is its trisector's forward tangent (trisector_predicates.h) times its direction;
//  - another site k of a branch's tie set is nearer than a and b on the side of M_k = rho_k D_a - rho_a D_k,
//    a positive multiple of grad d_a - grad d_k, and the face is on the side where every such k is farther.
// Predicates:
//  - face_turn(v, a, b, branch): POSITIVE if the face lies counterclockwise of the branch around N
//    (-sign det(N, tau, M_k) for the first k of the branch's other sites that decides it: the face is where
//    k is farther), ZERO if none decides it at first order;
//  - order_on_sheet(v, a, b, branches): the branches counterclockwise around N, by tau; two branches with
//    one tangent direction by their Taylor expansions in the bisector plane (branch_expansion.h), which
//    two distinct branches cannot share to fourth order.
#pragma once

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <vector>

#include "predicates/branch_expansion.h"
#include "predicates/curve_point.h"
#include "predicates/field_value.h"
#include "predicates/filtered_predicate.h"

namespace apollonius {

struct Sheet_branch {
  const Trisector* trisector;  // the edge's curve
  int direction;               // +1: the edge leaves v forward along it, -1: backward
  std::vector<Site> others;    // the sites of the edge's tie set other than the face's two (not empty)
};

template <class NT>
struct Sheet_fan_geometry {
  using F = Field_value<NT>;
  using Vector = std::array<F, 3>;

  Sheet_fan_geometry(const Vertex& v, const Site& a, const Site& b) : a_(a) {
    X_ = field_coordinates<NT>(field_point<NT>(v, a));
    const Vector4<NT> to_b = relative_site<NT>(b, a).row;
    normal = scaled_difference(to_b);
  }

  // rho_s D_a - rho_a D_s for a tied site s, from X = 2 (v - p_a, r + w_a): D_s = X / 2 + p_a - p_s,
  // rho_s = X_3 / 2 + w_s - w_a.
  Vector scaled_difference(const Vector4<NT>& a_minus_s) const {
    const F half_X3 = X_[3] / F(2);
    const F rho_s = half_X3 - F(a_minus_s[3]);
    Vector result;
    for (int j = 0; j < 3; ++j) {
      const F D_a = X_[j] / F(2);
      result[j] = rho_s * D_a - half_X3 * (D_a + F(a_minus_s[j]));
    }
    return result;
  }

  Vector other_side(const Site& k) const { return scaled_difference(relative_site<NT>(k, a_).row); }

  // The branch's tangent: tau0 = <X, e1> e2 - <X, e2> e1 (spatial part) in its trisector's frame, forward
  // on a closed curve and forward times sign(<tau0, monotone>) on an open one.
  static Vector tangent(const Vertex& v, const Sheet_branch& branch) {
    const Trisector_geometry<NT>& g = branch.trisector->geometry<NT>();
    const Field_point<NT> p = field_point<NT>(v, branch.trisector->origin());
    const F s = to_field_value(lorentz_value(p, g.e1)), u = to_field_value(lorentz_value(p, g.e2));
    int orientation = branch.direction;
    if (g.kind != Trisector_kind::ellipse) {
      const Vector4<NT> z =
          combination(lorentz_product(g.e2, g.monotone), g.e1, -lorentz_product(g.e1, g.monotone), g.e2);
      orientation *= static_cast<int>(sign_of_number(lorentz_value(p, z)));
    }
    Vector tau;
    for (int j = 0; j < 3; ++j) tau[j] = F(orientation) * (s * F(g.e2[j]) - u * F(g.e1[j]));
    return tau;
  }

  Vector normal;

 private:
  Site a_;
  std::array<F, 4> X_;
};

struct Face_turn_predicate {
  static constexpr const char* name = "face_turn";
  using Exact_number = Rational;

  template <class NT>
  static Sign evaluate(const Vertex& v, const Site& a, const Site& b, const Sheet_branch& branch) {
    const Sheet_fan_geometry<NT> fan(v, a, b);
    const typename Sheet_fan_geometry<NT>::Vector tau = Sheet_fan_geometry<NT>::tangent(v, branch);
    for (const Site& k : branch.others) {
      const Sign side = sign_of_field_value(determinant(fan.normal, tau, fan.other_side(k)));
      if (side != Sign::ZERO) return -side;
    }
    return Sign::ZERO;
  }
};

struct Order_on_sheet_predicate {
  static constexpr const char* name = "order_on_sheet";
  using Exact_number = Rational;

  template <class NT>
  static std::vector<std::size_t> evaluate(const Vertex& v, const Site& a, const Site& b,
                                           const std::vector<Sheet_branch>& branches) {
    using Fan = Sheet_fan_geometry<NT>;
    using F = Field_value<NT>;
    const Fan fan(v, a, b);
    std::vector<typename Fan::Vector> tau;
    for (const Sheet_branch& branch : branches) tau.push_back(Fan::tangent(v, branch));
    const auto turn = [&](std::size_t i, std::size_t j) {
      return sign_of_field_value(determinant(fan.normal, tau[i], tau[j]));
    };
    const auto same_way = [&](std::size_t i, std::size_t j) {
      return sign_of_field_value(tau[i][0] * tau[j][0] + tau[i][1] * tau[j][1] + tau[i][2] * tau[j][2]) ==
             Sign::POSITIVE;
    };
    // Whether j lies counterclockwise of i, both leaving v along tau[i] (rare: vertices of many tied sites).
    const auto counterclockwise_of = [&](std::size_t i, std::size_t j) {
      const Bisector_plane_projection<NT> plane(a, b);
      const Sign normal_side = sign_of_field_value(fan.normal[0] * F(plane.axis()[0]) +
                                                   fan.normal[1] * F(plane.axis()[1]) + fan.normal[2] * F(plane.axis()[2]));
      const std::array<F, 4> X = field_coordinates<NT>(field_point<NT>(v, a));
      const std::array<F, 2> u_v = plane.project({X[0], X[1], X[2]}), t = plane.project(tau[i]);
      const Sign above = compare_expansions(plane.expansion(branches[j].others.front(), u_v, t),
                                            plane.expansion(branches[i].others.front(), u_v, t));
      if (above == Sign::ZERO)
        throw std::logic_error("order_on_sheet: two edges of a face agree to fourth order at a vertex");
      return above * normal_side == Sign::POSITIVE;
    };
    // Half 0: the first branch's direction and the directions a positive turn from it; half 1: the rest.
    std::vector<int> halves(branches.size());
    for (std::size_t i = 0; i < branches.size(); ++i) {
      const Sign s = turn(0, i);
      halves[i] = s == Sign::POSITIVE || (s == Sign::ZERO && same_way(0, i)) ? 0 : 1;
    }
    std::vector<std::size_t> order(branches.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
      if (halves[i] != halves[j]) return halves[i] < halves[j];
      if (i == j) return false;
      const Sign s = turn(i, j);
      if (s != Sign::ZERO) return s == Sign::POSITIVE;
      return counterclockwise_of(i, j);  // one tangent direction (opposite ones never share a half)
    });
    return order;
  }
};

inline const Filtered_predicate<Face_turn_predicate> face_turn{};
inline const Filtered_predicate<Order_on_sheet_predicate> order_on_sheet{};

}  // namespace apollonius
