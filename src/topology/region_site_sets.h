// The distinct site sets of the octree's region boxes (octree_diagram.h, Octree_regions), each with its
// boxes. Boxes with the same sites offer the vertex-free search (vertex_free.h) the same candidates, so it
// lists each set's once: on balls of one circle with mixed weights (1,000 of them) 3.1 million region
// boxes hold 3,303 distinct sets, and their 49 million (candidate, box) occurrences were sorted.
// Cost: O(b k) expected for b boxes of at most k sites (a hash table of the sets, one pass to group).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "diagram/cancellation.h"
#include "diagram/flat_lists.h"
#include "octree/octree_diagram.h"

namespace apollonius {

// Invariant: sets are numbered in the order of their first box; each box is in exactly one set's list, and
// each list is ascending. The same for every thread count, as the boxes' order is.
class Region_site_sets {
 public:
  using Boxes = Flat_lists<std::uint32_t>::Range<const std::uint32_t*>;

  // Precondition: fewer than 2^32 boxes. Checks cancellation every 4096 boxes.
  explicit Region_site_sets(const Octree_regions& regions, const Cancellation* cancellation = nullptr);

  std::size_t size() const { return first_box_.size(); }
  const Octree_regions::Sites& sites(std::size_t set) const { return regions_.boxes[first_box_[set]].sites; }
  Boxes boxes(std::size_t set) const { return boxes_[set]; }

 private:
  const Octree_regions& regions_;
  std::vector<std::uint32_t> first_box_;  // per set
  Flat_lists<std::uint32_t> boxes_;       // per set
};

}  // namespace apollonius
