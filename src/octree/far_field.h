// The vertices far outside the sites: those outside the octree's root box R.
//
// Their tie sets are among the escaping sites (those owning a point outside R, none hidden), and each is a
// root of a 3-face of the escaping sites' lifted triangulation (lifted_triangulation.h): O(E log E) for E
// escaping sites, even when hundreds of them tie at infinity to within an ulp (a lattice face), and
// whatever their weights
// (tests/data/regression/far_field_enumerated_39k_quadruples_of_34_escaping_sites_to_4e265.balls).
// The patches below give the sites owning each part of the far region, which the whole diagram's
// vertex-free search uses.
//
// R contains the ball of radius R about O. A point x outside R is x = O + r y with y on a face of the cube
// [-1, 1]^3 and r >= R / |y|. For a site w, x - p_w = r v with v = y - tau (p_w - O), tau = 1 / r in
// [0, |y| / R]. Since |x - p_i| >= e.(x - p_i) for the unit vector e = v / |v|,
//     d_i(x) - d_w(x) >= w_w - w_i + e.(p_w - p_i),
// so site i owns no point outside R in a cone of directions y where (w_w - w_i) |v| + v.(p_w - p_i) > 0
// for every v. Only differences p_w - p_i enter, so a small cluster far from O is separated as well as
// one at O. The far region is cut into patches: squares of directions on the faces of the cube times
// intervals of tau, halved in all three for the first levels (so that sites owning points only at finite
// distance, like a lattice face's lighter balls, leave the patches beyond them), then in the directions
// only. Refinement stops at 4 remaining sites or sites whose lifts span at most a plane (no vertex can lie
// among them), or at a maximum depth. All bounds use outward-rounded intervals.
#pragma once

#include <array>
#include <cstddef>
#include <utility>
#include <vector>

#include "diagram/cancellation.h"
#include "predicates/axis_box.h"
#include "octree/leaf_decision.h"

namespace apollonius {

struct Far_field_vertices {
  std::vector<Found_vertex> vertices;
  std::size_t quadruples = 0;  // distinct quadruples decided exactly
  // The sites kept on each patch where refinement ended, 2 or more, ascending and each set once: every
  // point outside R lies in some patch's cone, and its owners are among that patch's sites.
  std::vector<std::vector<Site_index>> patch_sites;
};

// Every vertex of the diagram outside the closed root box, with its tie set. Kernel: kernels.h. `escaping`
// must contain every site that owns a point outside the box and no hidden site (site_set.h), and the root
// box must contain the ball of radius `radius` about `origin`. patch_sites is filled when with_patch_sites holds (else it may stay
// empty). Checks cancellation (cancellation.h) at each patch and each quadruple.
template <class Kernel>
Far_field_vertices far_vertices(const std::vector<Site>& sites, const std::vector<Site_index>& escaping,
                                const std::array<double, 3>& origin, double radius, const Axis_box& root,
                                bool with_patch_sites, const Cancellation* cancellation = nullptr);

}  // namespace apollonius
