// The sites as octree_diagram hands them to Seed_partition and propagate_candidates
// (octree/octree_diagram.cpp): the active sites, scaled by normalizing_exponent, and the root box's
// far-field scale. Tests of those steps start from here.
#pragma once

#include <vector>

#include "diagram/scale_normalization.h"
#include "diagram/site_set.h"
#include "predicates/kernels.h"

namespace apollonius::testing {

// kFarFieldScale of octree_diagram.cpp.
constexpr double kOctreeFarFieldScale = 32;

// Invariant: active is ascending and indexes sites.
struct Octree_input {
  std::vector<Site> sites;         // the input, scaled by 2^-exponent
  std::vector<Site_index> active;  // the sites neither hidden nor duplicates
  int exponent = 0;
};

inline Octree_input octree_input(const std::vector<Site>& input) {
  Octree_input result;
  result.active = active_sites(input.size(), classify_hidden_sites<Certified_kernel>(input));
  result.exponent = normalizing_exponent(input, result.active);
  result.sites = result.exponent == 0 ? input : scaled_sites(input, result.exponent);
  return result;
}

}  // namespace apollonius::testing
