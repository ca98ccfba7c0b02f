// The checks that run after every construction of the whole diagram (in the way of CDT and libigl): the
// edges are in their order (topology.h) with no two equal, each edge's ends hold its tie set, every vertex
// is an end of edges that hold each of its sites, each face boundary component is a closed cycle or an
// open chain from infinity to infinity along edges that hold the face's pair, and the Euler relation holds
// (euler_characteristic.h). A violation is a defect: std::logic_error, so that the command exits 3 and
// writes nothing.
#pragma once

#include "diagram/cancellation.h"
#include "topology/topology.h"

namespace apollonius {

// Checks cancellation (cancellation.h) once per 4096 edges, vertices or faces.
void validate_topology(const std::vector<Site>& sites, const Diagram_topology& topology,
                       const Cancellation* cancellation = nullptr);

}  // namespace apollonius
