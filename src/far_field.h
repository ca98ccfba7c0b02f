// The vertices far outside the sites: those outside the octree's root box.
//
// For x = O + t u (|u| = 1) and a = p - O:  |x - p| = sqrt(s^2 + |a_perp|^2) with s = t - u.a, so for
// t >= 2|a|:  t - u.a <= |x - p| <= t - u.a + |a|^2 / t.  Hence, writing h_i(u) = u.a_i + w_i,
//     d_i(x) - d_j(x) >= h_j(u) - h_i(u) - |a_j|^2 / t,
// and if h_j - h_i >= m > 0 on a cone of directions, site i owns no point of that cone beyond
// t = max(2|a_i|, 2|a_j|, 2|a_j|^2 / m). The directions are cut into patches (squares on the faces of the
// cube [-1, 1]^3), and a site leaves a patch only when that distance is within the root box's inscribed
// ball. Refinement stops at 3 remaining sites (no vertex can lie in the patch's cone outside the root
// box) or at a maximum depth, where every vertex outside the root box in that cone has its tie set among
// the remaining sites: their quadruples are enumerated and decided exactly against the escaping sites.
// All bounds use outward-rounded intervals.
#pragma once

#include <array>
#include <utility>
#include <vector>

#include "axis_box.h"
#include "leaf_decision.h"

namespace apollonius {

// Every vertex of the diagram outside the closed root box, with its tie set. `escaping` must contain every
// site that owns a point outside the box, and the root box must contain the ball of radius `radius`
// about `origin`.
std::vector<Found_vertex> far_vertices(const std::vector<Site>& sites, const std::vector<Site_index>& escaping,
                                       const std::array<double, 3>& origin, double radius, const Axis_box& root);

}  // namespace apollonius
