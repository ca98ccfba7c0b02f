// Vertex location by adaptive octree subdivision (paper section 5.2), with every decision exact.
//
//  1. Seed cubes: a grid over a box G holding every site centre strictly inside. Sites propagate to
//     neighbouring grid cells in Dijkstra order (key: a lower bound of the weighted distance to the cell);
//     a site enters a cell unless the cell's best site certainly dominates it there (lipschitz_filter.h,
//     then predicate dominates_on_box).
//  2. Far field: the sites whose cells reach the boundary of G (the escaping sites) own every point outside
//     G. The root box R contains G and a ball 2 * 256 times G's half-extent; vertices beyond R are found by
//     the direction analysis of far_field.h.
//  3. Every box of R is refined until it has at most 6 candidate sites, or cannot usefully be refined;
//     a leaf enumerates the quadruples of its candidates and keeps the vertices that lie in it (half-open).
//
// Completeness: a site owning a point x also owns the segment from its centre to x (cells are star-shaped,
// paper Theorem 2), so propagation through the 26 neighbours reaches every cell where it owns a point, and
// a site owning a point outside G owns a point of a boundary cell; removals are certified, so candidate
// sets are supersets of the owners; every vertex of R lies in exactly one half-open leaf (the upper faces
// of R are closed), whose candidates include its whole tie set; every vertex outside R is found by
// far_field.h.
#pragma once

#include <optional>
#include <vector>

#include "axis_box.h"
#include "diagram.h"

namespace apollonius {

// What the computation did, for --stats: wall times of the phases and the sizes they worked on.
struct Octree_statistics {
  double partition_seconds = 0, propagation_seconds = 0, refinement_seconds = 0, far_field_seconds = 0,
         assembly_seconds = 0;
  std::size_t seed_boxes = 0, seed_candidates = 0, escaping_sites = 0, boxes = 0, leaves = 0, leaf_candidates = 0,
              quadruples = 0, distinct_quadruples = 0;
};

struct Octree_options {
  int threads = 1;
  Octree_statistics* statistics = nullptr;  // filled in when not null
};

Diagram octree_diagram(const std::vector<Site>& sites, const Octree_options& options = {});

}  // namespace apollonius
