#include "measure/cut_candidates.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "predicates/unit_roundoff.h"

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
                              const std::vector<Site_index>& proposed, double reach) {
  Cut_candidates result{{}, std::numeric_limits<double>::infinity()};
  std::vector<bool> chosen(sites.size(), false);
  for (Site_index j : proposed)
    if (j != i && active[j]) chosen[j] = true;
  for (Site_index j = 0; j < sites.size(); ++j) {
    if (j == i || !active[j]) continue;
    const Radial_cut cut = Radial_cut::between(sites[i], sites[j], j);
    if (chosen[j] || cut.gap <= reach)
      result.cuts.push_back(cut);
    else  // the rounded gap is within 8 ulps of |D| + |alpha| of the exact one: 16 keep a lower bound
      result.clearance = std::min(result.clearance, cut.gap - 16 * kUnitRoundoff * (cut.gap + 2 * std::fabs(cut.weight_step)));
  }
  return result;
}

}  // namespace apollonius
