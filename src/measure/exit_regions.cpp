#include "measure/exit_regions.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "measure/exit_region_arcs.h"
#include "measure/gauss_kronrod_rule.h"
#include "measure/orthonormal_frame.h"
#include "predicates/unit_roundoff.h"

namespace apollonius {
namespace {

// Arc panels per cell beyond which every panel is accepted as it is (reached_tolerance is then false and
// the estimates say by how much): the halvings cannot multiply without bound where rounding defeats the rule.
constexpr std::size_t kMaxPanels = 20000;
// The share of the tolerance that the arcs' quadrature aims at.
constexpr double kArcShare = 1e-3;

// Integrals over one region: volume, face area, solid angle.
struct Region_sums : Arc_sums<3, 3> {
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

  // The three integrands at psi on the circle of `cap` (dphi / dpsi included), and the magnitudes whose
  // rounding they carry (the area's closed form cancels; exit_regions.h).
  Arc_node<3, 3> operator()(const Cap& cap, double psi) const {
    Vector3 u, du;
    point_on_cap(cap, psi, u, du);
    // On the clip's circle L = 1 / R: s from its definition, not from u (whose rounding |b| amplifies).
    const double x = dot(u, across_x_), y = dot(u, across_y_), s = cap.clip ? cap.h : dot(u, axis_);
    const double turn = (x * dot(du, across_y_) - y * dot(du, across_x_)) / (1 + s);
    const double one_minus_s = (x * x + y * y) / (1 + s);
    const double v = e_.a + beta_ * s;
    const double volume = (2 * e_.a + beta_ + beta_ * s) / (6 * v * v * top_ * top_);
    double cancelled;
    const double area = area_scale_ * area_difference(v, beta_ * one_minus_s, cancelled) * turn;
    Arc_node<3, 3> node;
    node.value = {volume * turn, area, turn};
    node.magnitude = {std::fabs(volume * turn), area_scale_ * cancelled * std::fabs(turn), std::fabs(turn)};
    return node;
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
    if (!arcs_.find(exits_, j, 1 / radius_)) return sums;
    sums.empty = false;
    sums.touches_clip = arcs_.touches_clip();
    sums.steepest = arcs_.steepest();
    const Region shape(exits_[j]);
    for (const Exit_region_arcs::Region_arc& r : arcs_.arcs()) {
      const Cap& cap = arcs_.caps()[r.cap];
      integrate_arc(shape, cap, r.arc.begin, r.arc.end, rule_, budget_, kMaxPanels, panels_, sums);
      // An uncertain end leaves the boundary open by about that much of the integrand.
      const Arc_node<3, 3> begin = shape(cap, r.arc.begin), end = shape(cap, r.arc.end);
      for (int c = 0; c < 3; ++c)
        sums.error[c] += std::fabs(begin.value[c]) * r.arc.begin_uncertainty +
                         std::fabs(end.value[c]) * r.arc.end_uncertainty;
    }
    return sums;
  }

 private:
  std::vector<Inverse_exit> exits_;
  double radius_;
  Gauss_kronrod_rule rule_;
  std::array<double, 3> budget_;
  Exit_region_arcs arcs_;
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
    exits.push_back(inverse_exit(cut));
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
