#include "octree/tie_point_star.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "octree/lift_span.h"
#include "predicates/kernels.h"
#include "predicates/rounding_guard.h"

namespace apollonius {
namespace {

// Patches are refined at most this deep (squares of side 2^-15 of a face).
constexpr int kMaxStarDepth = 16;
// Levels without a removal before the lifts of the candidates left are looked at.
constexpr int kStarStagnation = 2;
// Past this many patches per candidate the star gives up (exact enumeration is the caller's fallback).
constexpr std::size_t kPatchesPerCandidate = 256;
// And past this many recorded quadruples per candidate: a patch at kMaxStarDepth records all C(m, 4) of its
// m survivors, which for hundreds of sites tied at v (concentric shells of 2,000 balls) held 270 MB, where
// the caller streams its enumeration.
constexpr std::size_t kQuadruplesPerCandidate = 256;
constexpr std::size_t kRecordedSites = 6;
constexpr std::size_t kWitnesses = 3;

Interval dot(const std::array<Interval, 3>& a, const std::array<Interval, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

}  // namespace

template <class Kernel>
bool Tie_point_star<Kernel>::quadruples_near(const Vertex& v, const Axis_box& box, const Site_index* candidates,
                                              std::size_t k, std::vector<std::array<Site_index, 4>>& quadruples) {
  quadruples.clear();
  candidates_ = candidates;
  quadruples_ = &quadruples;
  box_ = box;
  patches_ = 0;
  {
    Rounding_guard guard;
    const std::array<Interval, 4> p = v.point_interval();
    for (int a = 0; a < 3; ++a) tie_point_[a] = p[a];
    n_.resize(k);
    half_inverse_.resize(k);
    for (std::size_t c = 0; c < k; ++c) {
      const Site& s = sites_[candidates[c]];
      const std::array<Interval, 3> offset = {p[0] - Interval(s.x), p[1] - Interval(s.y), p[2] - Interval(s.z)};
      const Interval distance = CGAL::sqrt(dot(offset, offset));
      if (!(distance.inf() > 0)) return false;  // v may be a candidate's centre: no direction there
      for (int a = 0; a < 3; ++a) n_[c][a] = offset[a] / distance;
      half_inverse_[c] = Interval(1) / (Interval(2) * distance);
    }
    Interval reach(0);
    for (int a = 0; a < 3; ++a) {
      const Interval below = p[a] - Interval(box.lo[a]), above = Interval(box.hi[a]) - p[a];
      reach = Interval(std::max({reach.sup(), std::fabs(below.inf()), std::fabs(below.sup()), std::fabs(above.inf()),
                                 std::fabs(above.sup())}));
    }
    reach_ = reach.sup();
    if (!std::isfinite(reach_)) return false;
  }
  std::vector<std::size_t> all(k);
  std::iota(all.begin(), all.end(), std::size_t{0});
  for (int face = 0; face < 6; ++face)
    if (!refine({face / 2, face % 2 ? 1.0 : -1.0, -1, 1, -1, 1, 0, 0}, all)) return false;
  std::sort(quadruples.begin(), quadruples.end());
  quadruples.erase(std::unique(quadruples.begin(), quadruples.end()), quadruples.end());
  return true;
}

template <class Kernel>
bool Tie_point_star<Kernel>::refine(const Patch& p, const std::vector<std::size_t>& survivors) {
  if (++patches_ > kPatchesPerCandidate * n_.size()) return false;
  std::vector<std::size_t> kept = survivors;
  {
    Rounding_guard guard;
    std::array<Interval, 3> y;
    y[p.axis] = Interval(p.side);
    y[(p.axis + 1) % 3] = Interval(p.s0, p.s1);
    y[(p.axis + 2) % 3] = Interval(p.t0, p.t1);
    // A patch whose cone up to S misses the box holds no point of it.
    const Interval s(0, reach_);
    for (int a = 0; a < 3; ++a) {
      const Interval x = tie_point_[a] + s * y[a];
      if (x.sup() < box_.lo[a] || x.inf() > box_.hi[a]) return true;
    }
    const Interval reach_times_y_squared = Interval(reach_) * dot(y, y);
    // Witnesses: the survivors least in y.n at the patch's middle (doubles: only a choice).
    std::array<double, 3> middle;
    middle[p.axis] = p.side;
    middle[(p.axis + 1) % 3] = p.s0 + (p.s1 - p.s0) / 2;
    middle[(p.axis + 2) % 3] = p.t0 + (p.t1 - p.t0) / 2;
    std::vector<std::pair<double, std::size_t>> order;
    for (std::size_t c : kept) {
      double value = 0;
      for (int a = 0; a < 3; ++a) value += middle[a] * (n_[c][a].inf() + n_[c][a].sup()) / 2;
      order.push_back({value, c});
    }
    const std::size_t witnesses = std::min(order.size(), kWitnesses);
    std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(witnesses), order.end());
    for (std::size_t w = 0; w < witnesses && kept.size() > 3; ++w) {
      const std::size_t j = order[w].second;
      if (std::find(kept.begin(), kept.end(), j) == kept.end()) continue;
      const double curvature = (reach_times_y_squared * half_inverse_[j]).sup();
      std::size_t end = 0;
      for (std::size_t c : kept) {
        const std::array<Interval, 3> difference = {n_[c][0] - n_[j][0], n_[c][1] - n_[j][1], n_[c][2] - n_[j][2]};
        const bool beaten = c != j && (dot(y, difference) - Interval(curvature)).inf() > 0;
        if (!beaten) kept[end++] = c;
      }
      kept.resize(end);
    }
  }
  if (kept.size() <= 3) return true;
  if (kept.size() <= kRecordedSites) return record(kept);
  const int stagnant = kept.size() == survivors.size() ? p.stagnant + 1 : 0;
  if (stagnant >= kStarStagnation || p.depth >= kMaxStarDepth) {
    // Every survivor ties at v: spanning a 3-space, all their quadruples with roots share one line through
    // (v, r) and the polynomial on it, so their roots are v and at most one more point, a valid root of
    // the heaviest basis if of any of them (lift_span.h).
    std::vector<Site_index> sites(kept.size());
    for (std::size_t c = 0; c < kept.size(); ++c) sites[c] = candidates_[kept[c]];
    std::array<Site_index, 4> basis;
    const int dimension = heaviest_lift_basis<Kernel>(sites_, sites.begin(), sites.end(), basis);
    if (dimension <= 2) return true;
    if (dimension == 3) {
      quadruples_->push_back(basis);
      return true;
    }
    if (p.depth >= kMaxStarDepth) return record(kept);
  }
  const double sm = p.s0 + (p.s1 - p.s0) / 2, tm = p.t0 + (p.t1 - p.t0) / 2;
  for (int q = 0; q < 4; ++q) {
    const Patch child{p.axis, p.side, q & 1 ? sm : p.s0, q & 1 ? p.s1 : sm, q & 2 ? tm : p.t0, q & 2 ? p.t1 : tm,
                      p.depth + 1, stagnant};
    if (!refine(child, kept)) return false;
  }
  return true;
}

template <class Kernel>
bool Tie_point_star<Kernel>::record(const std::vector<std::size_t>& survivors) {
  const std::size_t k = survivors.size();
  const std::size_t count = k < 4 ? 0 : k * (k - 1) / 2 * (k - 2) / 3 * (k - 3) / 4;  // C(k, 4), exact at each step
  if (quadruples_->size() + count > kQuadruplesPerCandidate * n_.size()) return false;
  std::vector<Site_index> s;
  for (std::size_t c : survivors) s.push_back(candidates_[c]);
  std::sort(s.begin(), s.end());
  for (std::size_t a = 0; a < k; ++a)
    for (std::size_t b = a + 1; b < k; ++b)
      for (std::size_t c = b + 1; c < k; ++c)
        for (std::size_t d = c + 1; d < k; ++d) quadruples_->push_back({s[a], s[b], s[c], s[d]});
  return true;
}

template class Tie_point_star<Certified_kernel>;
template class Tie_point_star<Floating_kernel>;

}  // namespace apollonius
