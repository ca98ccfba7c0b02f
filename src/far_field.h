// The vertices far outside the sites: those outside the octree's root box.
//
// For x = O + t u (|u| = 1) and a = p - O, |x - p| = sqrt(s^2 + q) with s = t - u.a and q = |a|^2 - (u.a)^2.
// Hence |x - p| >= s always, and |x - p| <= s + q / (2 s) when s > 0. Writing h_k(u) = u.a_k + w_k,
//     d_i(x) - d_j(x) >= h_j(u) - h_i(u) - q_j / (2 (t - |a_j|))   for t > |a_j|,
// and if h_j - h_i >= m > 0 on a cone of directions, site i owns no point of that cone beyond
// t = |a_j| + q_j / (2 m). The directions are cut into patches (squares on the faces of the cube
// [-1, 1]^3), and a site leaves a patch only when that distance is within the root box's inscribed
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

// Every vertex of the diagram outside the closed root box, with its tie set. Kernel: kernels.h. `escaping` must contain every
// site that owns a point outside the box, and the root box must contain the ball of radius `radius`
// about `origin`.
template <class Kernel>
std::vector<Found_vertex> far_vertices(const std::vector<Site>& sites, const std::vector<Site_index>& escaping,
                                       const std::array<double, 3>& origin, double radius, const Axis_box& root);

}  // namespace apollonius
