// The sites whose weighted distance d_s(x) = |x - c_s| - w_s may be at most a given reach at some point x of
// a box: the sites that may own, or tie at, a witness point known within that box. The whole diagram's
// vertex-free search uses it where there is no octree box to name those sites (the lifted fallback,
// octree_diagram.h step 5), so that each witness is tested against the sites near it, not against all.
#pragma once

#include <array>
#include <vector>

#include "diagram/site_tree.h"
#include "predicates/number_types.h"

namespace apollonius {

class Reaching_sites {
 public:
  // Cost O(n log n) for the n sites of `subset`.
  Reaching_sites(const std::vector<Site>& sites, std::vector<Site_index> subset);

  // Sets `out` to the sites of the subset, in no set order, for which d_s(x) <= reach may hold at some x of `box`
  // (bounds may be infinite). Certified: a site left out has d_s(x) > reach on the whole box (intervals
  // under a Rounding_guard). Cost: the nodes of the tree whose bound does not exclude them.
  void find(const std::array<Interval, 3>& box, double reach, std::vector<Site_index>& out) const;

 private:
  const std::vector<Site>& sites_;
  Site_tree tree_;
};

// An upper bound of d_s(x) = |x - c_s| - w_s over the box (possibly +infinity); under a Rounding_guard.
double weighted_distance_upper_bound(const std::array<Interval, 3>& box, const Site& s);

}  // namespace apollonius
