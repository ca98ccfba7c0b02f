#include "measure/exit_regions.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "measure/gauss_kronrod_rule.h"
#include "measure/orthonormal_frame.h"
#include "predicates/unit_roundoff.h"

namespace apollonius {
namespace {

constexpr double kPi = 3.14159265358979323846, kTwoPi = 2 * kPi;
// The cap tests that drop constraints leave this much (in cosines) for rounding: a constraint kept
// needlessly costs time, not accuracy (its arc is then empty).
constexpr double kCosineMargin = 1e-9;
// Halvings of an arc at most (2^-30 of a circle is far below any tolerance's share), and arc panels per
// cell beyond which every panel is accepted as it is (reached_tolerance is then false and the estimates
// say by how much): the halvings cannot multiply without bound where rounding defeats the rule.
constexpr int kMaxDepth = 30;
constexpr std::size_t kMaxPanels = 20000;
// Two circles closer than this (in the terms of one's equation on the other) are taken as one.
constexpr double kConcentric = 64 * std::numeric_limits<double>::epsilon();
// The share of the tolerance that the arcs' quadrature aims at.
constexpr double kArcShare = 1e-3;

Vector3 cross(const Vector3& a, const Vector3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// 1 / t = a + b.u for the cut of site j (exit_regions.h); alpha and c as in radial_cut.h.
struct Inverse_exit {
  double a;
  Vector3 b;
  double slope;  // |b|
  double alpha, c;
  Site_index site;
};

// The cap m.u >= h (m a unit vector, -1 < h < 1) and its circle u(psi) = h m + rho (cos psi e1 + sin psi e2),
// with (e1, e2, m) right-handed: increasing psi runs with the cap on its left.
struct Cap {
  Vector3 m;
  double h, rho;
  Vector3 e1, e2;
  bool clip = false;  // the clip's circle: m is the region's axis N, so u.N = h there exactly
  double uncertainty = 0;  // how far (radians) rounding may have moved the circle: n and d err by a few
                           // roundoffs of the terms they are differences of, over |n|
};

// Disjoint arcs [psi0, psi1] within [0, 2 pi] of one circle, with the uncertainty of each end (rounding,
// amplified where the circles that end it are nearly tangent).
struct Arc {
  double begin, end, begin_uncertainty, end_uncertainty;
};
using Arcs = std::vector<Arc>;

// Keeps the part of `arcs` within the circular interval [centre - half_width, centre + half_width], whose
// ends are uncertain by `uncertainty`.
void keep_within(Arcs& arcs, double centre, double half_width, double uncertainty, Arcs& scratch) {
  double lo = centre - half_width;
  lo -= kTwoPi * std::floor(lo / kTwoPi);
  const double hi = lo + 2 * half_width;
  const std::array<Arc, 2> pieces{{{lo, std::min(hi, kTwoPi), uncertainty, hi > kTwoPi ? 0.0 : uncertainty},
                                   {0, hi - kTwoPi, 0, uncertainty}}};
  const int count = hi > kTwoPi ? 2 : 1;
  scratch.clear();
  for (const Arc& arc : arcs)
    for (int k = 0; k < count; ++k) {
      const Arc& p = pieces[k];
      Arc kept{std::max(arc.begin, p.begin), std::min(arc.end, p.end), 0, 0};
      if (!(kept.begin < kept.end)) continue;
      kept.begin_uncertainty = arc.begin >= p.begin ? arc.begin_uncertainty : p.begin_uncertainty;
      kept.end_uncertainty = arc.end <= p.end ? arc.end_uncertainty : p.end_uncertainty;
      scratch.push_back(kept);
    }
  arcs.swap(scratch);
}

// Integrals over one region: volume, face area, solid angle.
struct Region_sums {
  std::array<double, 3> value{}, error{}, magnitude{};
  std::size_t nodes = 0;
  bool reached = true;
  bool touches_clip = false;  // some arc lies on the clip's circle: the sphere's region borders this one
  bool empty = true;          // no arc at all: the region has no area
  double steepest = 0;        // the largest |b| of the exit and of those whose caps bound the region
};

// The region of one cut: its axis frame and the closed forms of exit_regions.h.
class Region {
 public:
  explicit Region(const Inverse_exit& e) : e_(e) {
    beta_ = e.slope;
    axis_ = {e.b[0] / beta_, e.b[1] / beta_, e.b[2] / beta_};
    std::tie(across_x_, across_y_) = orthonormal_complement(axis_);
    top_ = e.a + beta_;
    std::tie(top_h_, top_h_magnitude_) = h_of(top_);
    area_scale_ = 2 / std::sqrt(e.c);
  }

  // The three integrands at psi on the circle of `cap` (dphi / dpsi included), and a fourth: the magnitude
  // whose rounding the area's value carries (its closed form cancels; exit_regions.h).
  std::array<double, 4> integrands(const Cap& cap, double psi) const {
    const double cs = std::cos(psi), sn = std::sin(psi);
    Vector3 u, du;
    for (int k = 0; k < 3; ++k) {
      u[k] = cap.h * cap.m[k] + cap.rho * (cs * cap.e1[k] + sn * cap.e2[k]);
      du[k] = cap.rho * (cs * cap.e2[k] - sn * cap.e1[k]);
    }
    // On the clip's circle L = 1 / R: s from its definition, not from u (whose rounding |b| amplifies).
    const double x = dot(u, across_x_), y = dot(u, across_y_), s = cap.clip ? cap.h : dot(u, axis_);
    const double turn = (x * dot(du, across_y_) - y * dot(du, across_x_)) / (1 + s);
    const double one_minus_s = (x * x + y * y) / (1 + s);
    const double v = e_.a + beta_ * s;
    const double volume = (2 * e_.a + beta_ + beta_ * s) / (6 * v * v * top_ * top_);
    double cancelled;
    const double area = area_scale_ * area_difference(v, beta_ * one_minus_s, cancelled) * turn;
    return {volume * turn, area, turn, area_scale_ * cancelled * std::fabs(turn)};
  }

 private:
  // H(v), an antiderivative of v^-3 sqrt(1 + alpha v) (exit_regions.h), and the magnitude of its terms.
  std::pair<double, double> h_of(double v) const {
    const double w = std::sqrt(std::max(0.0, 1 + e_.alpha * v));
    const double rational = -w * (w * w + 1) / (4 * v * v);
    if (e_.alpha == 0) return {rational, std::fabs(rational)};
    const double logarithmic = e_.alpha * e_.alpha / 8 * (2 * std::log1p(w) - std::log(std::fabs(e_.alpha) * v));
    return {rational + logarithmic, std::fabs(rational) + std::fabs(logarithmic)};
  }
  double h_derivative(double v) const { return std::sqrt(std::max(0.0, 1 + e_.alpha * v)) / (v * v * v); }

  // (H(top) - H(v)) / (top - v), top - v = gap > 0: the closed form, or where the gap is small (where it
  // would cancel) the mean of H' by 5-point Gauss-Legendre. H' = v^-3 sqrt(1 + alpha v) is singular at 0
  // and, for alpha < 0, at -1 / alpha, beyond top; with the gap below 0.05 of the distance to both, the
  // rule's error is of order 0.025^10.
  // `cancelled`: the magnitude of what was subtracted, over the gap (the value's rounding is about 4
  // roundoffs of it).
  double area_difference(double v, double gap, double& cancelled) const {
    const double reach = e_.alpha < 0 ? std::min(v, (1 + e_.alpha * v) / -e_.alpha) : v;
    if (!(gap <= 0.05 * reach)) {
      const auto [h, magnitude] = h_of(v);
      cancelled = (top_h_magnitude_ + magnitude) / gap;
      return (top_h_ - h) / gap;
    }
    static constexpr std::array<double, 5> node{0, 0.5384693101056831, -0.5384693101056831, 0.9061798459386640,
                                                -0.9061798459386640};
    static constexpr std::array<double, 5> weight{0.5688888888888889, 0.4786286704993665, 0.4786286704993665,
                                                  0.2369268850561891, 0.2369268850561891};
    double sum = 0;
    for (int k = 0; k < 5; ++k) sum += weight[k] * h_derivative(v + 0.5 * gap * (1 + node[k]));
    cancelled = 0.5 * sum;
    return 0.5 * sum;
  }

  Inverse_exit e_;
  double beta_, top_, top_h_, top_h_magnitude_, area_scale_;
  Vector3 axis_, across_x_, across_y_;
};

class Clipped_cell {
 public:
  Clipped_cell(std::vector<Inverse_exit> exits, double radius, double tolerance)
      : exits_(std::move(exits)), radius_(radius), rule_(make_gauss_kronrod_rule<15>()) {
    budget_ = {kArcShare * tolerance * radius * radius * radius, kArcShare * tolerance * radius * radius,
               kArcShare * tolerance};
  }

  Region_sums region(std::size_t j) {
    Region_sums sums;
    const Inverse_exit& e = exits_[j];
    caps_.clear();
    // The clip first: L_j >= 1 / R. Empty when the cut never comes within R.
    const double own = e.slope + std::fabs(e.a);
    if (!add_cap(e.b, 1 / radius_ - e.a, own + 1 / radius_)) return sums;
    caps_.front().clip = true;
    const Cap clip = caps_.front();
    sums.steepest = e.slope;
    for (std::size_t k = 0; k < exits_.size(); ++k) {
      if (k == j) continue;
      const Inverse_exit& o = exits_[k];
      const Vector3 n{e.b[0] - o.b[0], e.b[1] - o.b[1], e.b[2] - o.b[2]};
      const double d = o.a - e.a;
      const double norm = std::sqrt(dot(n, n));
      if (norm == 0) {  // parallel planes L_j - L_k = -d: all, nothing, or the same exit (lower index wins)
        if (d > 0 || (d == 0 && k < j)) return sums;
        continue;
      }
      const double h = d / norm;
      if (h <= -1) continue;
      if (h >= 1) return sums;
      const Vector3 m{n[0] / norm, n[1] / norm, n[2] / norm};
      // With gamma the angle between the caps' centres and r, r0 their angular radii (cos r = h, sin r =
      // rho): the clip's cap lies within this one when gamma + r0 <= r, and misses it when gamma >= r0 + r;
      // compared as cosines (no trigonometry), with a margin for rounding.
      const Vector3 normal = cross(m, clip.m);
      const double cos_between = dot(m, clip.m), sin_between = std::sqrt(dot(normal, normal));
      const double rho = std::sqrt((1 - h) * (1 + h));
      if (cos_between >= -clip.h && cos_between * clip.h - sin_between * clip.rho > h + kCosineMargin) continue;
      if (h >= -clip.h && cos_between < clip.h * h - clip.rho * rho - kCosineMargin) return sums;
      add_cap(n, d, own + o.slope + std::fabs(o.a));
      sums.steepest = std::max(sums.steepest, o.slope);
    }
    Region shape(e);
    for (std::size_t q = 0; q < caps_.size(); ++q) {
      const Cap& cap = caps_[q];
      arcs_.assign(1, Arc{0, kTwoPi, 0, 0});
      for (std::size_t l = 0; l < caps_.size() && !arcs_.empty(); ++l) {
        if (l == q) continue;
        const Cap& other = caps_[l];
        const double A = cap.rho * dot(other.m, cap.e1), B = cap.rho * dot(other.m, cap.e2);
        const double C = other.h - cap.h * dot(other.m, cap.m);
        const double r = std::sqrt(A * A + B * B);
        // Concentric circles, to rounding (A, B and C err by a few roundoffs): the other holds everywhere
        // on this one or nowhere; on one and the same circle, the same cap keeps its arcs once (on the
        // earlier), and the opposite cap leaves the region no interior (three exits tied along it).
        if (r <= kConcentric) {
          if (std::fabs(C) > kConcentric) {
            if (C > 0) arcs_.clear();
            continue;
          }
          if (dot(other.m, cap.m) < 0) return Region_sums{};
          if (l < q) arcs_.clear();
          continue;
        }
        const double c = C / r;
        if (c <= -1) continue;
        if (c >= 1) {
          arcs_.clear();
          break;
        }
        // c and the centre err by a few rounding errors over r; acos amplifies them by 1 / sin(half width),
        // up to sqrt(2 x error) where the circles are nearly tangent; the frames and the angles themselves
        // add some 32 rounding errors of a radian.
        const double c_error = 16 * kUnitRoundoff * (1 + std::fabs(C) + r) / r;
        const double half_width = std::acos(c), sine = std::sqrt((1 - c) * (1 + c));
        const double uncertainty = c_error / std::max(sine, std::sqrt(2 * c_error)) + c_error + 32 * kUnitRoundoff;
        keep_within(arcs_, std::atan2(B, A), half_width, uncertainty, scratch_);
      }
      if (q == 0 && !arcs_.empty()) sums.touches_clip = true;
      if (!arcs_.empty()) sums.empty = false;
      for (const Arc& arc : arcs_) {
        integrate_arc(shape, cap, arc.begin, arc.end, 0, sums);
        // An uncertain end leaves the boundary open by about that much of the integrand.
        const std::array<double, 4> begin = shape.integrands(cap, arc.begin), end = shape.integrands(cap, arc.end);
        for (int c = 0; c < 3; ++c)
          sums.error[c] += std::fabs(begin[c]) * arc.begin_uncertainty + std::fabs(end[c]) * arc.end_uncertainty;
      }
    }
    return sums;
  }

 private:
  // Adds the cap n.u >= d; false if it is empty (then nothing is added).
  bool add_cap(const Vector3& n, double d, double terms) {
    const double norm = std::sqrt(dot(n, n));
    const double h = d / norm;
    if (!(h < 1)) return false;
    Cap cap;
    cap.m = {n[0] / norm, n[1] / norm, n[2] / norm};
    cap.h = std::max(h, -1.0);
    cap.rho = std::sqrt((1 - cap.h) * (1 + cap.h));
    std::tie(cap.e1, cap.e2) = orthonormal_complement(cap.m);
    cap.uncertainty = 8 * kUnitRoundoff * terms / norm;
    caps_.push_back(cap);
    return true;
  }

  void integrate_arc(const Region& shape, const Cap& cap, double p0, double p1, int depth, Region_sums& sums) {
    const double half = 0.5 * (p1 - p0), middle = 0.5 * (p0 + p1);
    std::array<double, 3> kronrod{}, gauss{}, magnitude{};
    for (std::size_t k = 0; k < rule_.node.size(); ++k) {
      const std::array<double, 4> f = shape.integrands(cap, middle + half * rule_.node[k]);
      for (int c = 0; c < 3; ++c) {
        kronrod[c] += rule_.kronrod[k] * f[c], gauss[c] += rule_.gauss[k] * f[c];
        magnitude[c] += rule_.kronrod[k] * (c == 1 ? f[3] : std::fabs(f[c]));
      }
    }
    sums.nodes += rule_.node.size();
    std::array<double, 3> error;
    bool within = true;
    for (int c = 0; c < 3; ++c) {
      error[c] = half * std::fabs(kronrod[c] - gauss[c]);
      within = within && error[c] <= budget_[c] * (p1 - p0) / kTwoPi;
    }
    if (!within && depth < kMaxDepth && ++panels_ <= kMaxPanels) {
      integrate_arc(shape, cap, p0, middle, depth + 1, sums);
      integrate_arc(shape, cap, middle, p1, depth + 1, sums);
      return;
    }
    if (!within) sums.reached = false;
    for (int c = 0; c < 3; ++c) {
      sums.value[c] += half * kronrod[c];
      // A circle moved by delta moves the arc's integral by about delta times its magnitude (the
      // integrands vary on the scale of the sphere, 1 radian, or less).
      sums.error[c] += error[c] + cap.uncertainty * half * magnitude[c];
      sums.magnitude[c] += half * magnitude[c];
    }
  }

  std::vector<Inverse_exit> exits_;
  double radius_;
  Gauss_kronrod_rule rule_;
  std::array<double, 3> budget_;
  std::vector<Cap> caps_;
  Arcs arcs_, scratch_;
  std::size_t panels_ = 0;  // halvings so far, in the whole cell
};

}  // namespace

Unmeasurable_pair::Unmeasurable_pair(Site_index site_a, Site_index site_b)
    : std::runtime_error("balls " + std::to_string(std::min(site_a, site_b)) + " and " +
                         std::to_string(std::max(site_a, site_b)) +
                         " lie within 1e-4 of their probe-grown radius of each other, neither hiding the other: "
                         "their face passes through the ball's centre, beyond what double precision measures"),
      a(std::min(site_a, site_b)), b(std::max(site_a, site_b)) {}

bool too_close_to_measure(const Radial_cut& cut, double clip_radius) {
  return 2 * std::sqrt(dot(cut.offset, cut.offset)) * clip_radius > 1e4 * cut.numerator;
}

std::optional<Cell_measure> integrate_clipped_cell(const Cut_candidates& candidates, double clip_radius,
                                                   double relative_tolerance) {
  for (double clearance : candidates.clearance)
    if (clearance <= clip_radius * (1 + kClearanceMargin)) return std::nullopt;
  std::vector<Inverse_exit> exits;
  for (const Radial_cut& cut : candidates.cuts) {
    if (cut.gap >= 2 * clip_radius) continue;  // never within the clip: its nearest point is at gap / 2
    if (!(cut.numerator > 0) || too_close_to_measure(cut, clip_radius)) return std::nullopt;
    const double scale = 2 / cut.numerator;
    exits.push_back({scale * cut.weight_step,
                     {-scale * cut.offset[0], -scale * cut.offset[1], -scale * cut.offset[2]},
                     scale * std::sqrt(dot(cut.offset, cut.offset)),
                     cut.weight_step,
                     cut.numerator,
                     cut.site});
  }
  Clipped_cell cell(exits, clip_radius, relative_tolerance);
  Cell_measure m;
  const double R = clip_radius, R2 = R * R, R3 = R2 * R;
  double solid = 0, solid_error = 0, solid_magnitude = 0, volume_magnitude = 0;
  // The sphere's region is bounded by the clip arcs of the others: it is the whole sphere when there is no
  // other region, and empty (its measures exactly 0, not the rounding of 4 pi minus the others) when there
  // are some and none has a clip arc.
  bool sphere_bordered = false, any_region = false;
  for (std::size_t j = 0; j < exits.size(); ++j) {
    Region_sums sums = cell.region(j);
    // Rounding, amplified by the region's conditioning: u.N errs by about 1e-16 and L = a + b.u with it
    // by |b| 1e-16 against L >= 1 / R, and so do the ties that bound the region, so each value by about
    // |b| R of its magnitude's rounding, |b| the steepest of the exits involved. The factor 16 on top of
    // the 64 roundoffs below is measured: three balls 3e-6 R apart (|b| R = 8e5) erred by 500 roundoffs
    // times |b| R (fuzz_contacts).
    const double condition = 1 + 16 * sums.steepest * clip_radius;
    for (int c = 0; c < 3; ++c) sums.magnitude[c] *= condition;
    m.directions += sums.nodes;
    sphere_bordered = sphere_bordered || sums.touches_clip;
    any_region = any_region || !sums.empty;
    m.reached_tolerance = m.reached_tolerance && sums.reached;
    m.volume += sums.value[0], m.volume_error += sums.error[0];
    volume_magnitude += sums.magnitude[0];
    solid += sums.value[2], solid_error += sums.error[2], solid_magnitude += sums.magnitude[2];
    if (sums.value[1] > 0)
      m.contact_areas.push_back({exits[j].site, sums.value[1], sums.error[1] + 64 * kUnitRoundoff * sums.magnitude[1]});
  }
  const double sphere_solid = !any_region ? 4 * kPi : sphere_bordered ? std::max(0.0, 4 * kPi - solid) : 0.0;
  const double solid_rounding = any_region && sphere_bordered ? 64 * kUnitRoundoff * (4 * kPi + solid_magnitude) : 0.0;
  m.volume += R3 / 3 * sphere_solid;
  m.volume_error += R3 / 3 * (solid_error + solid_rounding) + 64 * kUnitRoundoff * volume_magnitude;
  m.sphere_area = R2 * sphere_solid;
  m.sphere_area_error = R2 * (solid_error + solid_rounding);
  m.cut_candidates = candidates.cuts.size();
  std::sort(m.contact_areas.begin(), m.contact_areas.end(),
            [](const Cell_measure::Face_area& x, const Cell_measure::Face_area& y) { return x.site < y.site; });
  return m;
}

}  // namespace apollonius
