#include "topology/reaching_sites.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "predicates/rounding_guard.h"

namespace apollonius {

namespace {

// x as an interval, x possibly infinite (Interval's constructor from one double asserts a finite one).
Interval point(double x) { return Interval(x, x); }

}  // namespace

Reaching_sites::Reaching_sites(const std::vector<Site>& sites, std::vector<Site_index> subset)
    : sites_(sites), tree_(sites, std::move(subset)) {}

void Reaching_sites::find(const std::array<Interval, 3>& box, double reach, std::vector<Site_index>& out) const {
  out.clear();
  if (!(reach < std::numeric_limits<double>::infinity())) {  // no bound (an enclosure beyond the double range)
    out = tree_.order();
    return;
  }
  Rounding_guard guard;
  // Whether some centre in [lo, hi] with weight at most w can have d <= reach at a point of the box:
  // d >= |x - c| - w >= gap - w, where gap is a lower bound of the distance between the two boxes.
  const auto may_reach = [&](const std::array<double, 3>& lo, const std::array<double, 3>& hi, double w) {
    const Interval limit = point(reach) + Interval(w);  // gap > reach + w excludes the centres
    if (limit.sup() < 0) return false;
    Interval gap_squared(0);
    for (int a = 0; a < 3; ++a) {
      const double gap = std::max(
          {0.0, (Interval(lo[a]) - point(box[a].sup())).inf(), (point(box[a].inf()) - Interval(hi[a])).inf()});
      gap_squared += point(gap) * point(gap);
    }
    return !(gap_squared.inf() > (point(limit.sup()) * point(limit.sup())).sup());
  };
  thread_local std::vector<std::size_t> stack;
  tree_.search(may_reach,
               [&](Site_index s) {
                 const std::array<double, 3> c{sites_[s].x, sites_[s].y, sites_[s].z};
                 if (may_reach(c, c, sites_[s].w)) out.push_back(s);
               },
               stack);
}

double weighted_distance_upper_bound(const std::array<Interval, 3>& box, const Site& s) {
  Interval distance_squared(0);
  const double centre[3] = {s.x, s.y, s.z};
  for (int a = 0; a < 3; ++a) {
    const Interval d = box[a] - Interval(centre[a]);
    distance_squared += CGAL::square(d);
  }
  const double bound = (CGAL::sqrt(distance_squared) - Interval(s.w)).sup();
  return std::isnan(bound) ? std::numeric_limits<double>::infinity() : bound;
}

}  // namespace apollonius
