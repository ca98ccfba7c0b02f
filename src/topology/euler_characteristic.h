// The check of the whole diagram that costs nothing (docs/design.md, "Euler"): the compactly supported
// Euler characteristic of R^3 is -1, and the diagram's open cells (vertices, edges, faces, cells) add up
// to it: 1 + V - E' + sum over faces (1 - holes) - C = 0, where E' leaves out the closed edges with no
// vertex (circles: characteristic 0), a face's holes are its closed boundary components less one if it
// is bounded, and C counts the cells.
#pragma once

#include "topology/topology.h"

namespace apollonius {

// 1 + V - E' + sum (1 - holes) - C, which is 0 for a correct diagram.
long euler_defect(const Diagram_topology& t);

}  // namespace apollonius
