// Step 1 of the octree (paper section 5.2.1): the candidate sites of every seed box, propagated in
// Dijkstra order (key: a lower bound of the site's weighted distance over the box) from each site's home
// box to face neighbours. A site enters a box unless one of the box's best candidates certainly dominates
// it there (centre_expansion.h, then the exact predicate dominates_on_box); only a site that entered a box
// moves on to its neighbours.
//
// Completeness: a site owning a point x also owns the segment from its centre to x (cells are star-shaped,
// paper Theorem 2). The closed boxes that the segment crosses are linked through face neighbours that also
// contain a point of it (around a point, the boxes that contain it are connected through shared faces),
// and a site is never certainly dominated where it owns a point. So every site reaches every seed box in
// which it owns a point: each candidate list is a superset of the owners of its box.
#pragma once

#include <vector>

#include "seed_partition.h"

namespace apollonius {

// candidates[id] for every box identifier of the partition (empty for unused identifiers).
std::vector<std::vector<Site_index>> propagate_candidates(const std::vector<Site>& sites,
                                                          const std::vector<Site_index>& active,
                                                          const Seed_partition& partition);

}  // namespace apollonius
