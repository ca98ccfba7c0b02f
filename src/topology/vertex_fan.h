// The edges that leave a vertex (paper section 4.1, eqs. 25-28). For three sites T of the vertex's tie set
// S, the arc of T's trisector on one side of the vertex belongs to the diagram exactly when every other
// site of S is farther there (sides_near_vertex: exact, to second order) or ties along the whole curve,
// joining the edge's tie set; sites outside S are farther near the vertex anyway. A generic vertex
// (|S| = 4) has four edges, one per triple. For |S| = k <= kEveryTripleUpTo the enumeration costs O(k^3)
// triples, each dropped as soon as two sites disagree, at most k - 3 predicates each; larger tie sets offer
// only their star's triples (vertex_triples.h, departure_star.h).
#pragma once

#include <array>
#include <vector>

#include <boost/container/small_vector.hpp>

#include "diagram/diagram.h"
#include "predicates/trisector.h"
#include "topology/departure_star.h"

namespace apollonius {

// Invariants: triple is the three smallest sites of tie_set, which is ascending and lies in the vertex's.
struct Departure {
  using Sites = boost::container::small_vector<Site_index, 4>;  // inline: nearly every tie set has 3
  std::array<Site_index, 3> triple;
  Sites tie_set;
  int direction = 0;  // +1: the edge leaves forward along the triple's trisector (trisector.h); -1: backward
};

// The edges leaving v along `trisector`, the trisector of v.tie_set[i], v.tie_set[j], v.tie_set[l]
// (i < j < l), each once (from the smallest triple of its tie set): none, one or two, appended to out.
// With v's gradients (departure_star.h), a site's sides whose first order they tell for certain need no
// predicate: t = (n_j - n_i) x (n_l - n_i) is tangent to the curve at v, so d_s - r has the sign of
// t.(n_s - n_i) on one side and the opposite on the other; which side is forward, the first predicate
// answered to first order tells. Two sites of opposite certain signs end it at once. Where the first order
// is certainly 0 (n_s on the circle of the triple's n: balls tangent to one circle), the lifts 1 / |v - p_k|
// (tie_gradients) give the second order, the same on both sides. O(k) intervals, for the large tie sets whose
// departures run through all k sites.
void departures_along(const std::vector<Site>& sites, const Diagram_vertex& v, const Trisector& trisector,
                      const std::array<std::size_t, 3>& positions, std::vector<Departure>& out,
                      const Tie_gradients* gradients = nullptr, const std::vector<Interval>* lifts = nullptr);

}  // namespace apollonius
