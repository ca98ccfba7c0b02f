// Vertex location by adaptive octree subdivision (paper section 5.2), with every decision exact.
//
//  1. Seed cubes: a grid over an aligned cube G holding every site centre. Sites propagate to neighbouring
//     grid cells in Dijkstra order (key: the least weighted distance to the cell); a site enters a cell
//     unless the cell's best site certainly dominates it there (predicate dominates_on_box).
//  2. Far field: the sites whose cells reach the boundary of G (the escaping sites) bound where vertices
//     outside G can be (far_field.h). The root cube R contains G and that bound.
//  3. Every cube of R is refined until it has at most 4 candidate sites, or cannot usefully be refined;
//     a leaf enumerates the quadruples of its candidates and keeps the vertices that lie in it (half-open).
//
// Completeness: a site owning a point x also owns the segment from its centre to x (cells are star-shaped,
// paper Theorem 2), so propagation through the 26 neighbours reaches every cell where it owns a point;
// removals are certified, so candidate sets are supersets of the owners; every vertex lies in exactly one
// half-open leaf, whose candidates include its whole tie set.
#pragma once

#include <optional>
#include <vector>

#include "axis_box.h"
#include "diagram.h"

namespace apollonius {

struct Octree_options {
  int threads = 1;
};

Diagram octree_diagram(const std::vector<Site>& sites, const Octree_options& options = {});

}  // namespace apollonius
