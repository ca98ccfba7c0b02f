// The whole diagram from its vertices (paper sections 5.3-5.5): the edges that leave every vertex, paired
// along their curves, then the faces they bound and the cells.
#pragma once

#include "topology/topology.h"

namespace apollonius {

struct Topology_options {
  int threads = 1;
};

// `diagram` must be the complete vertex diagram of `sites` (octree_diagram or brute_force_diagram).
Diagram_topology build_topology(const std::vector<Site>& sites, Diagram diagram, const Topology_options& options = {});

}  // namespace apollonius
