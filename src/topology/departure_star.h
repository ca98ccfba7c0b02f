// The triples of a vertex's tie set along whose trisectors an edge may leave the vertex, from the star of
// directions at v, for tie sets too large to list every triple (balls tangent to one sphere: 1,000 sites
// tied at its centre are 166 million triples, and 2,000 or so edges).
//
// With n_k = (v - p_k) / |v - p_k|, the gradient of d_k at v, d_k(v + e) = d(v) + e.n_k + O(|e|^2). An edge
// of tie set E leaves v along the tangent t of its trisector, with E nearest along it, so to first order
// t.n_a = t.n_b <= t.n_j for a, b in E and j in the tie set: E's sites minimise y.n at y = t / |t|_inf, a
// point of the surface of [-1, 1]^3. A patch of directions (a square on a face of the cube) keeps every
// site that no other beats at each y of it (y.(n_c - n_j) > 0, certain in intervals), so E survives in
// every patch that contains y. Patches are refined until at most three sites survive. Where they stop
// dropping (sites whose n_k are cocircular tie to first order along the circle's axis) or at kMaxDepth,
// survivors that are exactly cocircular (sides_near_vertex) are separated by second order, in a star over
// their lifts (n_k, 1 / |v - p_k|), and those that tie to second order too and along a whole curve give that
// curve's smallest triple; any other survivors give every triple of theirs (the derivations are at
// settle_first_order_tie and settle_second_order_tie). A tie set whose n_k all lie on one circle goes to the
// second star at once. So each edge's smallest triple (from which departures_along counts it) is recorded:
// a superset of the departures, which departures_along then decides exactly. In general position the n_k's
// convex hull has about 2k facets, one per edge; on k balls tangent to one circle, all tied at its centre,
// the lifts' lower facets number about k.
//
// Termination: depth at most kMaxDepth, at most kPatchesPerSite patches and kTriplesPerSite recorded
// triples per site, past which it gives up and the caller lists every triple (exact, as for small sets).
#pragma once

#include <array>
#include <vector>

#include "diagram/diagram.h"
#include "predicates/number_types.h"

namespace apollonius {

// Per site of a tie set, in its order: an enclosure of n_k, the gradient of d_k at the vertex. Computed
// (and intervals used) only inside a Rounding_guard.
using Tie_gradients = std::vector<std::array<Interval, 3>>;

// Fills `gradients` (and, if given, `inverse_distances`, enclosures of 1 / |v - p_k|: the second order's
// lifts) for v and returns true; false when some enclosure is not finite or v may be a centre.
bool tie_gradients(const std::vector<Site>& sites, const Diagram_vertex& v, Tie_gradients& gradients,
                   std::vector<Interval>* inverse_distances = nullptr);

// Replaces `triples` with triples of v.tie_set (ascending, sorted, each once) that include every triple
// along which an edge leaves v, and returns true; or returns false when it gives up.
bool candidate_departure_triples(const std::vector<Site>& sites, const Diagram_vertex& v,
                                 std::vector<std::array<Site_index, 3>>& triples);

}  // namespace apollonius
