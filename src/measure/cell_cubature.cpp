#include "measure/cell_cubature.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include "measure/direction_range.h"
#include "measure/exit_regions.h"
#include "measure/gauss_kronrod_rule.h"

namespace apollonius {
namespace {

// Integrands: volume, distance, direction x y z, the faces' area and the clipping sphere's (these seven
// have their errors estimated and controlled; the areas are zero without a clip radius), then the median
// Hessian xx yy zz xy xz yz.
constexpr int kVolume = 0, kDistance = 1, kDirection = 2, kFaceArea = 5, kSphereArea = 6, kHessian = 7;
constexpr int kComponents = 13, kControlled = 7;
using Values = std::array<double, kComponents>;
using Errors = std::array<double, kControlled>;
constexpr double kInfinity = std::numeric_limits<double>::infinity();
// The inner integrals' share of the error budget.
constexpr double kInnerShare = 0.1;
// Panels per cell beyond which every panel is accepted as it is (reached_tolerance is then false when
// the estimates miss the target): the bisections cannot multiply without bound.
constexpr std::size_t kMaxPanels = 20000;
// Rays per cell beyond which no piece of a line and no panel is refined further (reached_tolerance false
// where an estimate then misses its target). Without it, a cell beside a pair of sites one ulp apart
// refined pieces 16 deep in each of the 31 lines of each of 20,000 panels: minutes. With it, a cell costs
// at most this many rays plus the lines of the panels pending when it is reached (at most 2 x 60 per face,
// the depth of interval()).
constexpr std::size_t kMaxRays = 2000000;
// Events are bracketed to this width in b: the bracket's two-point rule then errs by about its width
// squared times the jump in the slope of the line integrals, far below any tolerance, and the smooth
// panels beside it end where the (b - b*)^(3/2) terms are smoothed by the substitution.
constexpr double kEventWidth = 1e-6;
// ... or the tolerance, when that is larger (up to 1e-4): the bracket's error, about its width squared
// times the slope's jump, stays far below the tolerance's share of it.
double event_width(double tolerance) { return std::clamp(tolerance, kEventWidth, 1e-4); }
// Signatures sampled per face before the bisections.
constexpr int kFaceSamples = 3;

// Thrown when a ray's exit reaches the clearance: the cell needs more candidates.
struct Clearance_exceeded {};

// QUADPACK's estimate of a Gauss-Kronrod value's error (R. Piessens et al., QUADPACK, 1983, routine
// qk15): the difference d = |Kronrod - Gauss| estimates the Gauss value's error, which for smooth
// integrands is far larger than the Kronrod value's; it is scaled by the variation of the integrand
// (resasc, the integral of |f - its mean|) as resasc min(1, (200 d / resasc)^1.5).
double kronrod_error(double difference, double resasc) {
  if (resasc == 0 || difference == 0) return difference;
  const double ratio = std::min(1.0, 200 * difference / resasc);
  return resasc * ratio * std::sqrt(ratio);
}

// One candidate exit along the rays: a cut (radial_cut.h), a plane of the box: tau = h / p[axis], valid
// where sign p[axis] > 0, or the clipping sphere: tau = h / |p|.
constexpr int kPlane = -1, kSphere = -2;
struct Exit {
  int cut;  // index into the candidates' cuts, or kPlane, or kSphere
  int axis;
  double h;
  int sign;
};

// Exit k along a line, in one form for cuts, planes and the sphere: tau(a) = N / (alpha |p| - e0 - e1 a)
// where that denominator is positive, +infinity elsewhere. A cut: N = c / 2, alpha its weight step, e0 +
// e1 a = p.D; a plane p[m] tau = h: N = |h|, alpha = 0, e0 + e1 a = -sign p[m]; the sphere: N = R, alpha =
// 1, e = 0. Two exits then tie where |p| (N_j alpha_k - N_k alpha_j) = (N_j e0_k - N_k e0_j) + (N_j e1_k -
// N_k e1_j) a (cell_cubature.h), and each ray costs one division per exit.
struct Line_exit {
  int k;  // index into the exits
  double N, alpha, e0, e1;
  double denominator(double a, double p_norm) const { return alpha * p_norm - e0 - e1 * a; }
  double tau(double a, double p_norm) const {
    const double d = denominator(a, p_norm);
    return d > 0 ? N / d : std::numeric_limits<double>::infinity();
  }
};

// The rays of face `face` at outer coordinate b: p(a) = q + a e, |p|^2 = s2 + a^2 (cell_cubature.h).
struct Face_line {
  int face, inner_axis;
  Vector3 q;
  double s2;
  std::vector<int> live;         // the exits that can be the least somewhere on the line
  std::vector<Line_exit> table;  // the live exits' forms, in the same order
  const Line_exit& of(int k) const {
    for (const Line_exit& x : table)
      if (x.k == k) return x;
    return table.front();  // not reached: pieces carry live exits only
  }
  Vector3 at(double a) const {
    Vector3 p = q;
    p[inner_axis] += a;
    return p;
  }
};

// Invariant: pieces cover [-1, 1] in order; exit -1 marks a piece whose exit is taken as the least of all
// (the walk gave up or a check failed).
struct Piece {
  double a0, a1;
  int exit;
};

// What one cut contributes: the integrals of tau^2 d tau / d alpha and of its face's area element, and the
// area's error estimate.
struct Cut_integral {
  int cut;
  double derivative, area, area_error;
};

struct Line_result {
  Values value{};
  Errors error{};
  std::vector<Cut_integral> cuts;  // runs of one cut may repeat; summed by cut where accepted
};

class Cell_integrator {
 public:
  Cell_integrator(const Site& site, const Cut_candidates& candidates, const Axis_box& box,
                  const Cell_cubature_options& options)
      : centre_{site.x, site.y, site.z}, candidates_(candidates), options_(options),
        inner_(make_gauss_kronrod_rule<15>()), outer_(make_gauss_kronrod_rule<15>()),
        clipped_(std::isfinite(options.clip_radius)), derivative_total_(candidates.cuts.size(), 0.0),
        area_total_(candidates.cuts.size(), 0.0), area_error_total_(candidates.cuts.size(), 0.0),
        panel_kronrod_(candidates.cuts.size(), 0.0), panel_gauss_(candidates.cuts.size(), 0.0) {
    for (std::size_t c = 0; c < candidates.cuts.size(); ++c) exits_.push_back({static_cast<int>(c), 0, 0, 0});
    for (int axis = 0; axis < 3; ++axis) {
      exits_.push_back({kPlane, axis, box.hi[axis] - centre_[axis], 1});
      exits_.push_back({kPlane, axis, box.lo[axis] - centre_[axis], -1});
    }
    if (clipped_) exits_.push_back({kSphere, 0, options.clip_radius, 0});
  }

  Cell_cubature_result run() {
    Cell_cubature_result result;
    std::vector<int> all(exits_.size());
    for (std::size_t k = 0; k < exits_.size(); ++k) all[k] = static_cast<int>(k);
    for (int face = 0; face < 6; ++face) prune({face, -1, 1, -1, 1}, all, face_live_[face]);
    try {
      estimate_scales();
      for (int face = 0; face < 6; ++face) integrate_face(face);
    } catch (const Clearance_exceeded&) {
      result.clearance_exceeded = true;
      result.largest_exit = largest_exit_;
      return result;
    }
    Cell_measure& m = result.measure;
    if (!options_.median_integrals) {  // the closed-form pieces added some: not the cell's, drop them
      for (int c = kDistance; c < kFaceArea; ++c) total_[c] = 0, total_error_[c] = 0;
      for (int c = kHessian; c < kComponents; ++c) total_[c] = 0;
    }
    m.volume = total_[kVolume], m.volume_error = total_error_[kVolume];
    m.distance_integral = total_[kDistance], m.distance_error = total_error_[kDistance];
    m.direction_integral = {total_[kDirection], total_[kDirection + 1], total_[kDirection + 2]};
    m.direction_error = total_error_[kDirection] + total_error_[kDirection + 1] + total_error_[kDirection + 2];
    for (int h = 0; h < 6; ++h) m.median_hessian[h] = total_[kHessian + h];
    for (std::size_t c = 0; c < derivative_total_.size(); ++c) {
      if (derivative_total_[c] != 0) m.volume_derivatives.push_back({candidates_.cuts[c].site, derivative_total_[c]});
      if (clipped_ && area_total_[c] != 0)
        m.contact_areas.push_back({candidates_.cuts[c].site, area_total_[c], area_error_total_[c]});
    }
    std::sort(m.volume_derivatives.begin(), m.volume_derivatives.end());
    std::sort(m.contact_areas.begin(), m.contact_areas.end(),
              [](const Cell_measure::Face_area& x, const Cell_measure::Face_area& y) { return x.site < y.site; });
    m.sphere_area = total_[kSphereArea], m.sphere_area_error = total_error_[kSphereArea];
    m.directions = rays_;
    m.cut_candidates = candidates_.cuts.size();
    m.reached_tolerance = reached_;
    result.largest_exit = largest_exit_;
    return result;
  }

 private:
  // ---- exits along one line ----

  // The line at b, in a buffer reused from line to line (valid until the next call).
  const Face_line& line(int face, double b, const std::vector<int>& from) const {
    const int axis = face / 2;
    Face_line& l = line_;
    l.face = face;
    l.inner_axis = (axis + 1) % 3;
    l.q = {0, 0, 0};
    l.q[axis] = face % 2 == 0 ? 1 : -1;
    l.q[(axis + 2) % 3] = b;
    l.s2 = 1 + b * b;
    prune_line(l, from);
    return l;
  }

  // The range of the distance t = tau |p| of exit x over the rectangle's directions, (inf, inf) where it
  // never bounds them. For a cut, t = c / (2 (alpha - u.D)); for a plane, t = |h| |p| / |p_m| on the side
  // where it is valid.
  std::pair<double, double> distance_range(const Face_rectangle& r, const Exit& x) const {
    if (x.cut >= 0) return cut_distance_range(candidates_.cuts[x.cut], r);
    if (x.cut == kSphere) return {x.h, x.h};
    const int axis = r.face / 2;
    const auto square_range = [](double lo, double hi) {
      const double m = std::max(lo * lo, hi * hi);
      return std::pair<double, double>{lo <= 0 && hi >= 0 ? 0 : std::min(lo * lo, hi * hi), m};
    };
    const auto [a2_low, a2_high] = square_range(r.a0, r.a1);
    const auto [b2_low, b2_high] = square_range(r.b0, r.b1);
    const double h = std::fabs(x.h);
    if (x.axis == axis) {
      if (x.sign * (r.face % 2 == 0 ? 1 : -1) < 0) return {kInfinity, kInfinity};
      return {h * std::sqrt(1 + a2_low + b2_low), h * std::sqrt(1 + a2_high + b2_high)};
    }
    // p_m is a (the inner axis) or b (the outer one); the other coordinate is the free one.
    const bool inner = x.axis == (axis + 1) % 3;
    const double lo = inner ? r.a0 : r.b0, hi = inner ? r.a1 : r.b1;
    const double other2_low = inner ? b2_low : a2_low, other2_high = inner ? b2_high : a2_high;
    // The valid part of [lo, hi]: x.sign p_m > 0.
    const double valid_lo = x.sign > 0 ? std::max(lo, 0.0) : lo, valid_hi = x.sign > 0 ? hi : std::min(hi, 0.0);
    if (!(valid_lo < valid_hi) && !(valid_lo == valid_hi && valid_lo != 0)) return {kInfinity, kInfinity};
    const double far = std::max(std::fabs(valid_lo), std::fabs(valid_hi)), near = std::min(std::fabs(valid_lo), std::fabs(valid_hi));
    const bool everywhere = x.sign > 0 ? lo > 0 : hi < 0;
    return {h * std::sqrt(1 + far * far + other2_low) / far,
            everywhere ? h * std::sqrt(1 + near * near + other2_high) / near : kInfinity};
  }

  // prune() for the rays of one line, with the cuts' ranges in closed form: u.D = (c0 + c1 a) / sqrt(s2 +
  // a^2) over a in [-1, 1] is extreme at the ends or at a = c1 s2 / c0, where it is +-sqrt(c0^2 / s2 + c1^2).
  void prune_line(Face_line& l, const std::vector<int>& from) const {
    ranges_.resize(exits_.size());
    const double inverse_end = 1 / std::sqrt(l.s2 + 1);
    double ceiling = kInfinity;
    for (int k : from) {
      const Exit& x = exits_[k];
      if (x.cut < 0) {  // a plane or the sphere
        ranges_[k] = distance_range({l.face, -1, 1, l.q[(l.face / 2 + 2) % 3], l.q[(l.face / 2 + 2) % 3]}, x);
      } else {
        const Radial_cut& cut = candidates_.cuts[x.cut];
        const double c0 = dot(l.q, cut.offset), c1 = cut.offset[l.inner_axis];
        double low = (c0 - std::fabs(c1)) * inverse_end, high = (c0 + std::fabs(c1)) * inverse_end;
        if (c0 != 0 && std::fabs(c1 * l.s2) < std::fabs(c0)) {
          const double extreme = std::sqrt(c0 * c0 / l.s2 + c1 * c1);
          if (c0 > 0) high = extreme; else low = -extreme;
        }
        const double alpha = cut.weight_step;
        ranges_[k] = alpha - low <= 0 ? std::pair<double, double>{kInfinity, kInfinity}
                                      : std::pair<double, double>{cut.numerator / (2 * (alpha - low)),
                                                                  alpha - high > 0 ? cut.numerator / (2 * (alpha - high)) : kInfinity};
      }
      ceiling = std::min(ceiling, ranges_[k].second);
    }
    ceiling *= 1 + 1e-9;
    l.live.clear();
    l.table.clear();
    for (int k : from)
      if (ranges_[k].first * (1 - 1e-9) <= ceiling) {
        l.live.push_back(k);
        l.table.push_back(line_exit(l, k));
      }
  }

  Line_exit line_exit(const Face_line& l, int k) const {
    const Exit& x = exits_[k];
    if (x.cut >= 0) {
      const Radial_cut& cut = candidates_.cuts[x.cut];
      return {k, 0.5 * cut.numerator, cut.weight_step, dot(l.q, cut.offset), cut.offset[l.inner_axis]};
    }
    if (x.cut == kSphere) return {k, x.h, 1, 0, 0};
    return {k, std::fabs(x.h), 0, -x.sign * l.q[x.axis], x.axis == l.inner_axis ? -1.0 * x.sign : 0.0};
  }

  // Keeps, of `from`, the exits whose least distance over the rectangle is at most the least of all their
  // greatest distances: the others are never the least exit there. (Margins of 1e-9 cover the rounding of
  // the ranges.)
  void prune(const Face_rectangle& r, const std::vector<int>& from, std::vector<int>& live) const {
    ranges_.resize(exits_.size());
    double ceiling = kInfinity;
    for (int k : from) {
      ranges_[k] = distance_range(r, exits_[k]);
      ceiling = std::min(ceiling, ranges_[k].second);
    }
    ceiling *= 1 + 1e-9;
    live.clear();
    for (int k : from)
      if (ranges_[k].first * (1 - 1e-9) <= ceiling) live.push_back(k);
  }

  int least_exit(const Face_line& l, double a, double p_norm, double* least = nullptr) const {
    int best = -1;
    double best_tau = kInfinity;
    for (const Line_exit& x : l.table) {
      const double t = x.tau(a, p_norm);
      if (t < best_tau) best_tau = t, best = x.k;
    }
    if (least) *least = best_tau;
    return best;
  }

  // Where exits f and g tie along the line: |p| A = b0 + b1 a (Line_exit), squared into a quadratic in a;
  // roots where A and b0 + b1 a differ in sign come from the squaring and are dropped. Appends the roots
  // in (lo, hi).
  static void ties(const Face_line& l, const Line_exit& f, const Line_exit& g, double lo, double hi, double* roots,
                   int& count) {
    const double A = f.N * g.alpha - g.N * f.alpha, b0 = f.N * g.e0 - g.N * f.e0, b1 = f.N * g.e1 - g.N * f.e1;
    const auto keep = [&](double r) {
      if (r > lo && r < hi && A * (b0 + b1 * r) >= 0) roots[count++] = r;
    };
    if (A == 0) {
      if (b1 != 0) keep(-b0 / b1);
      return;
    }
    // A far below b1 (a cut and a plane, with weights one ulp apart): squared, the discriminant
    // 4 A^2 (b0^2 + b1^2 s2 - A^2 s2) is what is left of two terms 4 b0^2 b1^2, and rounding erases it, with
    // the tie, once A^2 is below about eps b1^2. Newton's method on b0 + b1 a - A |p| from -b0 / b1
    // instead: its derivative b1 - A a / |p| stays within 1e-5 of b1, and each step squares the relative
    // error, which starts at about A / b1 <= 1e-5, so two steps reach rounding.
    if (std::fabs(A) <= 1e-5 * std::fabs(b1)) {
      double r = -b0 / b1;
      for (int step = 0; step < 2; ++step) {
        const double norm = std::sqrt(l.s2 + r * r);
        r -= (b0 + b1 * r - A * norm) / (b1 - A * r / norm);
      }
      if (r > lo && r < hi) roots[count++] = r;  // a root of the unsquared equation: no sign to check
      return;
    }
    const double qa = A * A - b1 * b1, qb = -2 * b0 * b1, qc = A * A * l.s2 - b0 * b0;
    if (std::fabs(qa) <= 1e-14 * (A * A + b1 * b1)) {
      if (qb != 0) keep(-qc / qb);
      return;
    }
    const double discriminant = qb * qb - 4 * qa * qc;
    if (discriminant < 0) return;
    const double t = -0.5 * (qb + std::copysign(std::sqrt(discriminant), qb));
    if (t != 0) keep(qc / t);
    keep(t / qa);
  }

  // The position in l.table of the least exit along the ray at a (0 if none bounds it: not reached, the
  // box bounds every ray).
  static std::size_t least_slot(const Face_line& l, double a) {
    const double p_norm = std::sqrt(l.s2 + a * a);
    std::size_t best = 0;
    double best_tau = kInfinity;
    for (std::size_t n = 0; n < l.table.size(); ++n) {
      const double t = l.table[n].tau(a, p_norm);
      if (t < best_tau) best_tau = t, best = n;
    }
    return best;
  }

  // Whether exit x bounds the rays near a, where it ties another. A plane through the site (N = 0) is the
  // least exit, 0, on its outer side and none on the other: it changes at its pole, where its denominator
  // vanishes and it ties every other exit (ties: A = 0, root -e0 / e1), so the pole counts.
  static bool bounds_near(const Line_exit& x, double a, double p_norm) { return x.N == 0 || x.denominator(a, p_norm) > 0; }

  // The pieces of the line: the least exit and where it changes, walking from a = -1 to 1 through the
  // ties of the current least exit with every other (a kinetic lower envelope). Each step moves right by
  // at least 1e-13, and a line whose pieces outnumber any real envelope's gives up into one checked piece.
  void walk(const Face_line& l, std::vector<Piece>& pieces) const {
    pieces.clear();
    double a = -1;
    std::size_t current = least_slot(l, -1 + 1e-9);
    const std::size_t limit = 4 * l.live.size() + 8;
    double roots[2];
    while (pieces.size() < limit) {
      double next = 1;
      const Line_exit& c = l.table[current];
      for (std::size_t n = 0; n < l.table.size(); ++n) {
        if (n == current) continue;
        const Line_exit& x = l.table[n];
        int count = 0;
        ties(l, c, x, a + 1e-13, next, roots, count);
        for (int r = 0; r < count; ++r) {
          const double p_norm = std::sqrt(l.s2 + roots[r] * roots[r]);
          if (bounds_near(x, roots[r], p_norm) && bounds_near(c, roots[r], p_norm)) next = std::min(next, roots[r]);
        }
      }
      if (!pieces.empty() && pieces.back().exit == c.k)
        pieces.back().a1 = next;
      else
        pieces.push_back({a, next, c.k});
      if (next >= 1) return;
      a = next;
      current = least_slot(l, std::min(next + 1e-10, 0.5 * (next + 1)));
    }
    pieces.back().a1 = a;  // gave up: the rest is one piece, least exit at every node
    pieces.push_back({a, 1, -1});
  }

  // What the outer rule compares: the exits of the pieces, in order.
  std::vector<int> signature(int face, double b, const std::vector<int>& from) {
    std::vector<int> s;
    walk(line(face, b, from), pieces_);
    for (const Piece& p : pieces_)  // pieces shorter than the roots' rounding are not part of it
      if (p.a1 - p.a0 > 1e-12 && (s.empty() || s.back() != p.exit)) s.push_back(p.exit);
    return s;
  }

  // ---- integrands ----

  // Adds the integrands at a of line l, times weight, into v; the exit is x, or the least when null.
  // Returns the cut that is the exit (kPlane, kSphere otherwise) and sets derivative to weight tau^2 d tau / d alpha.
  int add_node(const Face_line& l, double a, const Line_exit* x, double weight, Values& v, double& derivative) {
    const Vector3 p = l.at(a);
    const double p_norm = std::sqrt(l.s2 + a * a);
    if (!x) x = &l.table[least_slot(l, a)];
    double t = x->tau(a, p_norm);
    // A piece's exit that misses one of its rays: the walk placed a tie wrongly, as it may beside a cut of
    // a pair one ulp apart (tie quadratics with coefficients near 1e-31). The least exit is then taken.
    if (!(t < kInfinity)) x = &l.table[least_slot(l, a)], t = x->tau(a, p_norm);
    const int exit = x->k;
    ++rays_;
    const double distance = t * p_norm;
    // The box's planes bound every ray from a site inside it, and no candidate can bound one that they
    // miss: measure_cells would otherwise take in sites for ever.
    if (!(distance < kInfinity)) throw std::logic_error("integrate_cell: a ray from the site leaves the box");
    largest_exit_[l.face] = std::max(largest_exit_[l.face], distance);
    if (distance * (1 + kClearanceMargin) >= candidates_.clearance[l.face]) throw Clearance_exceeded();
    const double t2 = t * t, t3 = t2 * t;
    v[kVolume] += weight * t3 / 3;
    const int cut = exits_[exit].cut;
    derivative = 0;
    if (options_.median_integrals) {
      v[kDistance] += weight * t3 * t * p_norm / 4;
      const double g = weight * t3 / (3 * p_norm);
      v[kDirection] += g * p[0], v[kDirection + 1] += g * p[1], v[kDirection + 2] += g * p[2];
      const double radial = weight * t2 / (2 * p_norm), inverse_norm2 = 1 / (p_norm * p_norm);
      v[kHessian] += radial * (1 - p[0] * p[0] * inverse_norm2);
      v[kHessian + 1] += radial * (1 - p[1] * p[1] * inverse_norm2);
      v[kHessian + 2] += radial * (1 - p[2] * p[2] * inverse_norm2);
      v[kHessian + 3] -= radial * p[0] * p[1] * inverse_norm2;
      v[kHessian + 4] -= radial * p[0] * p[2] * inverse_norm2;
      v[kHessian + 5] -= radial * p[1] * p[2] * inverse_norm2;
    }
    if (cut >= 0) {
      const Radial_cut& c = candidates_.cuts[cut];
      const double denominator = x->denominator(a, p_norm);
      if (options_.median_integrals) derivative = weight * t2 * c.tau_derivative(p, p_norm, denominator);
      if (clipped_)  // the face's area element (cell_cubature.h)
        v[kFaceArea] += weight * t2 / p_norm * std::sqrt(2 * (distance + c.weight_step) * p_norm / denominator);
    } else if (cut == kSphere) {
      v[kSphereArea] += weight * exits_[exit].h * exits_[exit].h / (p_norm * p_norm * p_norm);
    }
    return cut;
  }

  // One piece of a line by Gauss-Kronrod 7/15, halved while its volume error estimate exceeds its share
  // of the inner budget. Without the median integrals (kMedian false) only the volume and the two areas
  // are summed: the other components are zero at every node.
  template <bool kMedian>
  void integrate_piece(const Face_line& l, double a0, double a1, int exit, int depth, Line_result& out) {
    constexpr int kCount = kMedian ? kComponents : 3, kControlledCount = kMedian ? kControlled : 3;
    // The n-th component summed: all of them, or the volume and the areas.
    constexpr auto component = [](int n) { return kMedian || n == 0 ? n : n == 1 ? kFaceArea : kSphereArea; };
    const double half = 0.5 * (a1 - a0), middle = 0.5 * (a0 + a1);
    const Line_exit* x = exit >= 0 ? &l.of(exit) : nullptr;
    // Graded toward an end near the exit's pole: there t grows like the inverse distance to the pole, and
    // the outermost node, 0.0086 of the half-width inside the end, sees none of it (a site 4 from its
    // neighbour's plane in a box 1e5 wide lost 3e-5 of its volume so, with estimates 1e-8). While t at an
    // end exceeds 4 times t at the middle, the piece is halved without a rule; each halving moves the
    // middle toward the end, and the pole lies beyond it, so this ends once the piece is about as wide as
    // the end's distance to the pole: log2(width / distance) halvings on that side, and none elsewhere.
    if (a1 - a0 > 1e-12 && depth < 60 && rays_ < kMaxRays) {
      const auto tau_at = [&](double a) {
        const double p_norm = std::sqrt(l.s2 + a * a);
        return (x ? *x : l.table[least_slot(l, a)]).tau(a, p_norm);
      };
      const double at_middle = tau_at(middle);
      rays_ += 3;
      if (at_middle < kInfinity && std::max(tau_at(a0), tau_at(a1)) > 4 * at_middle) {
        integrate_piece<kMedian>(l, a0, middle, exit, depth + 1, out);
        integrate_piece<kMedian>(l, middle, a1, exit, depth + 1, out);
        return;
      }
    }
    Values kronrod{}, gauss{};
    std::array<Cut_integral, 31> cuts;
    std::array<Errors, 31> controlled;
    std::size_t cut_count = 0;
    for (std::size_t k = 0; k < inner_.node.size(); ++k) {
      Values v{};
      double derivative;
      const int cut = add_node(l, middle + half * inner_.node[k], x, 1, v, derivative);
      if (cut >= 0)
        cuts[cut_count++] = {cut, half * inner_.kronrod[k] * derivative, half * inner_.kronrod[k] * v[kFaceArea], 0};
      for (int n = 0; n < kCount; ++n) {
        const int c = component(n);
        kronrod[c] += inner_.kronrod[k] * v[c], gauss[c] += inner_.gauss[k] * v[c];
      }
      for (int n = 0; n < kControlledCount; ++n) controlled[k][component(n)] = v[component(n)];
    }
    Errors error{};
    for (int n = 0; n < kControlledCount; ++n) {
      const int c = component(n);
      double resasc = 0;
      for (std::size_t k = 0; k < inner_.node.size(); ++k) resasc += inner_.kronrod[k] * std::fabs(controlled[k][c] - 0.5 * kronrod[c]);
      error[c] = kronrod_error(half * std::fabs(kronrod[c] - gauss[c]), half * resasc);
    }
    if (!within_budget(error, a1 - a0, kInnerShare) && depth < 16 && a1 - a0 > 1e-12) {
      if (rays_ < kMaxRays) {
        integrate_piece<kMedian>(l, a0, middle, exit, depth + 1, out);
        integrate_piece<kMedian>(l, middle, a1, exit, depth + 1, out);
        return;
      }
      reached_ = false;
    }
    for (int c = 0; c < kComponents; ++c) out.value[c] += half * kronrod[c];
    for (int c = 0; c < kControlled; ++c) out.error[c] += error[c];
    // Runs of one cut are merged, across pieces too; the piece's area error goes, whole, to each cut that
    // is an exit on it (one, but where the walk gave up).
    int errored = -1;  // the last cut given this piece's error
    for (std::size_t d = 0; d < cut_count; ++d) {
      if (!out.cuts.empty() && out.cuts.back().cut == cuts[d].cut) {
        out.cuts.back().derivative += cuts[d].derivative;
        out.cuts.back().area += cuts[d].area;
      } else {
        out.cuts.push_back(cuts[d]);
      }
      if (errored != cuts[d].cut) {
        out.cuts.back().area_error += error[kFaceArea];
        errored = cuts[d].cut;
      }
    }
  }

  // The integrals along the line at b: its pieces, each checked at its middle (the least exit there must
  // be the piece's, else the piece is integrated with the least exit at every node).
  Line_result integrate_line(int face, double b, const std::vector<int>& from) {
    const Face_line& l = line(face, b, from);
    walk(l, pieces_);
    Line_result result;
    for (const Piece& piece : pieces_) {
      int exit = piece.exit;
      if (exit >= 0) {
        const double a = 0.5 * (piece.a0 + piece.a1), p_norm = std::sqrt(l.s2 + a * a);
        double least;
        least_exit(l, a, p_norm, &least);
        if (least < l.of(exit).tau(a, p_norm) * (1 - 1e-12)) exit = -1;
      }
      if (exit >= 0 && exits_[exit].cut == kPlane && exits_[exit].axis != l.inner_axis)
        integrate_flat_piece(l, piece.a0, piece.a1, exits_[exit], result);
      else if (exit >= 0 && exits_[exit].cut == kSphere)
        integrate_sphere_piece(l, piece.a0, piece.a1, exits_[exit].h, result);
      else if (options_.median_integrals)
        integrate_piece<true>(l, piece.a0, piece.a1, exit, 0, result);
      else
        integrate_piece<false>(l, piece.a0, piece.a1, exit, 0, result);
    }
    return result;
  }

  // A piece whose exit is a plane of the box across the line (the face's own axis, or the outer one):
  // tau = h / p_m is a constant T there, and with P = |p| = sqrt(s2 + a^2), A = asinh(a / sqrt(s2)) the
  // integrals are closed forms: volume T^3 / 3 [a], distance T^4 / 4 [a P + s2 A] / 2, direction
  // T^3 / 3 (q [A] + e [P]), Hessian T^2 / 2 (I [A] - q q^T [a / (s2 P)] + (q e^T + e q^T) [1 / P]
  // - e e^T [A - a / P]), where p = q + a e. Exact but for rounding: no error estimate to add.
  void integrate_flat_piece(const Face_line& l, double a0, double a1, const Exit& plane, Line_result& out) {
    const double T = plane.h / l.q[plane.axis], s = std::sqrt(l.s2);
    const double P0 = std::sqrt(l.s2 + a0 * a0), P1 = std::sqrt(l.s2 + a1 * a1);
    const double farthest = T * std::max(P0, P1);
    largest_exit_[l.face] = std::max(largest_exit_[l.face], farthest);
    if (farthest * (1 + kClearanceMargin) >= candidates_.clearance[l.face]) throw Clearance_exceeded();
    rays_ += 2;
    const double dA = std::asinh(a1 / s) - std::asinh(a0 / s), dP = P1 - P0;
    const double T2 = T * T, T3 = T2 * T;
    out.value[kVolume] += T3 / 3 * (a1 - a0);
    out.value[kDistance] += T3 * T / 8 * (a1 * P1 - a0 * P0 + l.s2 * dA);
    Vector3 g;
    for (int c = 0; c < 3; ++c) g[c] = l.q[c] * dA;
    g[l.inner_axis] += dP;
    for (int c = 0; c < 3; ++c) out.value[kDirection + c] += T3 / 3 * g[c];
    const double qq = a1 / (l.s2 * P1) - a0 / (l.s2 * P0), qe = 1 / P1 - 1 / P0, ee = dA - (a1 / P1 - a0 / P0);
    Vector3 e{0, 0, 0};
    e[l.inner_axis] = 1;
    const auto entry = [&](int i, int j) {
      return 0.5 * T2 * ((i == j ? dA : 0.0) - l.q[i] * l.q[j] * qq + (l.q[i] * e[j] + e[i] * l.q[j]) * qe - e[i] * e[j] * ee);
    };
    out.value[kHessian] += entry(0, 0), out.value[kHessian + 1] += entry(1, 1), out.value[kHessian + 2] += entry(2, 2);
    out.value[kHessian + 3] += entry(0, 1), out.value[kHessian + 4] += entry(0, 2), out.value[kHessian + 5] += entry(1, 2);
  }

  // A piece whose exit is the clipping sphere: tau = R / P, P = |p| = sqrt(s2 + a^2), so every integrand
  // is R^k times a rational function of a and P, with closed-form antiderivatives [.] from a0 to a1:
  // volume R^3 / 3 [a / (s2 P)], distance R^4 / 4 [a / (s2 P)], sphere area R^2 [a / (s2 P)], direction
  // R^3 / 3 (q [a / (2 s2 P^2) + atan(a / s) / (2 s^3)] - e [1 / (2 P^2)]), Hessian R^2 / 2 (I [a / (s2 P)]
  // - q q^T [a (2 a^2 + 3 s2) / (3 s2^2 P^3)] + (q e^T + e q^T) [1 / (3 P^3)] - e e^T [a^3 / (3 s2 P^3)]),
  // where p = q + a e. Exact but for rounding: no error estimate to add.
  void integrate_sphere_piece(const Face_line& l, double a0, double a1, double R, Line_result& out) {
    const double s2 = l.s2, s = std::sqrt(s2);
    const double P0 = std::sqrt(s2 + a0 * a0), P1 = std::sqrt(s2 + a1 * a1);
    largest_exit_[l.face] = std::max(largest_exit_[l.face], R);
    if (R * (1 + kClearanceMargin) >= candidates_.clearance[l.face]) throw Clearance_exceeded();
    rays_ += 2;
    const double inverse_cube = a1 / (s2 * P1) - a0 / (s2 * P0);  // [a / (s2 P)] = int da / P^3
    const double R2 = R * R, R3 = R2 * R;
    out.value[kVolume] += R3 / 3 * inverse_cube;
    out.value[kDistance] += R3 * R / 4 * inverse_cube;
    out.value[kSphereArea] += R2 * inverse_cube;
    const double along_q = a1 / (2 * s2 * P1 * P1) - a0 / (2 * s2 * P0 * P0) +
                           (std::atan(a1 / s) - std::atan(a0 / s)) / (2 * s2 * s);  // int da / P^4
    const double along_e = 1 / (2 * P0 * P0) - 1 / (2 * P1 * P1);                    // int a da / P^4
    for (int c = 0; c < 3; ++c) out.value[kDirection + c] += R3 / 3 * l.q[c] * along_q;
    out.value[kDirection + l.inner_axis] += R3 / 3 * along_e;
    const auto fifth = [&](double a, double P) { return a * (2 * a * a + 3 * s2) / (3 * s2 * s2 * P * P * P); };
    const double qq = fifth(a1, P1) - fifth(a0, P0);                                      // int da / P^5
    const double qe = 1 / (3 * P0 * P0 * P0) - 1 / (3 * P1 * P1 * P1);                   // int a da / P^5
    const double ee = a1 * a1 * a1 / (3 * s2 * P1 * P1 * P1) - a0 * a0 * a0 / (3 * s2 * P0 * P0 * P0);  // int a^2 da / P^5
    Vector3 e{0, 0, 0};
    e[l.inner_axis] = 1;
    const auto entry = [&](int i, int j) {
      return 0.5 * R2 * ((i == j ? inverse_cube : 0.0) - l.q[i] * l.q[j] * qq - (l.q[i] * e[j] + e[i] * l.q[j]) * qe - e[i] * e[j] * ee);
    };
    out.value[kHessian] += entry(0, 0), out.value[kHessian + 1] += entry(1, 1), out.value[kHessian + 2] += entry(2, 2);
    out.value[kHessian + 3] += entry(0, 1), out.value[kHessian + 4] += entry(0, 2), out.value[kHessian + 5] += entry(1, 2);
  }

  // ---- the outer integral over b ----

  void accept(const Values& value, const Errors& error, const std::vector<Cut_integral>& cuts) {
    for (int c = 0; c < kComponents; ++c) total_[c] += value[c];
    for (int c = 0; c < kControlled; ++c) total_error_[c] += error[c];
    for (const Cut_integral& i : cuts) {
      derivative_total_[i.cut] += i.derivative;
      area_total_[i.cut] += i.area;
      area_error_total_[i.cut] += i.area_error;
    }
  }

  // Whether the errors of a panel (or inner piece) of the given width stay within share x its budget.
  bool within_budget(const Errors& e, double width, double share = 1) const {
    const double volume = share * volume_budget_ * width;
    return e[kVolume] <= volume && (!clipped_ || e[kFaceArea] + e[kSphereArea] <= share * area_budget_ * width) &&
           (!options_.median_integrals || (e[kDistance] <= share * distance_budget_ * width &&
                                           e[kDirection] + e[kDirection + 1] + e[kDirection + 2] <= volume));
  }

  // Gauss-Kronrod 15/31 over [l, r] in s, b = l + (r - l)(3 s^2 - 2 s^3): the substitution's derivative
  // vanishes at both ends, which turns the (b - b*)^(1/2) and ^(3/2) behaviour at a located event into
  // smooth functions of s.
  bool panel(int face, double l, double r, bool force, const std::vector<int>& from) {
    throw_if_cancelled(options_.cancellation);
    Values kronrod{}, gauss{};
    Errors inner{};
    std::array<Errors, 31> controlled{};
    std::vector<Cut_integral> cuts;
    for (std::size_t k = 0; k < outer_.node.size(); ++k) {
      const double s = 0.5 * (1 + outer_.node[k]);
      const double b = l + (r - l) * s * s * (3 - 2 * s), jacobian = 0.5 * (r - l) * 6 * s * (1 - s);
      if (jacobian == 0) continue;
      const Line_result line_result = integrate_line(face, b, from);
      for (int c = 0; c < kComponents; ++c) {
        kronrod[c] += outer_.kronrod[k] * jacobian * line_result.value[c];
        gauss[c] += outer_.gauss[k] * jacobian * line_result.value[c];
      }
      for (int c = 0; c < kControlled; ++c) controlled[k][c] = jacobian * line_result.value[c];
      for (int c = 0; c < kControlled; ++c) inner[c] += outer_.kronrod[k] * jacobian * line_result.error[c];
      for (const Cut_integral& i : line_result.cuts) {
        const double w = outer_.kronrod[k] * jacobian;
        cuts.push_back({i.cut, w * i.derivative, w * i.area, w * i.area_error});
        if (clipped_) {
          panel_kronrod_[i.cut] += w * i.area;
          panel_gauss_[i.cut] += outer_.gauss[k] * jacobian * i.area;
        }
      }
    }
    // Each face's outer error, |Kronrod - Gauss| of its own area (without QUADPACK's scaling).
    if (clipped_) {
      const std::size_t lines = cuts.size();
      for (std::size_t n = 0; n < lines; ++n) {
        const int cut = cuts[n].cut;
        if (panel_kronrod_[cut] == 0 && panel_gauss_[cut] == 0) continue;
        cuts.push_back({cut, 0, 0, std::fabs(panel_kronrod_[cut] - panel_gauss_[cut])});
        panel_kronrod_[cut] = panel_gauss_[cut] = 0;
      }
    }
    Errors error;
    for (int c = 0; c < kControlled; ++c) {
      double resasc = 0;  // in units of the rule on [-1, 1], like kronrod and gauss here
      for (std::size_t k = 0; k < outer_.node.size(); ++k)
        resasc += outer_.kronrod[k] * std::fabs(controlled[k][c] - 0.5 * kronrod[c]);
      error[c] = kronrod_error(std::fabs(kronrod[c] - gauss[c]), resasc) + inner[c];
    }
    if (!force && !within_budget(error, r - l)) return false;
    if (!within_budget(error, r - l)) reached_ = false;
    accept(kronrod, error, cuts);
    return true;
  }

  // A bracket around an event: two-point Gauss, its error estimated by the variation across it, between
  // its nodes and between the lines at its ends (`ends`, at l and r), which a jump may leave on one side.
  void bracket(int face, double l, double r, const std::vector<int>& from, const Line_result (&ends)[2]) {
    throw_if_cancelled(options_.cancellation);
    const double half = 0.5 * (r - l), middle = 0.5 * (l + r), x = half / std::sqrt(3.0);
    const Line_result left = integrate_line(face, middle - x, from), right = integrate_line(face, middle + x, from);
    Values value;
    Errors error;
    for (int c = 0; c < kComponents; ++c) value[c] = half * (left.value[c] + right.value[c]);
    for (int c = 0; c < kControlled; ++c)
      error[c] = half * (std::fabs(left.value[c] - right.value[c]) + left.error[c] + right.error[c]) +
                 (r - l) * std::fabs(ends[0].value[c] - ends[1].value[c]);
    // Each face's error: its own variation across the bracket, and its lines' errors.
    std::vector<Cut_integral> cuts;
    for (const Line_result* side : {&left, &right})
      for (const Cut_integral& i : side->cuts) {
        cuts.push_back({i.cut, half * i.derivative, half * i.area, half * i.area_error});
        if (clipped_) panel_kronrod_[i.cut] += (side == &left ? half : -half) * i.area;
      }
    if (clipped_) {
      const std::size_t lines = cuts.size();
      for (std::size_t n = 0; n < lines; ++n) {
        const int cut = cuts[n].cut;
        if (panel_kronrod_[cut] == 0) continue;
        cuts.push_back({cut, 0, 0, std::fabs(panel_kronrod_[cut])});
        panel_kronrod_[cut] = 0;
      }
    }
    accept(value, error, cuts);
  }

  // [l, r] with the signatures at its ends. Where they differ, bisection on the signatures alone keeps
  // the left end's signature at lo and a different one at hi, down to a bracket of width event_width(): the
  // panel [l, lo] then has no event at either end, and the rest [hi, r] is treated alike. A smooth panel
  // whose estimate misses its budget is halved, which also uncovers events that left the signatures at
  // both ends equal.
  void interval(int face, double l, double r, const std::vector<int>& left, const std::vector<int>& right, int depth,
                const std::vector<int>& parent_live) {
    // The exits that can be least on the strip [-1, 1] x [l, r]: the lines there prune from these.
    std::vector<int> live;
    prune({face, -1, 1, l, r}, parent_live, live);
    if (left != right) {
      double lo = l, hi = r;
      std::vector<int> high = right, narrow = live;
      int step = 0;
      const auto bisect_to = [&](double width) {
        while (hi - lo > width) {
          if (++step % 4 == 0) {
            const std::vector<int> wider = narrow;
            prune({face, -1, 1, lo, hi}, wider, narrow);
          }
          const double m = 0.5 * (lo + hi);
          if (!(m > lo && m < hi)) return;  // adjacent doubles
          std::vector<int> middle = signature(face, m, narrow);
          if (middle == left)
            lo = m;
          else
            hi = m, high = std::move(middle);
        }
      };
      bisect_to(event_width(options_.relative_tolerance));
      // The bracket's rule errs by its width times the jump of the line integrals across it: small at a
      // kink, the usual event, but a cut nearly through the site (sites one ulp apart) has its pole on the
      // face, and the line integrals jump there by a whole line's volume. The bracket then narrows until
      // width x jump is within 1% of the cell's volume budget (or to adjacent doubles).
      Line_result ends[2] = {integrate_line(face, lo, narrow), integrate_line(face, hi, narrow)};
      const double jump = std::fabs(ends[0].value[kVolume] - ends[1].value[kVolume]);
      if (jump * (hi - lo) > 0.12 * volume_budget_) {
        bisect_to(0.12 * volume_budget_ / jump);
        ends[0] = integrate_line(face, lo, narrow), ends[1] = integrate_line(face, hi, narrow);
      }
      if (lo > l) interval(face, l, lo, left, left, depth + 1, live);
      bracket(face, lo, hi, narrow, ends);
      if (hi < r) interval(face, hi, r, high, right, depth + 1, live);
      return;
    }
    if (panel(face, l, r, depth >= 60 || r - l < 1e-12 || ++panels_ > kMaxPanels || rays_ >= kMaxRays, live)) return;
    const double m = 0.5 * (l + r);
    const std::vector<int> middle = signature(face, m, live);
    interval(face, l, m, left, middle, depth + 1, live);
    interval(face, m, r, middle, right, depth + 1, live);
  }

  void integrate_face(int face) {
    std::vector<double> at;
    for (int k = 0; k <= kFaceSamples; ++k) at.push_back(-1 + 2.0 * k / kFaceSamples);
    // A plane of the box through the site, across the lines (p[m] = b): every line's exit jumps from 0 to
    // another at b = 0, a jump that bisection would only bracket (an error of its width times the jump),
    // so b = 0 ends intervals: the line there has the other side's exits, and the bracket of the event
    // lies on one side of it.
    const int across = (face / 2 + 2) % 3;
    for (const Exit& x : exits_)
      if (x.cut == kPlane && x.axis == across && x.h == 0) {
        if (!std::binary_search(at.begin(), at.end(), 0.0)) at.insert(std::upper_bound(at.begin(), at.end(), 0.0), 0.0);
        break;
      }
    std::vector<std::vector<int>> signatures;
    for (double b : at) signatures.push_back(signature(face, b, face_live_[face]));
    for (std::size_t k = 0; k + 1 < at.size(); ++k)
      interval(face, at[k], at[k + 1], signatures[k], signatures[k + 1], 0, face_live_[face]);
  }

  // Rough volume and distance integral (a midpoint rule over a few lines per face), which set the error
  // budgets: tolerance x each, spread evenly over the 6 faces' outer coordinate b in [-1, 1].
  void estimate_scales() {
    volume_budget_ = distance_budget_ = area_budget_ = kInfinity;
    double volume = 0, distance = 0, area = 0;
    constexpr int kLines = 4;
    for (int face = 0; face < 6; ++face)
      for (int k = 0; k < kLines; ++k) {
        const Line_result r = integrate_line(face, -1 + (2.0 * k + 1) / kLines, face_live_[face]);
        volume += r.value[kVolume] * 2.0 / kLines, distance += r.value[kDistance] * 2.0 / kLines;
        area += (r.value[kFaceArea] + r.value[kSphereArea]) * 2.0 / kLines;
      }
    const double tolerance = options_.relative_tolerance, tiny = std::numeric_limits<double>::min();
    volume_budget_ = std::max(tolerance * volume / 12, tiny);
    distance_budget_ = std::max(tolerance * distance / 12, tiny);
    if (clipped_) area_budget_ = std::max(tolerance * area / 12, tiny);
  }

  const Vector3 centre_;
  const Cut_candidates& candidates_;
  const Cell_cubature_options& options_;
  const Gauss_kronrod_rule inner_, outer_;
  std::vector<Exit> exits_;
  std::vector<Piece> pieces_;
  mutable Face_line line_;
  mutable std::vector<std::pair<double, double>> ranges_;
  std::array<std::vector<int>, 6> face_live_;  // the exits that can be the least somewhere on each face
  const bool clipped_;  // a clip radius: the sphere is an exit, and the areas are integrated
  Values total_{};
  Errors total_error_{};
  std::vector<double> derivative_total_, area_total_, area_error_total_;  // per cut
  std::vector<double> panel_kronrod_, panel_gauss_;  // per cut, zero between uses (panel(), bracket())
  double volume_budget_ = 0, distance_budget_ = 0, area_budget_ = kInfinity;
  std::array<double, 6> largest_exit_{0, 0, 0, 0, 0, 0};
  std::size_t rays_ = 0, panels_ = 0;
  bool reached_ = true;
};

}  // namespace

Axis_box box_beyond(const Site& site, double distance) {
  const double centre[3] = {site.x, site.y, site.z};
  Axis_box box;
  for (int a = 0; a < 3; ++a) {
    box.lo[a] = centre[a] - distance, box.hi[a] = centre[a] + distance;
    // The differences below are exact or round towards the true one, so the loops end within a few steps.
    while (centre[a] - box.lo[a] < distance) box.lo[a] = std::nextafter(box.lo[a], -kInfinity);
    while (box.hi[a] - centre[a] < distance) box.hi[a] = std::nextafter(box.hi[a], kInfinity);
  }
  return box;
}

Cell_cubature_result integrate_cell(const Site& site, const Cut_candidates& candidates, const Axis_box& box,
                                    const Cell_cubature_options& options) {
  if (!(options.clip_radius > 0)) throw std::invalid_argument("integrate_cell: the clip radius must be > 0");
  // A pair hidden in floating point only (numerator 0) would put a cut at t = 0 with no direction: the
  // lines' walks cannot take it, and no caller should pass one (contacts refuse such pairs first).
  for (const Radial_cut& cut : candidates.cuts)
    if (!(cut.numerator > 0) && !(cut.gap >= 2 * options.clip_radius))  // beyond a clip it never matters
      throw std::domain_error("integrate_cell: site " + std::to_string(cut.site) +
                              " is hidden by the cell's site in floating point only, not exactly");
  const double radius = options.clip_radius;
  if (std::isfinite(radius) && !options.median_integrals && options.exit_regions) {
    // The planes of the box must lie beyond the clip, where they are never the exit.
    const Vector3 x{site.x, site.y, site.z};
    bool beyond = true;
    for (int a = 0; a < 3; ++a) beyond = beyond && box.hi[a] - x[a] >= radius && x[a] - box.lo[a] >= radius;
    if (beyond)
      if (std::optional<Cell_measure> measure = integrate_clipped_cell(candidates, radius, options.relative_tolerance)) {
        Cell_cubature_result result;
        result.measure = std::move(*measure);
        result.largest_exit.fill(radius);
        return result;
      }
  }
  return Cell_integrator(site, candidates, box, options).run();
}

}  // namespace apollonius
