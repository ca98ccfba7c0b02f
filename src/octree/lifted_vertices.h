// The vertices of a set of sites, none hidden, from the 3-faces of their lifted triangulation
// (lifted_triangulation.h): every vertex is a root of one of them, and the triangulation's edges decide it.
//
// A root v of a 3-face quadruple is a vertex iff no site is strictly closer; with no site hidden that is
// iff v's lift lies in the power cell of v's first site, and a power cell is cut out by the site's
// neighbours alone (and no unplaced lift reaches past it). The tie set is then that site with the unplaced
// sites that tie and those reached over edges between tied sites (the tied lifts span a cell of the
// regular subdivision, which the triangulation refines: its edges connect them).
//
// For sites of one weight the triangulation is Delaunay's (equal_weight_lifts.h), and the edges give way to
// the cells: a cell's circumsphere is empty, so its root is a vertex, and the sites tied there are those
// of the cells across facets on the same sphere, which the triangulation marks (tie_set_through_cells):
// no conflict test, where the edges of a vertex's four sites took about 34, and a sphere's cells are
// decided once per range.
//
// A root is first tested against the apexes of the 3-face's two full cells: the power cells of its sites
// meet along its line of roots only between those cells' power centres, so a root outside that edge of
// the power diagram is beaten by an apex. Only a certified NEGATIVE rejects, so this changes no answer;
// it rejects with two conflict tests most of the roots that are no vertex, where the neighbours took up
// to their degree (balls tangent to one sphere: about 140).
//
// Cost: the triangulation, O(k log k) expected for k lifts in general position, and for each of its Q
// 3-faces one vertices_of, two conflict tests per root, and O(degree + unplaced) more per vertex. A vertex of t > 4 tied sites is
// a root of up to C(t, 4) of the 3-faces; once decided it is remembered, and the later quadruples among its
// sites only name it (root_equal_to) instead of testing its t * degree sites again: O(Q + t * degree) for
// t balls tangent to one sphere, where testing every time cost O(Q t degree) (1,000 balls tangent to one
// circle: 9.4 s, then a fraction of a second).
#pragma once

#include <functional>
#include <vector>

#include "diagram/cancellation.h"
#include "octree/leaf_decision.h"
#include "octree/lifted_triangulation.h"
#include "predicates/site.h"
#include "predicates/vertex.h"

namespace apollonius {

// Every vertex of `lifts`' sites (none hidden) for which `wanted` holds, each once, with its tie set among
// them; in no particular order. A vertex of more than four tied sites, a root of several quadruples,
// comes from the least of them, whatever the thread count. `wanted` is called from several threads.
// Kernel: kernels.h. Checks cancellation (cancellation.h) at each quadruple.
template <class Kernel>
std::vector<Found_vertex> lifted_vertices(const std::vector<Site>& sites, const Lifted_triangulation& lifts,
                                          const std::function<bool(const Vertex&)>& wanted,
                                          const Cancellation* cancellation = nullptr);

}  // namespace apollonius
