#include "measure/cut_candidates.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "measure/direction_range.h"

namespace apollonius {

std::vector<std::vector<Site_index>> vertex_neighbours(const Diagram& diagram) {
  std::vector<bool> hidden(diagram.site_count, false);
  for (const Hidden_site& h : diagram.hidden) hidden[h.site] = true;
  std::vector<std::vector<Site_index>> neighbours(diagram.site_count);
  for (const Diagram_vertex& v : diagram.vertices)
    for (Site_index a : v.tie_set)
      for (Site_index b : v.tie_set)
        if (a != b && !hidden[b]) neighbours[a].push_back(b);
  for (std::vector<Site_index>& list : neighbours) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return neighbours;
}

Cut_candidates cut_candidates(const std::vector<Site>& sites, const std::vector<bool>& active, Site_index i,
                              const std::vector<Site_index>& proposed, const std::array<double, 6>& reach,
                              const Axis_box& box) {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  Cut_candidates result;
  result.clearance.fill(kInfinity);
  const Site& s = sites[i];
  const double x[3] = {s.x, s.y, s.z};
  double farthest = 0;  // from the site to a corner of the box
  for (int corner = 0; corner < 8; ++corner) {
    double d2 = 0;
    for (int a = 0; a < 3; ++a) {
      const double d = ((corner >> a) & 1 ? box.hi[a] : box.lo[a]) - x[a];
      d2 += d * d;
    }
    farthest = std::max(farthest, std::sqrt(d2));
  }
  std::vector<bool> chosen(sites.size(), false);
  for (Site_index j : proposed)
    if (j != i && active[j]) chosen[j] = true;
  // The others by increasing gap: a cut is never nearer than half its gap (t = c / (2 (alpha - u.D)) >=
  // c / (2 (alpha + |D|)) = gap / 2), so once half the gap, lowered by twice the margin (rounding), is
  // beyond every face's reach and clearance, no later site is within reach or lowers a clearance that a
  // ray can reach. A ray of face f (|p_k| = 1 >= |p_m|) leaves the box within sqrt(3) times the distance
  // h to the box's plane across it, so a clearance beyond sqrt(3) h (with margins) is never reached:
  // every comparison of the cubature, and so every result, is the one all the per-face bounds would give,
  // at O(n log n) instead of six bounds per site.
  std::vector<Radial_cut> others;
  for (Site_index j = 0; j < sites.size(); ++j) {
    if (j == i || !active[j]) continue;
    const Radial_cut cut = Radial_cut::between(s, sites[j], j);
    if (chosen[j])
      result.cuts.push_back(cut);
    else if (cut.gap <= 2 * farthest * (1 + kClearanceMargin))  // else it beats i nowhere in the box
      others.push_back(cut);
  }
  std::sort(others.begin(), others.end(), [](const Radial_cut& x, const Radial_cut& y) { return x.gap < y.gap; });
  std::array<double, 6> unreachable;  // per face: no ray of the face comes this far within the box
  for (int f = 0; f < 6; ++f) {
    const int k = f / 2;
    unreachable[f] = std::sqrt(3.0) * (f % 2 == 0 ? box.hi[k] - x[k] : x[k] - box.lo[k]) * (1 + 4 * kClearanceMargin);
  }
  for (const Radial_cut& cut : others) {
    const double floor = 0.5 * cut.gap * (1 - 2 * kClearanceMargin);
    bool done = true;
    for (int f = 0; f < 6; ++f) done = done && floor > reach[f] && floor >= std::min(result.clearance[f], unreachable[f]);
    if (done) break;
    std::array<double, 6> nearest;
    bool within_reach = false;
    for (int f = 0; f < 6; ++f) {
      nearest[f] = cut_distance_range(cut, {f, -1, 1, -1, 1}).first * (1 - kClearanceMargin);
      within_reach = within_reach || nearest[f] <= reach[f];
    }
    if (within_reach) {
      result.cuts.push_back(cut);
    } else {
      for (int f = 0; f < 6; ++f) result.clearance[f] = std::min(result.clearance[f], nearest[f]);
    }
  }
  // In site order, as the callers expect of the proposal's order.
  std::sort(result.cuts.begin(), result.cuts.end(), [](const Radial_cut& x, const Radial_cut& y) { return x.site < y.site; });
  return result;
}

}  // namespace apollonius
