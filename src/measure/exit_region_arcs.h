// The regions of one exit on the sphere of directions around a site (exit_regions.h): the boundary of one
// region as arcs of circles, and adaptive Gauss-Kronrod quadrature of a closed 1-form along them. Floating
// point: quadrature only, never a decision of the diagram. Shared by the clipped cells of the contacts
// (exit_regions.h) and the box cells of the centroidal diagrams (box_cell_regions.h).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include "measure/gauss_kronrod_rule.h"
#include "measure/radial_cut.h"

namespace apollonius {

inline constexpr double kPi = 3.14159265358979323846, kTwoPi = 2 * kPi;

// 1 / t = a + b.u along the unit direction u: a cut (alpha and c as in radial_cut.h; a = 2 alpha / c,
// b = -2 D / c) or a plane of a box at distance h (a = 0, b = +-e_axis / h; alpha = c = 0).
struct Inverse_exit {
  double a;
  Vector3 b;
  double slope;  // |b| > 0
  double alpha, c;
  Site_index site;  // the cut's site, or kNoSite for a plane
};
inline constexpr Site_index kNoSite = static_cast<Site_index>(-1);

// The inverse exit of a cut whose numerator is positive.
inline Inverse_exit inverse_exit(const Radial_cut& cut) {
  const double scale = 2 / cut.numerator;
  return {scale * cut.weight_step,
          {-scale * cut.offset[0], -scale * cut.offset[1], -scale * cut.offset[2]},
          scale * std::sqrt(dot(cut.offset, cut.offset)),
          cut.weight_step,
          cut.numerator,
          cut.site};
}

// The cap m.u >= h (m a unit vector, -1 < h < 1) and its circle u(psi) = h m + rho (cos psi e1 + sin psi e2),
// with (e1, e2, m) right-handed: increasing psi runs with the cap on its left.
struct Cap {
  Vector3 m;
  double h, rho;
  Vector3 e1, e2;
  bool clip = false;       // the clip's circle: m is the region's axis N, so u.N = h there exactly
  double uncertainty = 0;  // how far (radians) rounding may have moved the circle: n and d err by a few
                           // roundoffs of the terms they are differences of, over |n|
};

// An arc [begin, end] within [0, 2 pi] of a cap's circle, with the uncertainty of each end (rounding,
// amplified where the circles that end it are nearly tangent).
struct Arc {
  double begin, end, begin_uncertainty, end_uncertainty;
};

// The direction on a cap's circle at angle psi, and its derivative in psi.
inline void point_on_cap(const Cap& cap, double psi, Vector3& u, Vector3& du) {
  const double cs = std::cos(psi), sn = std::sin(psi);
  for (int k = 0; k < 3; ++k) {
    u[k] = cap.h * cap.m[k] + cap.rho * (cs * cap.e1[k] + sn * cap.e2[k]);
    du[k] = cap.rho * (cs * cap.e2[k] - sn * cap.e1[k]);
  }
}

// Invariant after find(): arcs() bound the region of exit j, each arc on caps()[arc.cap], caps()[0] the clip.
class Exit_region_arcs {
 public:
  struct Region_arc {
    std::size_t cap;
    Arc arc;
    Vector3 first, last;  // the directions at its ends
  };

  // The region of exits[j]: where L_j >= L_k for every k and L_j >= inverse_clip (1 / R; 0 for no clip).
  // False when it has no interior. Cost: O(k) cap tests, then O(k'^2) for the k' caps kept.
  bool find(const std::vector<Inverse_exit>& exits, std::size_t j, double inverse_clip);

  const std::vector<Cap>& caps() const { return caps_; }
  const std::vector<Region_arc>& arcs() const { return arcs_; }
  bool touches_clip() const { return touches_clip_; }  // some arc lies on the clip's circle
  double steepest() const { return steepest_; }        // the largest |b| of the exit and of the caps' exits

  // The least of a + b.u over the arcs (a closed form per arc: a + b.u is A + B cos(psi - psi0) there).
  double least_along_arcs(double a, const Vector3& b) const;

 private:
  bool add_cap(const Vector3& n, double d, double terms);

  std::vector<Cap> caps_;
  std::vector<Region_arc> arcs_;
  std::vector<Arc> cap_arcs_, scratch_;
  bool touches_clip_ = false;
  double steepest_ = 0;
};

// Adaptive Gauss-Kronrod along arcs of an integrand of K components whose first C have their errors
// estimated and controlled. The integrand at psi returns an Arc_node: its values (dphi / dpsi included),
// the magnitudes whose rounding each controlled value carries, and an error already in the value (inner
// quadrature), per controlled component.
template <std::size_t K, std::size_t C>
struct Arc_node {
  std::array<double, K> value{};
  std::array<double, C> magnitude{}, error{};
};

template <std::size_t K, std::size_t C>
struct Arc_sums {
  std::array<double, K> value{};
  std::array<double, C> error{}, magnitude{};
  std::size_t nodes = 0;
  bool reached = true;
};

// Integrates f along [p0, p1] of `cap`, halving while some controlled estimate exceeds its budget (per
// full circle) times the arc's share of 2 pi, at most to depth 30 and while `panels` stays within
// max_panels (then accepted as it is, reached false).
template <std::size_t K, std::size_t C, class Integrand>
void integrate_arc(const Integrand& f, const Cap& cap, double p0, double p1, const Gauss_kronrod_rule& rule,
                   const std::array<double, C>& budget, std::size_t max_panels, std::size_t& panels,
                   Arc_sums<K, C>& sums, int depth = 0) {
  constexpr int kMaxDepth = 30;
  const double half = 0.5 * (p1 - p0), middle = 0.5 * (p0 + p1);
  std::array<double, K> kronrod{}, gauss{};
  std::array<double, C> magnitude{}, inner{};
  for (std::size_t k = 0; k < rule.node.size(); ++k) {
    const Arc_node<K, C> node = f(cap, middle + half * rule.node[k]);
    for (std::size_t c = 0; c < K; ++c) kronrod[c] += rule.kronrod[k] * node.value[c], gauss[c] += rule.gauss[k] * node.value[c];
    for (std::size_t c = 0; c < C; ++c)
      magnitude[c] += rule.kronrod[k] * node.magnitude[c], inner[c] += rule.kronrod[k] * node.error[c];
  }
  sums.nodes += rule.node.size();
  std::array<double, C> error;
  bool within = true;
  for (std::size_t c = 0; c < C; ++c) {
    error[c] = half * std::fabs(kronrod[c] - gauss[c]);
    within = within && error[c] <= budget[c] * (p1 - p0) / kTwoPi;
  }
  if (!within && depth < kMaxDepth && ++panels <= max_panels) {
    integrate_arc(f, cap, p0, middle, rule, budget, max_panels, panels, sums, depth + 1);
    integrate_arc(f, cap, middle, p1, rule, budget, max_panels, panels, sums, depth + 1);
    return;
  }
  if (!within) sums.reached = false;
  for (std::size_t c = 0; c < K; ++c) sums.value[c] += half * kronrod[c];
  for (std::size_t c = 0; c < C; ++c) {
    // A circle moved by delta moves the arc's integral by about delta times its magnitude (the
    // integrands vary on the scale of the sphere, 1 radian, or less).
    sums.error[c] += error[c] + half * inner[c] + cap.uncertainty * half * magnitude[c];
    sums.magnitude[c] += half * magnitude[c];
  }
}

}  // namespace apollonius
