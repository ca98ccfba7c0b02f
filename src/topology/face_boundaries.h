// The faces of the diagram from its edges (paper section 5.4). Along an edge with tie set T, the sites of
// T that are consecutive around it (all three pairs when |T| = 3; order_around_edge otherwise) each
// share a face, on that side of the edge: a half-edge (edge, pair). At a vertex, the half-edges of one
// pair bound the face's sectors there in twos (more than two only at a vertex of 5 or more tied sites:
// paired by their order on the sheet, sheet_fan.h), and a face's boundary goes from one to the other;
// walking so gives every boundary component, closed or an open chain between two ends at infinity.
#pragma once

#include <utility>
#include <vector>

#include "diagram/cancellation.h"
#include "topology/topology.h"

namespace apollonius {

// One boundary component of the faces of one pair: edge ids in order along it.
struct Boundary_component {
  Site_index a = 0, b = 0;
  std::vector<std::size_t> edges;
  bool closed = false;
};

// Every boundary component, by pair, then by first edge. Throws std::logic_error where the half-edges of
// a pair at a vertex cannot be paired: an odd number, or no edge there whose face side is decided at first
// order (a configuration this version does not decide: reported, never guessed). Checks cancellation
// (cancellation.h) once per edge, per vertex and pair, and per 4096 half-edges linked or walked from.
std::vector<Boundary_component> boundary_components(const std::vector<Site>& sites, const Diagram& diagram,
                                                    const std::vector<Diagram_edge>& edges,
                                                    const Cancellation* cancellation = nullptr);

}  // namespace apollonius
