#include "measure/box_cell_regions.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <tuple>

#include "measure/exit_region_arcs.h"
#include "measure/exit_regions.h"
#include "measure/gauss_kronrod_rule.h"
#include "measure/orthonormal_frame.h"
#include "predicates/unit_roundoff.h"

namespace apollonius {
namespace {

// Components: volume, distance, direction (N, e1, e2) with errors controlled; then the Hessian in the
// region's frame (NN, N1, N2, 11, 22, 12) and d m / d w_j.
constexpr std::size_t kVolume = 0, kDistance = 1, kDirection = 2, kHessian = 5, kDerivative = 11;
constexpr std::size_t kComponents = 12, kControlled = 5;
using Node = Arc_node<kComponents, kControlled>;
using Sums = Arc_sums<kComponents, kControlled>;

// As in exit_regions.cpp: arc panels per cell at most, and the arcs' share of the tolerance.
constexpr std::size_t kMaxPanels = 20000;
constexpr double kArcShare = 1e-3;
// The meridians' share of the tolerance (relative to their own value), and their halvings at most.
constexpr double kMeridianShare = 1e-2;
constexpr int kMeridianDepth = 12;
// A site left out is taken in when L_j - L_k comes within this much (relative to the terms) of 0
// somewhere: taking in a site needlessly costs time only.
constexpr double kHarmlessMargin = 1e-9;

// The integrals along one meridian from N to the node (s' from s to 1), in sigma with s' = 1 - (1 - s) sigma^2,
// where rho' = sqrt(1 - s) sigma sqrt(1 + s') is smooth (box_cell_regions.h): the integrals over sigma in
// [0, 1] of sigma^2 sqrt(1 + s') f3, sigma^2 s' sqrt(1 + s') k, sigma^3 (1 + s') k and sigma (1 - rho'^2 / 2) k,
// f3 = v^-3 / 3, k = v^-2 / 2.
struct Meridian {
  std::array<double, 4> value{};
  double direction_error = 0;  // of value[0]
};

class Median_region {
 public:
  Median_region(const Inverse_exit& e, const Gauss_kronrod_rule& rule, double tolerance)
      : e_(e), rule_(rule), relative_(std::max(kMeridianShare * tolerance, 64 * kUnitRoundoff)) {
    beta_ = e.slope;
    axis_ = {e.b[0] / beta_, e.b[1] / beta_, e.b[2] / beta_};
    std::tie(across_x_, across_y_) = orthonormal_complement(axis_);
    top_ = e.a + beta_;
  }

  const Vector3& axis() const { return axis_; }
  const Vector3& across_x() const { return across_x_; }
  const Vector3& across_y() const { return across_y_; }

  Node operator()(const Cap& cap, double psi) const {
    Vector3 u, du;
    point_on_cap(cap, psi, u, du);
    const double x = dot(u, across_x_), y = dot(u, across_y_), s = dot(u, axis_);
    const double w = x * dot(du, across_y_) - y * dot(du, across_x_);
    const double turn = w / (1 + s);
    const double v = e_.a + beta_ * s, v2 = v * v, top2 = top_ * top_;
    const double cubic = (top2 + top_ * v + v2) / (v2 * v * top2 * top_);
    const double quadratic = (top_ + v) / (v2 * top2);
    Node node;
    node.value[kVolume] = quadratic / 6 * turn;
    node.value[kDistance] = cubic / 12 * turn;
    node.value[kDirection] = (s * top_ + v) / (6 * v2 * top2) * turn;
    if (e_.c > 0) node.value[kDerivative] = -2 / e_.c * (cubic / 3 + e_.alpha * quadratic / 2) * turn;
    if (x != 0 || y != 0) {
      Meridian m;
      meridian(s, 0, 1, 0, m);
      // The primitives over the powers of rho their forms carry (rho^2 = (1 - s)(1 + s)).
      const double root = std::sqrt(1 + s), over_rho3 = 2 / (root * root * root);
      const double direction = over_rho3 * m.value[0];           // P / rho^3
      const double slanted = over_rho3 * m.value[1];             // h1 / rho^3
      const double radial2 = 2 * (1 - s) * m.value[2] / (1 + s);  // h0 / rho^2
      const double radial4 = 2 * m.value[2] / ((1 + s) * (1 + s));  // h0 / rho^4
      const double isotropic = 2 * m.value[3] / (1 + s);         // h2 / rho^2
      const double difference = x * x - y * y;
      node.value[kDirection + 1] = x * w * direction;
      node.value[kDirection + 2] = y * w * direction;
      node.error[kDirection + 1] = std::fabs(x * w * over_rho3) * m.direction_error;
      node.error[kDirection + 2] = std::fabs(y * w * over_rho3) * m.direction_error;
      node.value[kHessian] = w * radial2;
      node.value[kHessian + 1] = -x * w * slanted;
      node.value[kHessian + 2] = -y * w * slanted;
      node.value[kHessian + 3] = w * (isotropic - difference * radial4 / 2);
      node.value[kHessian + 4] = w * (isotropic + difference * radial4 / 2);
      node.value[kHessian + 5] = -x * y * w * radial4;
    }
    for (std::size_t c = 0; c < kControlled; ++c) node.magnitude[c] = std::fabs(node.value[c]);
    return node;
  }

 private:
  // Gauss-Kronrod on [t0, t1] of sigma, halved while the direction's estimate exceeds its relative share.
  void meridian(double s, double t0, double t1, int depth, Meridian& sum) const {
    const double half = 0.5 * (t1 - t0), middle = 0.5 * (t0 + t1), one_minus_s = 1 - s;
    std::array<double, 4> kronrod{};
    double gauss = 0;
    for (std::size_t k = 0; k < rule_.node.size(); ++k) {
      const double sigma = middle + half * rule_.node[k], sigma2 = sigma * sigma;
      const double along = 1 - one_minus_s * sigma2, root = std::sqrt(1 + along);
      const double v = e_.a + beta_ * along, inverse2 = 1 / (v * v);
      const double f3 = inverse2 / (3 * v), k2 = inverse2 / 2;
      const double rho2 = one_minus_s * sigma2 * (1 + along);
      const double f[4] = {sigma2 * root * f3, sigma2 * along * root * k2, sigma2 * sigma * (1 + along) * k2,
                           sigma * (1 - rho2 / 2) * k2};
      for (int c = 0; c < 4; ++c) kronrod[c] += rule_.kronrod[k] * f[c];
      gauss += rule_.gauss[k] * f[0];
    }
    const double error = half * std::fabs(kronrod[0] - gauss);
    if (error > relative_ * half * std::fabs(kronrod[0]) && depth < kMeridianDepth) {
      meridian(s, t0, middle, depth + 1, sum);
      meridian(s, middle, t1, depth + 1, sum);
      return;
    }
    for (int c = 0; c < 4; ++c) sum.value[c] += half * kronrod[c];
    sum.direction_error += error;
  }

  Inverse_exit e_;
  const Gauss_kronrod_rule& rule_;
  double relative_;
  double beta_, top_;
  Vector3 axis_, across_x_, across_y_;
};

// Whether exit k beats exit j somewhere on the region of j (arcs), to within the margin.
bool beats_somewhere(const Inverse_exit& j, const Inverse_exit& k, const Exit_region_arcs& arcs) {
  const double da = j.a - k.a;
  const Vector3 db{j.b[0] - k.b[0], j.b[1] - k.b[1], j.b[2] - k.b[2]};
  const double norm = std::sqrt(dot(db, db));
  const double margin = kHarmlessMargin * (std::fabs(j.a) + j.slope + std::fabs(k.a) + k.slope);
  if (da - norm > margin) return false;  // L_j > L_k on the whole sphere
  if (arcs.least_along_arcs(da, db) <= margin) return true;
  if (norm == 0) return false;
  // The critical point -db / |db|, where L_j - L_k is least on the sphere: inside the region?
  const Vector3 lowest{-db[0] / norm, -db[1] / norm, -db[2] / norm};
  for (const Cap& cap : arcs.caps())
    if (dot(cap.m, lowest) < cap.h - kHarmlessMargin) return false;
  return true;
}

}  // namespace

std::optional<Cell_measure> integrate_box_cell(const std::vector<Site>& sites, const std::vector<bool>& active,
                                               Site_index i, const std::vector<Site_index>& proposed,
                                               const Axis_box& box, double relative_tolerance,
                                               double reach_hint) {
  const Site& site = sites[i];
  const Vector3 x{site.x, site.y, site.z};
  std::vector<Inverse_exit> planes;
  for (int a = 0; a < 3; ++a) {
    const double to_hi = box.hi[a] - x[a], to_lo = x[a] - box.lo[a];
    if (!(to_hi > 0 && to_lo > 0)) return std::nullopt;
    Inverse_exit plane{0, {0, 0, 0}, 1 / to_hi, 0, 0, kNoSite};
    plane.b[a] = 1 / to_hi;
    planes.push_back(plane);
    plane.b[a] = -1 / to_lo, plane.slope = 1 / to_lo;
    planes.push_back(plane);
  }
  std::vector<bool> candidate(sites.size(), false);
  std::vector<Radial_cut> cuts;
  const auto take = [&](Site_index j) {
    if (j == i || candidate[j] || !active[j]) return;
    candidate[j] = true;
    cuts.push_back(Radial_cut::between(site, sites[j], j));
  };
  for (Site_index j : proposed) take(j);

  // Reused from cell to cell by each thread: their vectors keep their capacity.
  thread_local std::vector<Inverse_exit> exits;
  thread_local std::vector<Exit_region_arcs> regions;
  thread_local std::vector<char> nonempty;
  double farthest = 0;  // T_max
  // The clip L >= 1 / clip_radius drops the exits that cannot come within it before their arcs are
  // sought (the cap tests of exit_region_arcs.cpp). A region that reaches the clip shows the cell
  // reaching beyond it: the radius doubles, up to none once it passes the box's farthest corner.
  double corner = 0;
  for (int a = 0; a < 3; ++a) corner += std::pow(std::max(box.hi[a] - x[a], x[a] - box.lo[a]), 2);
  corner = std::sqrt(corner);
  double clip_radius = reach_hint < corner ? reach_hint : std::numeric_limits<double>::infinity();
  for (;;) {
    exits = planes;
    for (const Radial_cut& cut : cuts) {
      if (!(cut.numerator > 0)) return std::nullopt;
      exits.push_back(inverse_exit(cut));
    }
    regions.resize(exits.size());
    nonempty.assign(exits.size(), 0);
    double least = std::numeric_limits<double>::infinity();
    bool reaches_clip = false;
    for (std::size_t j = 0; j < exits.size() && !reaches_clip; ++j) {
      if (!regions[j].find(exits, j, std::isfinite(clip_radius) ? 1 / clip_radius : 0)) continue;
      reaches_clip = regions[j].touches_clip();
      nonempty[j] = 1;
      least = std::min(least, regions[j].least_along_arcs(exits[j].a, exits[j].b));
    }
    if (reaches_clip) {
      if (!std::isfinite(clip_radius)) return std::nullopt;  // unbounded by rounding
      clip_radius = 2 * clip_radius < corner ? 2 * clip_radius : std::numeric_limits<double>::infinity();
      continue;
    }
    if (!(least > 0)) return std::nullopt;
    farthest = 1 / least;
    // Sites left out that come within reach, and beat some region somewhere.
    const std::size_t before = cuts.size();
    for (Site_index k = 0; k < sites.size(); ++k) {
      if (k == i || candidate[k] || !active[k]) continue;
      const Radial_cut cut = Radial_cut::between(site, sites[k], k);
      if (cut.gap >= 2 * farthest * (1 + kHarmlessMargin)) continue;  // beats i only beyond gap / 2
      if (!(cut.numerator > 0)) return std::nullopt;
      const Inverse_exit e = inverse_exit(cut);
      for (std::size_t j = 0; j < exits.size(); ++j)
        if (nonempty[j] && beats_somewhere(exits[j], e, regions[j])) {
          take(k);
          break;
        }
    }
    if (cuts.size() == before) break;
  }
  for (const Radial_cut& cut : cuts)
    if (too_close_to_measure(cut, farthest)) return std::nullopt;

  static const Gauss_kronrod_rule rule = make_gauss_kronrod_rule<15>();
  const double t3 = farthest * farthest * farthest;
  const std::array<double, kControlled> budget{kArcShare * relative_tolerance * t3,
                                               kArcShare * relative_tolerance * t3 * farthest,
                                               kArcShare * relative_tolerance * t3, kArcShare * relative_tolerance * t3,
                                               kArcShare * relative_tolerance * t3};
  std::size_t panels = 0;
  Cell_measure m;
  std::array<double, 6> hessian{};  // xx yy zz xy xz yz
  double volume_magnitude = 0, distance_magnitude = 0, direction_magnitude = 0;
  for (std::size_t j = 0; j < exits.size(); ++j) {
    if (!nonempty[j]) continue;
    const Median_region shape(exits[j], rule, relative_tolerance);
    Sums sums;
    for (const Exit_region_arcs::Region_arc& r : regions[j].arcs()) {
      const Cap& cap = regions[j].caps()[r.cap];
      integrate_arc(shape, cap, r.arc.begin, r.arc.end, rule, budget, kMaxPanels, panels, sums);
      const Node begin = shape(cap, r.arc.begin), end = shape(cap, r.arc.end);
      for (std::size_t c = 0; c < kControlled; ++c)
        sums.error[c] += std::fabs(begin.value[c]) * r.arc.begin_uncertainty +
                         std::fabs(end.value[c]) * r.arc.end_uncertainty;
    }
    const double condition = 1 + 16 * regions[j].steepest() * farthest;
    m.directions += sums.nodes;
    m.reached_tolerance = m.reached_tolerance && sums.reached;
    m.volume += sums.value[kVolume], m.volume_error += sums.error[kVolume];
    m.distance_integral += sums.value[kDistance], m.distance_error += sums.error[kDistance];
    volume_magnitude += condition * sums.magnitude[kVolume];
    distance_magnitude += condition * sums.magnitude[kDistance];
    // From the region's frame (N, e1, e2) to the world's.
    const std::array<Vector3, 3> frame{shape.axis(), shape.across_x(), shape.across_y()};
    for (int a = 0; a < 3; ++a) {
      m.direction_error += sums.error[kDirection + a];
      direction_magnitude += condition * sums.magnitude[kDirection + a];
      for (int k = 0; k < 3; ++k) m.direction_integral[k] += sums.value[kDirection + a] * frame[a][k];
    }
    // The symmetric frame matrix: NN N1 N2 11 22 12.
    const double h[3][3] = {{sums.value[kHessian], sums.value[kHessian + 1], sums.value[kHessian + 2]},
                            {sums.value[kHessian + 1], sums.value[kHessian + 3], sums.value[kHessian + 5]},
                            {sums.value[kHessian + 2], sums.value[kHessian + 5], sums.value[kHessian + 4]}};
    constexpr int kRow[6] = {0, 1, 2, 0, 0, 1}, kColumn[6] = {0, 1, 2, 1, 2, 2};
    for (int q = 0; q < 6; ++q)
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) hessian[q] += h[a][b] * frame[a][kRow[q]] * frame[b][kColumn[q]];
    if (exits[j].site != kNoSite && sums.value[kDerivative] != 0)
      m.volume_derivatives.push_back({exits[j].site, sums.value[kDerivative]});
  }
  m.volume_error += 64 * kUnitRoundoff * volume_magnitude;
  m.distance_error += 64 * kUnitRoundoff * distance_magnitude;
  m.direction_error += 64 * kUnitRoundoff * direction_magnitude;
  m.median_hessian = hessian;
  m.cut_candidates = cuts.size();
  std::sort(m.volume_derivatives.begin(), m.volume_derivatives.end());
  return m;
}

}  // namespace apollonius
