// Another implementation's topology, a CLAIM that `certify` judges (judge_topology.h): the GPU codes'
// form, as `diagram --format topology` writes it: {"bisectors": [[a, b], ...], "trisectors": [[a, b, c],
// ...], "quadrisectors": [[a, b, c, d], ...]}, the tie sets of the faces, edges and vertices. Other
// members are ignored.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "predicates/site.h"

namespace apollonius {

// Invariant: sites ascending, distinct, each below the input's site count, as many as the category needs
// (a bisector 2, a trisector 3 or more, a quadrisector 4 or more).
struct Claimed_set {
  std::vector<Site_index> sites;
  std::size_t line;  // 1-based line where the set starts in its file
};

// One category of sets; present is false when the claim has no member for it (then it is not judged).
struct Claimed_category {
  bool present = false;
  std::vector<Claimed_set> sets;  // in the claim's order
};

enum class Topology_category { bisectors, trisectors, quadrisectors };
inline constexpr std::array<Topology_category, 3> topology_categories = {
    Topology_category::bisectors, Topology_category::trisectors, Topology_category::quadrisectors};
const char* name_of(Topology_category category);  // "bisectors", "trisectors", "quadrisectors"

// The fewest sites of a set of the category: a bisector has exactly 2.
inline std::size_t least_size(Topology_category category) {
  switch (category) {
    case Topology_category::bisectors: return 2;
    case Topology_category::trisectors: return 3;
    case Topology_category::quadrisectors: return 4;
  }
  return 0;
}

struct Claimed_topology {
  std::array<Claimed_category, 3> categories;  // indexed by Topology_category
  const Claimed_category& operator[](Topology_category c) const { return categories[static_cast<std::size_t>(c)]; }
};

// Reads a claimed topology for an input of site_count sites. Site indices may come in any order. Throws
// Input_error (name, line, reason) for anything malformed: not JSON, not an object, no category at all, a
// category or a set that is not an array, an index that is no integer or out of range, an index repeated
// in one set, a set of the wrong size.
Claimed_topology read_claimed_topology(const std::string& content, const std::string& name, std::size_t site_count);

}  // namespace apollonius
