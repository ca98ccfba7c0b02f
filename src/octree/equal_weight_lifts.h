// The lifted triangulation (lifted_triangulation.h) of sites of one weight: the Delaunay triangulation of
// their centres.
//
// With w_i = w for every site, the lifts q_i = (p_i, w) lie in the hyperplane t = w of R^4 and share the
// power weight 2 w^2, so their power diagram restricted to that hyperplane is the Voronoi diagram of the
// centres, and their regular triangulation spans three dimensions: a Delaunay triangulation of the
// centres, whose 3-faces are its cells (the Apollonius diagram of equal balls is the Voronoi diagram of
// their centres). CGAL's Delaunay_triangulation_3 builds one, breaking ties among cospherical centres by
// symbolic perturbation as the regular triangulation in R^4 does: any triangulation refining the Delaunay
// subdivision serves (lifted_triangulation.h). Its predicates, orientation and in-sphere, are exact
// (Epick: static and interval filters, then exact arithmetic), for centres anywhere in the double range.
// The in-sphere test (without perturbation) also says which cells across facets share a circumsphere.
// Cost: O(n log n) expected for n centres in general position, and four in-sphere tests per cell
// (docs/benchmarks.md, "Balls of one radius").
#pragma once

#include <vector>

#include "octree/lifted_triangulation.h"

namespace apollonius {

// Whether every site of `subset` has the weight of the first (exactly, as doubles).
bool has_one_weight(const std::vector<Site>& sites, const std::vector<Site_index>& subset);

// lifted_triangulation(sites, subset) for a subset of one weight (precondition: has_one_weight). A centre
// repeated within the subset is placed once, for its smallest index; the others are unplaced.
Lifted_triangulation equal_weight_lifted_triangulation(const std::vector<Site>& sites,
                                                       const std::vector<Site_index>& subset,
                                                       const Cancellation* cancellation = nullptr);

}  // namespace apollonius
