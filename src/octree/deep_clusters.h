// Whether the octree would refine through many more binades than the sites' spacing needs: a cluster of
// balls beside one ball far away, or sites from 1e-260 to 1e265 in one input. Its boxes grow with the
// binades between the sites' extent and their closest pairs (BALL_SMALL_10000 and one ball at 1e12: 906,148
// boxes, 36 s and 1.1 GB), where the lifted triangulation's cost does not depend on scale (5 s, 86 MB;
// docs/benchmarks.md, "Deep inputs go to the lifted triangulation").
//
// Only the choice between two exact algorithms depends on it, never their output: doubles and an estimate
// suffice. Cost: O(n log n), one sort.
#pragma once

#include <cstddef>
#include <vector>

#include "predicates/site.h"

namespace apollonius {

// Binades between the sites' extent and a pair's distance beyond which a pair counts as deep. Of the
// generated families and the benchmark inputs only wide-range has such pairs (n random points in a cube
// come within 2^-32 of its side of each other with probability about n^2 2^-94); a ball 1e4 away from
// BALL_SMALL_1000 already made the octree slower than the lifts: the threshold is conservative.
inline constexpr int kDeepBinades = 32;
// Deep pairs an input needs: a single close pair costs the octree a few boxes per binade, a cluster far more.
inline constexpr std::size_t kDeepPairs = 3;

// The number of pairs of active sites, consecutive in Morton order on a 2^21 grid over their extent, whose
// centres lie closer than 2^-kDeepBinades times that extent (Chebyshev distance), counted up to `enough`.
// Sites in one grid cell are consecutive, so a cluster far smaller than a cell gives its pairs.
std::size_t deep_pairs(const std::vector<Site>& sites, const std::vector<Site_index>& active, std::size_t enough);

inline bool has_deep_clusters(const std::vector<Site>& sites, const std::vector<Site_index>& active) {
  return deep_pairs(sites, active, kDeepPairs) >= kDeepPairs;
}

}  // namespace apollonius
