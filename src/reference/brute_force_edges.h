// The edges of the diagram by brute force, the reference the topology layer is checked against: for every
// three active sites, the vertices of the diagram on their trisector in order along it, and every arc
// between consecutive ones (or to infinity, or the whole vertex-free curve) tested at one witness point
// against every site. An arc is an edge when no site is closer at its witness; the sites that tie there
// join its tie set, and it is reported from the three smallest. O(n^3) curves, O(n) per arc. Shares the
// predicates and the vertex list, not the topology layer's code.
#pragma once

#include <vector>

#include "diagram/diagram.h"
#include "topology/topology.h"

namespace apollonius {

// `diagram` must be the complete vertex diagram of `sites`. Sorted as Diagram_topology's edges.
std::vector<Diagram_edge> brute_force_edges(const std::vector<Site>& sites, const Diagram& diagram);

}  // namespace apollonius
