// Which sites can cut the rays of a cell. The certified diagram proposes the sites that share a vertex
// with it; those are not always enough (faces without a vertex exist, and a cell's face with a neighbour
// may have all its vertices outside the box), so the proposal comes with a clearance that makes it
// provably sufficient along every ray actually evaluated:
//   if j beats i at x = x_i + t u, then |x - x_j| - w_j <= t - w_i, so |x_i - x_j| <= t + |x - x_j|
//   <= 2 t + w_j - w_i: the gap |x_i - x_j| - (w_j - w_i) of j is at most 2 t.
// So along a ray whose computed exit t satisfies 2 t < clearance (the least gap of the sites left out),
// no site left out cuts before t, and the exit is the true one. A ray that fails this sends the cell back
// with more candidates (cell_cubature.h). The gaps and exits are rounded: the clearance is lowered by a
// bound on the gaps' rounding, and exits are compared with a relative margin.
#pragma once

#include <cstddef>
#include <vector>

#include "diagram/diagram.h"
#include "measure/radial_cut.h"
#include "predicates/site.h"

namespace apollonius {

// For each site, the sites that share a vertex (a tie set) with it, ascending, hidden sites excluded.
std::vector<std::vector<Site_index>> vertex_neighbours(const Diagram& diagram);

// Invariant: every active site but i is in cuts or has an exact gap >= clearance.
struct Cut_candidates {
  std::vector<Radial_cut> cuts;
  double clearance;  // +infinity when every other active site is a candidate
};

// The candidates of site i: `proposed` and every active site whose gap is at most reach (reach may be 0);
// `active[j]` says whether site j is not hidden. O(n) per call.
Cut_candidates cut_candidates(const std::vector<Site>& sites, const std::vector<bool>& active, Site_index i,
                              const std::vector<Site_index>& proposed, double reach);

// The margin by which a ray's exit must stay within the clearance: 2 t (1 + margin) < clearance.
inline constexpr double kClearanceMargin = 1e-9;

}  // namespace apollonius
