// Bounds over a patch of the cubed sphere of directions (cell_cubature.h): how near a cut can come along
// any of its rays. They decide which sites are worth evaluating on which rays, and the clearance that
// makes a candidate set sufficient (cut_candidates.h). Floating point, with relative margins where used.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "measure/radial_cut.h"

namespace apollonius {

// The directions p of a rectangle [a0, a1] x [b0, b1] of cube face `face` (b0 = b1 for a line):
// p[k] = +-1 (k = face / 2, + for even faces), p[k + 1] = a, p[k + 2] = b, indices mod 3.
struct Face_rectangle {
  int face;
  double a0, a1, b0, b1;
};

// The least and greatest of u.V over the rectangle's unit directions u = p / |p|: on an edge of fixed b,
// u.V = (B0 + B1 a) / sqrt(1 + b^2 + a^2) is extreme at the ends or at a = B1 (1 + b^2) / B0 (likewise on
// an edge of fixed a); inside, only at u = +-V / |V|.
inline std::pair<double, double> projection_range(const Face_rectangle& r, const Vector3& V) {
  const int axis = r.face / 2, inner = (axis + 1) % 3, outer = (axis + 2) % 3;
  const double normal = r.face % 2 == 0 ? V[axis] : -V[axis];  // n.V, n the face's axis direction
  double low = std::numeric_limits<double>::infinity(), high = -low;
  const auto edge = [&](double c0, double c1, double fixed, double lo, double hi) {
    // (c0 + c1 x) / sqrt(1 + fixed^2 + x^2) over x in [lo, hi]
    const double s2 = 1 + fixed * fixed;
    const auto f = [&](double x) { return (c0 + c1 * x) / std::sqrt(s2 + x * x); };
    const double ends[2] = {f(lo), f(hi)};
    for (double e : ends) low = std::min(low, e), high = std::max(high, e);
    if (c0 != 0) {
      const double critical = c1 * s2 / c0;
      if (critical > lo && critical < hi) low = std::min(low, f(critical)), high = std::max(high, f(critical));
    }
  };
  for (double b : {r.b0, r.b1}) edge(normal + b * V[outer], V[inner], b, r.a0, r.a1);
  if (r.b0 < r.b1) {
    for (double a : {r.a0, r.a1}) edge(normal + a * V[inner], V[outer], a, r.b0, r.b1);
    if (normal != 0) {
      const double a = V[inner] / normal, b = V[outer] / normal, norm = std::sqrt(dot(V, V));
      if (a >= r.a0 && a <= r.a1 && b >= r.b0 && b <= r.b1) (normal > 0 ? high : low) = normal > 0 ? norm : -norm;
    }
  }
  return {low, high};
}

// The least and greatest distance t = c / (2 (alpha - u.D)) at which the cut meets the rectangle's rays,
// +infinity where it may miss some (greatest) or misses all (both).
inline std::pair<double, double> cut_distance_range(const Radial_cut& cut, const Face_rectangle& r) {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  const auto [low, high] = projection_range(r, cut.offset);
  const double alpha = cut.weight_step;
  if (alpha - low <= 0) return {kInfinity, kInfinity};
  return {cut.numerator / (2 * (alpha - low)), alpha - high > 0 ? cut.numerator / (2 * (alpha - high)) : kInfinity};
}

}  // namespace apollonius
