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
  for (Site_index j = 0; j < sites.size(); ++j) {
    if (j == i || !active[j]) continue;
    const Radial_cut cut = Radial_cut::between(s, sites[j], j);
    if (chosen[j]) {
      result.cuts.push_back(cut);
      continue;
    }
    if (cut.gap > 2 * farthest * (1 + kClearanceMargin)) continue;  // beats i nowhere in the box
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
  return result;
}

}  // namespace apollonius
