// The isolated points at equal weighted distance from every site of a claimed set (docs/design.md, "Algebra"): the
// candidates for the vertex a claim names. Decided by exact predicates only.
#pragma once

#include <vector>

#include "predicates/vertex.h"

namespace apollonius {

// Invariant: points is empty unless status is isolated, and then holds 1 or 2 points, each with a valid
// radius (r + w >= 0 for every site of the set) and tied exactly with every site of the set.
struct Equidistant_points {
  enum class Status {
    isolated,         // the set's isolated equidistant points are `points`
    rank_deficient,   // every 4 of the sites are rank-deficient or have a whole line of ties: no isolated point
    no_valid_root,    // 4 of the sites have no point with a valid radius, so the set has none
    not_equidistant,  // the points of 4 of the sites are not at the same distance from the others
  };
  Status status;
  std::vector<Vertex> points;
};

// set: 4 or more distinct site indices, ascending. The first quadruple of the set (in lexicographic
// order) whose equidistant set is discrete gives every candidate; the other sites must tie with them.
Equidistant_points equidistant_points(const std::vector<Site_index>& set, const std::vector<Site>& sites);

}  // namespace apollonius
