// Which sites can cut the rays of a cell. The certified diagram proposes the sites that share a vertex
// with it; those are not always enough (faces without a vertex exist, and a cell's face with a neighbour
// may have all its vertices outside the box), so the proposal comes with clearances that make it provably
// sufficient along every ray actually evaluated:
//   a site j cuts the ray x_i + t u at t = c_j / (2 (alpha_j - u.D_j)) (radial_cut.h), and nowhere if
//   alpha_j <= u.D_j; over the rays of one face of the cubed sphere, that distance is at least
//   c_j / (2 (alpha_j - min u.D_j)) (direction_range.h). The clearance of a face is the least of these
//   over the sites left out: along a ray of that face whose computed exit t is below it, no site left out
//   cuts before t, so the exit is the true one (the cell is star-shaped from its site, paper Theorem 2).
// A ray that fails this sends the cell back with more candidates (cell_measures.cpp). Sites whose gap
// |D_j| - alpha_j exceeds twice the distance from the site to the farthest corner of the box are left out
// without a bound: they cannot beat i anywhere in the box (if j beats i at distance t, the gap is <= 2 t).
// The bounds are rounded: they are lowered by a relative margin, and so are the rays' exits compared.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "diagram/diagram.h"
#include "measure/radial_cut.h"
#include "predicates/axis_box.h"
#include "predicates/site.h"

namespace apollonius {

// For each site, the sites that share a vertex (a tie set) with it, ascending, hidden sites excluded.
std::vector<std::vector<Site_index>> vertex_neighbours(const Diagram& diagram);

// Invariant: every active site but i is in cuts or cuts no ray of face f nearer than clearance[f].
struct Cut_candidates {
  std::vector<Radial_cut> cuts;
  std::array<double, 6> clearance;  // per face of the cubed sphere; +infinity when nothing is left out
};

// The candidates of site i (inside `box`): `proposed`, and every active site whose cuts can come within
// reach[f] of the site on some face f; `active[j]` says whether site j is not hidden. O(n) per call.
Cut_candidates cut_candidates(const std::vector<Site>& sites, const std::vector<bool>& active, Site_index i,
                              const std::vector<Site_index>& proposed, const std::array<double, 6>& reach,
                              const Axis_box& box);

// The relative margin of the comparisons: an exit t is within the clearance when t (1 + margin) < it.
inline constexpr double kClearanceMargin = 1e-9;

}  // namespace apollonius
