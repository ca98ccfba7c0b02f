// Step 2 of the octree (paper section 5.2.1): the candidate sites of every seed box, in two passes.
//  1. Each box keeps as its witnesses the four sites of least weighted distance at its centre, found by a
//     search in a tree of the sites (site_tree.h) where the paper propagates distances from the sites'
//     home boxes (which sites they are matters for speed only).
//  2. Each site floods from its home box through face neighbours, entering every box where no witness
//     certainly dominates it (centre_expansion.h); only a box it entered passes it on. The floods are
//     independent, so they run in parallel; the lists are sorted, so every thread count gives the same.
//
// Completeness: a site owning a point x also owns the segment from its centre to x (cells are star-shaped,
// paper Theorem 2). The closed boxes that the segment crosses are linked through face neighbours that also
// contain a point of it (around a point, the boxes that contain it are connected through shared faces),
// and a site is never certainly dominated where it owns a point. So every site reaches every seed box in
// which it owns a point: each candidate list is a superset of the owners of its box.
#pragma once

#include <vector>

#include "diagram/cancellation.h"
#include "octree/seed_partition.h"
#include "octree/work_budget.h"

namespace apollonius {

// candidates[id] for every box identifier of the partition (empty for unused identifiers). `slack`
// multiplies the rounding-error slack of the filters: 1 certified, 0 on the floating path (kernels.h).
// Checks cancellation (cancellation.h) every 4096 boxes of the graph and of pass 1, and before each site's
// flood. Each (box, site) pair a flood enters is spent from `budget` when given, after
// the site's flood (work_budget.h: throws Work_budget_exceeded past it).
std::vector<std::vector<Site_index>> propagate_candidates(const std::vector<Site>& sites,
                                                          const std::vector<Site_index>& active,
                                                          const Seed_partition& partition, double slack,
                                                          const Cancellation* cancellation = nullptr,
                                                          Work_budget* budget = nullptr);

}  // namespace apollonius
