// Predicates at a point given by doubles (a mesh vertex, a sample): which of two sites is nearer in the
// weighted distance d_s(p) = |p - x_s| - w_s, and on which side of a ball's sphere the point lies. The
// mesh's coordinates are approximate; these decide exactly on them (docs/design.md, "Meshes").
#pragma once

#include <array>

#include "predicates/filtered_predicate.h"
#include "predicates/site.h"

namespace apollonius {

// sign(d_s(p) - d_t(p)) = sign(sqrt(A) - sqrt(B) - W), A = |p - x_s|^2, B = |p - x_t|^2, W = w_s - w_t,
// without roots: X = sqrt(A) - sqrt(B) has the sign of A - B; where X and W differ in sign, so does X - W;
// else X - W has the sign of X times that of X^2 - W^2 = C - 2 sqrt(A B), C = A + B - W^2, which is
// negative when C < 0 and has the sign of C^2 - 4 A B otherwise. Degree 4 in the inputs.
struct Compare_weighted_distances_predicate {
  static constexpr const char* name = "compare_weighted_distances";

  template <class NT>
  static Sign evaluate(const std::array<double, 3>& p, const Site& s, const Site& t) {
    const NT sx = NT(p[0]) - NT(s.x), sy = NT(p[1]) - NT(s.y), sz = NT(p[2]) - NT(s.z);
    const NT tx = NT(p[0]) - NT(t.x), ty = NT(p[1]) - NT(t.y), tz = NT(p[2]) - NT(t.z);
    const NT A = sx * sx + sy * sy + sz * sz, B = tx * tx + ty * ty + tz * tz, W = NT(s.w) - NT(t.w);
    const Sign x = certain_sign(A - B), w = certain_sign(W);
    if (x == Sign::ZERO) return -w;
    if (w == Sign::ZERO || w != x) return x;
    const NT C = A + B - W * W;
    const Sign c = certain_sign(C);
    Sign squares;  // sign(C - 2 sqrt(A B))
    if (c == Sign::POSITIVE)
      squares = certain_sign(C * C - NT(4) * A * B);
    else  // A B = 0 with C = 0 is a tie; otherwise C - 2 sqrt(A B) < 0
      squares = c == Sign::ZERO && certain_sign(A * B) == Sign::ZERO ? Sign::ZERO : Sign::NEGATIVE;
    return x * squares;
  }
};

// sign(|p - x_s| - (w_s + r)): positive outside the sphere of radius w_s + r about x_s (everywhere when
// that radius is negative), zero on it.
struct Side_of_grown_ball_predicate {
  static constexpr const char* name = "side_of_grown_ball";

  template <class NT>
  static Sign evaluate(const std::array<double, 3>& p, const Site& s, double r) {
    const NT radius = NT(s.w) + NT(r);
    if (certain_sign(radius) == Sign::NEGATIVE) return Sign::POSITIVE;
    const NT dx = NT(p[0]) - NT(s.x), dy = NT(p[1]) - NT(s.y), dz = NT(p[2]) - NT(s.z);
    return certain_sign(dx * dx + dy * dy + dz * dz - radius * radius);
  }
};

inline const Filtered_predicate<Compare_weighted_distances_predicate> compare_weighted_distances{};
inline const Filtered_predicate<Side_of_grown_ball_predicate> side_of_grown_ball{};

}  // namespace apollonius
