#include "measure/exit_region_arcs.h"

#include <algorithm>
#include <limits>
#include <tuple>

#include "measure/orthonormal_frame.h"
#include "predicates/unit_roundoff.h"

namespace apollonius {
namespace {

// The cap tests that drop constraints leave this much (in cosines) for rounding: a constraint kept
// needlessly costs time, not accuracy (its arc is then empty).
constexpr double kCosineMargin = 1e-9;
// Two circles closer than this (in the terms of one's equation on the other) are taken as one.
constexpr double kConcentric = 64 * std::numeric_limits<double>::epsilon();

Vector3 cross(const Vector3& a, const Vector3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// Keeps the part of `arcs` within the circular interval [centre - half_width, centre + half_width], whose
// ends are uncertain by `uncertainty`.
void keep_within(std::vector<Arc>& arcs, double centre, double half_width, double uncertainty,
                 std::vector<Arc>& scratch) {
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

}  // namespace

bool Exit_region_arcs::add_cap(const Vector3& n, double d, double terms) {
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

bool Exit_region_arcs::find(const std::vector<Inverse_exit>& exits, std::size_t j, double inverse_clip) {
  caps_.clear();
  caps_.reserve(exits.size());
  arcs_.clear();
  touches_clip_ = false;
  const Inverse_exit& e = exits[j];
  steepest_ = e.slope;
  // The clip first: L_j >= 1 / R. Empty when the exit never comes within R.
  const double own = e.slope + std::fabs(e.a);
  if (!add_cap(e.b, inverse_clip - e.a, own + inverse_clip)) return false;
  caps_.front().clip = true;
  const Cap clip = caps_.front();
  for (std::size_t k = 0; k < exits.size(); ++k) {
    if (k == j) continue;
    const Inverse_exit& o = exits[k];
    const Vector3 n{e.b[0] - o.b[0], e.b[1] - o.b[1], e.b[2] - o.b[2]};
    const double d = o.a - e.a;
    const double norm = std::sqrt(dot(n, n));
    if (norm == 0) {  // parallel planes L_j - L_k = -d: all, nothing, or the same exit (lower index wins)
      if (d > 0 || (d == 0 && k < j)) return false;
      continue;
    }
    const double h = d / norm;
    if (h <= -1) continue;
    if (h >= 1) return false;
    const Vector3 m{n[0] / norm, n[1] / norm, n[2] / norm};
    // With gamma the angle between the caps' centres and r, r0 their angular radii (cos r = h, sin r =
    // rho): the clip's cap lies within this one when gamma + r0 <= r, and misses it when gamma >= r0 + r;
    // compared as cosines (no trigonometry), with a margin for rounding.
    const Vector3 normal = cross(m, clip.m);
    const double cos_between = dot(m, clip.m), sin_between = std::sqrt(dot(normal, normal));
    const double rho = std::sqrt((1 - h) * (1 + h));
    if (cos_between >= -clip.h && cos_between * clip.h - sin_between * clip.rho > h + kCosineMargin) continue;
    if (h >= -clip.h && cos_between < clip.h * h - clip.rho * rho - kCosineMargin) return false;
    add_cap(n, d, own + o.slope + std::fabs(o.a));
    steepest_ = std::max(steepest_, o.slope);
  }
  // The smallest caps first (the clip stays first): they are the likeliest to cut a circle away, which
  // ends the loop below early for the many caps that bound nothing. The region does not depend on it.
  std::sort(caps_.begin() + 1, caps_.end(), [](const Cap& p, const Cap& q) { return p.h > q.h; });
  for (std::size_t q = 0; q < caps_.size(); ++q) {
    const Cap& cap = caps_[q];
    cap_arcs_.assign(1, Arc{0, kTwoPi, 0, 0});
    for (std::size_t l = 0; l < caps_.size() && !cap_arcs_.empty(); ++l) {
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
          if (C > 0) cap_arcs_.clear();
          continue;
        }
        if (dot(other.m, cap.m) < 0) {
          arcs_.clear();
          touches_clip_ = false;
          return false;
        }
        if (l < q) cap_arcs_.clear();
        continue;
      }
      const double c = C / r;
      if (c <= -1) continue;
      if (c >= 1) {
        cap_arcs_.clear();
        break;
      }
      // c and the centre err by a few rounding errors over r; acos amplifies them by 1 / sin(half width),
      // up to sqrt(2 x error) where the circles are nearly tangent; the frames and the angles themselves
      // add some 32 rounding errors of a radian.
      const double c_error = 16 * kUnitRoundoff * (1 + std::fabs(C) + r) / r;
      const double half_width = std::acos(c), sine = std::sqrt((1 - c) * (1 + c));
      const double uncertainty = c_error / std::max(sine, std::sqrt(2 * c_error)) + c_error + 32 * kUnitRoundoff;
      keep_within(cap_arcs_, std::atan2(B, A), half_width, uncertainty, scratch_);
    }
    if (q == 0 && !cap_arcs_.empty()) touches_clip_ = true;
    for (const Arc& arc : cap_arcs_) {
      Region_arc r{q, arc, {}, {}};
      Vector3 tangent;
      point_on_cap(cap, arc.begin, r.first, tangent);
      point_on_cap(cap, arc.end, r.last, tangent);
      arcs_.push_back(r);
    }
  }
  return !arcs_.empty();
}

double Exit_region_arcs::least_along_arcs(double a, const Vector3& b) const {
  double least = std::numeric_limits<double>::infinity();
  for (const Region_arc& r : arcs_) {
    const Cap& cap = caps_[r.cap];
    // a + b.u(psi) = base + amplitude cos(psi - centre) on the circle.
    const double base = a + cap.h * dot(b, cap.m);
    const double b1 = cap.rho * dot(b, cap.e1), b2 = cap.rho * dot(b, cap.e2);
    const double amplitude = std::sqrt(b1 * b1 + b2 * b2);
    least = std::min({least, a + dot(b, r.first), a + dot(b, r.last)});
    double lowest = std::atan2(b2, b1) + kPi;  // where the cosine is -1
    lowest -= kTwoPi * std::floor(lowest / kTwoPi);
    if (lowest >= r.arc.begin && lowest <= r.arc.end) least = std::min(least, base - amplitude);
  }
  return least;
}

}  // namespace apollonius
