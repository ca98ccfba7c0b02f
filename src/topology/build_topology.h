// The whole diagram from its vertices (paper sections 5.3-5.5): the edges that leave every vertex, paired
// along their curves, then the faces they bound and the cells.
#pragma once

#include "topology/topology.h"

namespace apollonius {

struct Topology_options {
  int threads = 1;
};

// The edges that have a vertex, from the complete vertex diagram of `sites` (octree_diagram or
// brute_force_diagram). Faces and cells are left empty: the edges with no vertex and the faces' nesting
// are the next steps (docs/design.md, "The whole diagram").
Diagram_topology build_edges(const std::vector<Site>& sites, Diagram diagram, const Topology_options& options = {});

// The faces and cells from the edges. Throws std::logic_error for what it does not decide yet: degenerate
// vertices where one pair's faces meet more than two edges, degenerate edges with no vertex.
void add_faces_and_cells(const std::vector<Site>& sites, Diagram_topology& topology);

}  // namespace apollonius
