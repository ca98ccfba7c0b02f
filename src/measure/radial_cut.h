// Where a ray from a site leaves its cell (paper Theorem 2: cells are star-shaped from their sites, so each
// ray leaves once). Floating point: these feed the quadrature of cell_measures.h, never a decision of the
// diagram.
#pragma once

#include <array>
#include <cmath>
#include <limits>

#include "predicates/axis_box.h"
#include "predicates/site.h"

namespace apollonius {

using Vector3 = std::array<double, 3>;

inline double dot(const Vector3& a, const Vector3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Site j as seen from site i: along x_i + t u, d_i = d_j where t + alpha = |D + t u|, D = x_i - x_j,
// alpha = w_j - w_i. Squaring gives t = (|D|^2 - alpha^2) / (2 (alpha - u.D)): a cut where alpha > u.D (and
// then t + alpha = |D - alpha u|^2 / (2 (alpha - u.D)) >= 0 holds by itself); none where alpha <= u.D, since
// j never gets nearer than i along that ray. For two sites that do not hide each other |D| > |alpha|, so
// the numerator is positive. Rays are parametrised as x_i + tau p with p not normalised (cubed sphere), so
// that t = tau |p| and tau = gap (|D| + alpha) / (2 (alpha |p| - p.D)).
// Invariant: gap = |D| - alpha >= 0 (rounded; 0 for a pair that is hidden in floating point only).
struct Radial_cut {
  Vector3 offset;         // D = x_i - x_j
  double weight_step;     // alpha = w_j - w_i
  double numerator;       // |D|^2 - alpha^2, as gap (|D| + alpha): no cancellation
  double gap;             // |D| - alpha: j can beat i within distance t of x_i only if gap <= 2 t
  Site_index site;        // j

  static Radial_cut between(const Site& i, const Site& j, Site_index j_index) {
    Radial_cut cut;
    cut.offset = {i.x - j.x, i.y - j.y, i.z - j.z};
    cut.weight_step = j.w - i.w;
    const double distance = std::sqrt(dot(cut.offset, cut.offset));
    cut.gap = std::max(0.0, distance - cut.weight_step);
    cut.numerator = cut.gap * (distance + cut.weight_step);
    cut.site = j_index;
    return cut;
  }

  // alpha |p| - p.D: the cut exists along p when this is positive.
  double denominator(const Vector3& p, double p_norm) const { return weight_step * p_norm - dot(p, offset); }

  // d tau / d alpha at a cut along p (tau = numerator / (2 denominator)): -(|p| (|D|^2 + alpha^2) -
  // 2 alpha p.D) / (2 denominator^2) = -|p| |D - alpha u|^2 / (2 denominator^2) <= 0: a larger w_j shrinks
  // the cell of i. d tau / d w_j is this, d tau / d w_i its negative.
  double tau_derivative(const Vector3& p, double p_norm, double denominator_value) const {
    const double norm_squared = dot(offset, offset);
    const double numerator_derivative =
        p_norm * (norm_squared + weight_step * weight_step) - 2 * weight_step * dot(p, offset);
    return -numerator_derivative / (2 * denominator_value * denominator_value);
  }
};

// Where x + tau p leaves the closed box (x inside it): the least (bound - x_a) / p_a over the axes.
inline double box_exit(const Vector3& x, const Vector3& p, const Axis_box& box) {
  double tau = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a) {
    if (p[a] > 0) tau = std::min(tau, (box.hi[a] - x[a]) / p[a]);
    if (p[a] < 0) tau = std::min(tau, (box.lo[a] - x[a]) / p[a]);
  }
  return std::max(tau, 0.0);
}

}  // namespace apollonius
