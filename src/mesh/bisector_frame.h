// The bisector plane of two sites and the sheet above it (paper Theorem 3, section 5.4): the sheet of
// d_a = d_b is a graph over the plane Pi through the midpoint m of the centres, orthogonal to the axis
// n = (x_b - x_a) / D. A point p = (p1, p2) of Pi lifts to h(p) = m + p1 u1 + p2 u2 + z n with
//   z^2 / delta^2 - rho^2 / (f^2 - delta^2) = 1,  delta = (w_a - w_b) / 2, f = D / 2, rho = |p|,
// z of the sign of delta (the sheet nearer the site of smaller weight; the plane z = 0 for equal weights).
// APPROXIMATE: doubles, for the mesh's coordinates only; nothing here decides anything.
#pragma once

#include <array>
#include <cmath>
#include <tuple>
#include <utility>

#include "measure/orthonormal_frame.h"
#include "predicates/site.h"

namespace apollonius {

using Point3 = std::array<double, 3>;

// Invariant: u1, u2, n orthonormal and right-handed; D > |w_a - w_b| (the sites do not hide each other).
struct Bisector_frame {
  Point3 middle, u1, u2, n;
  double half_distance = 0, half_weight_step = 0;  // f, delta
  double focal_gap = 0;                            // f^2 - delta^2 > 0

  Bisector_frame(const Site& a, const Site& b) {
    const Point3 d{b.x - a.x, b.y - a.y, b.z - a.z};
    const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    n = {d[0] / length, d[1] / length, d[2] / length};
    middle = {(a.x + b.x) / 2, (a.y + b.y) / 2, (a.z + b.z) / 2};
    std::tie(u1, u2) = orthonormal_complement(n);
    half_distance = length / 2;
    half_weight_step = (a.w - b.w) / 2;
    // f^2 - delta^2 = (f - |delta|)(f + |delta|): no cancellation when the sites nearly hide each other.
    focal_gap = (half_distance - std::abs(half_weight_step)) * (half_distance + std::abs(half_weight_step));
  }

  std::array<double, 2> project(const Point3& x) const {
    const Point3 r{x[0] - middle[0], x[1] - middle[1], x[2] - middle[2]};
    return {r[0] * u1[0] + r[1] * u1[1] + r[2] * u1[2], r[0] * u2[0] + r[1] * u2[1] + r[2] * u2[2]};
  }

  // The height z of the sheet above p.
  double height(const std::array<double, 2>& p) const {
    if (half_weight_step == 0) return 0;
    const double rho2 = p[0] * p[0] + p[1] * p[1];
    return half_weight_step * std::sqrt(1 + rho2 / focal_gap);
  }

  Point3 lift(const std::array<double, 2>& p) const {
    const double z = height(p);
    return {middle[0] + p[0] * u1[0] + p[1] * u2[0] + z * n[0], middle[1] + p[0] * u1[1] + p[1] * u2[1] + z * n[1],
            middle[2] + p[0] * u1[2] + p[1] * u2[2] + z * n[2]};
  }

  // The paper's density (eq. 37): the area of the sheet over a unit area of Pi, sqrt(1 + |grad z|^2), with
  // grad z = delta^2 p / ((f^2 - delta^2) z).
  double area_ratio(const std::array<double, 2>& p) const {
    if (half_weight_step == 0) return 1;
    const double z = height(p);
    const double g = half_weight_step * half_weight_step / (focal_gap * z);
    return std::sqrt(1 + g * g * (p[0] * p[0] + p[1] * p[1]));
  }
};

}  // namespace apollonius
