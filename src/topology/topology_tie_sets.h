// The tie sets of the whole diagram's faces, edges and vertices: the form in which the GPU codes'
// topology experiments compare diagrams (`diagram --format topology`, `certify` of such a claim).
#pragma once

#include <vector>

#include "topology/topology.h"

namespace apollonius {

// Invariant: each list ascending (lexicographically), each set ascending and listed once; bisectors have
// 2 sites, trisectors 3 or more (a degenerate edge gives its whole tie set), quadrisectors 4 or more.
struct Topology_tie_sets {
  std::vector<std::vector<Site_index>> bisectors, trisectors, quadrisectors;
};

Topology_tie_sets topology_tie_sets(const Diagram_topology& topology);

}  // namespace apollonius
