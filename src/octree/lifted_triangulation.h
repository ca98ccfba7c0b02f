// Candidate quadruples from the regular triangulation of the sites lifted to R^4.
//
// Site i lifts to q_i = (p_i, w_i) in R^4 with power weight 2 w_i^2. For z = (x, t),
//     |x - p_i|^2 - (t + w_i)^2 = |x|^2 - t^2 - L_i(z),  L_i(z) = 2 x.p_i + 2 t w_i + w_i^2 - |p_i|^2,
// and |z - q_i|^2 - 2 w_i^2 = |z|^2 - L_i(z), so the power diagram of the lifts is the upper envelope of
// the L_i. Let x be a vertex of the Apollonius diagram of a set S of sites, none hidden (is_hidden.h), at
// distance t, with tie set T. Then L_i(z) = |x|^2 - t^2 for i in T, and L_j(z) < |x|^2 - t^2 for j in S
// outside T, i.e. |x - p_j| > |t + w_j|: where t + w_j >= 0 because |x - p_j| - w_j > t; where t + w_j < 0
// because otherwise, for i in T (t = |x - p_i| - w_i), |p_j - p_i| <= |x - p_j| + |x - p_i| <= w_i - w_j
// and ball j would lie in ball i. So z lies on the face of the power diagram whose maximisers are exactly T,
// dual to the cell conv{q_i : i in T} of the regular subdivision, with no condition on t. A vertex has
// lifts spanning 3 or more dimensions (lift_outside_span.h), so that cell holds a 3-simplex of any regular
// triangulation refining the subdivision, as CGAL's (symbolically perturbed) one does: four sites of T,
// affinely independent, of which x is a root. Hence every such vertex is a root of a quadruple spanning a
// 3-face of the triangulation: O(k) to O(k^2) quadruples for k sites instead of C(k, 4).
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "diagram/cancellation.h"
#include "predicates/site.h"

namespace apollonius {

// The regular triangulation of the lifts of a set of sites, as far as the far field needs it.
//
// Tie sets through its edges: a vertex z of the power diagram of the lifts lies in the cell of a site a iff
// L_a(z) >= L_j(z) for every neighbour j of a (a power cell is the intersection of the half-spaces of its
// facets, and each facet is shared with a neighbour; a triangulation refining the regular subdivision has
// every such edge). The sites tied at z span a cell of the regular subdivision, which the triangulation
// refines, so the edges among them connect them all. Lifts that are no vertex of the triangulation (hidden
// by the others, or repeating another) can still tie at z: they are listed apart.
struct Lifted_triangulation {
  static constexpr Site_index kNoSite = std::numeric_limits<Site_index>::max();
  std::vector<std::array<Site_index, 4>> quadruples;  // ascending, each once, each ascending
  // apexes[q]: the sites opposite quadruples[q] in the two full cells sharing it, kNoSite for an infinite
  // cell or where the lifts span only three dimensions (then the 3-faces are the full cells). The power
  // cells of the quadruple's sites meet along its line of roots between those two cells' power centres.
  std::vector<std::array<Site_index, 2>> apexes;
  std::vector<Site_index> sites;                      // the subset, ascending
  // neighbours[i]: the sites joined to sites[i] by an edge, ascending; empty for an unplaced site.
  std::vector<std::vector<Site_index>> neighbours;
  std::vector<Site_index> unplaced;  // sites of the subset that are no vertex, ascending
  // Only for sites of one weight, whose triangulation is Delaunay's (equal_weight_lifts.h), else empty:
  // across_facets[q] holds, for each facet of the cell quadruples[q] with a finite cell beyond it, that
  // cell's position in quadruples, its site opposite the facet, and whether that site lies on the
  // circumsphere of quadruples[q] (exactly: then both cells have one circumsphere); kNoCell for a facet on
  // the hull.
  static constexpr std::uint32_t kNoCell = std::numeric_limits<std::uint32_t>::max();
  struct Across_facet {
    std::uint32_t cell = kNoCell;
    Site_index site = kNoSite;
    bool same_sphere = false;
  };
  std::vector<std::array<Across_facet, 4>> across_facets;

  std::size_t position_of(Site_index s) const;                       // in sites; s must be one of them
  const std::vector<Site_index>& neighbours_of(Site_index s) const;  // s in sites
};

// The quadruples of the sites of `subset` spanning a 3-face of the regular triangulation of their lifts,
// with its edges. Exact: intervals, then Mpzf (lifted_triangulation.cpp, Power_weight_kernel). Cost:
// O(k log k) expected for the triangulation of k lifts in general position, plus its size.
Lifted_triangulation lifted_triangulation(const std::vector<Site>& sites, const std::vector<Site_index>& subset,
                                          const Cancellation* cancellation = nullptr);

}  // namespace apollonius
