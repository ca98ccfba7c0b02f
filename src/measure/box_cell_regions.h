// A cell clipped to a box, with the integrals of the geometric median, by the regions of one exit
// (exit_regions.h): the fast path of measure_cells for the centroidal diagrams. APPROXIMATE, with an error
// estimate.
//
// Exits. The cuts of the candidate sites and the six planes of the box: the plane at distance h along
// +-e_a has 1 / t = u_a / h, affine in u like a cut's (a = 0, b = +-e_a / h). The box bounds every ray, so
// the regions cover the sphere and none reaches the clip (L >= 0).
//
// Integrals, on the region of exit j in its frame (N = b / |b|, e1, e2), s = u.N, v = 1 / t = a + |b| s,
// with Top = a + |b| and the 1-form of Stokes' theorem as in exit_regions.h (G dphi, G = integral of g
// from s to 1, dphi = w / rho^2 dpsi along an arc, w = x y' - y x', rho^2 = x^2 + y^2 = (1 - s)(1 + s)):
//   volume         t^3 / 3:        G = (1 - s) (Top + v) / (6 v^2 Top^2)
//   distance       t^4 / 4:        G = (1 - s) (Top^2 + Top v + v^2) / (12 v^3 Top^3)
//   direction . N  s t^3 / 3:      G = (1 - s) (s Top + v) / (6 v^2 Top^2)
//   d m / d w_j    t^2 dt/dalpha:  G = -(2 / c) (1 - s) [(Top^2 + Top v + v^2) / (3 v^3 Top^3)
//                                       + alpha (Top + v) / (2 v^2 Top^2)]   (t^2 dt/dalpha = -2 (1 + alpha v) / (c v^4))
// The rest depend on phi too: direction . e1 = x t^3 / 3 = rho cos(phi) t^3 / 3, and the median Hessian
// (I - u u^T) t^2 / 2 has terms in rho cos(phi), rho sin(phi), rho^2 cos(2 phi), rho^2 sin(2 phi). For
// g = f(s) cos(k phi) the form is P(s) cos(k phi) dphi, P the integral of f from s to 1, and so on; P is a
// quadrature along the meridian from N in sigma, s' = 1 - (1 - s) sigma^2 (sigma in [0, 1]), where
// rho' = sqrt(1 - s) sigma sqrt(1 + s') is smooth and v is monotone, between Top and its value at the arc,
// both positive. The powers of rho that the forms divide by cancel with those of sqrt(1 - s) in closed
// form, so the forms stay smooth where the arc passes N.
//
// Candidates. The proposed sites (the vertex neighbours) give a cell; its farthest point from the site is
// on an arc (1 / L_j is largest where L_j is least, and the least of an affine function over a region is
// on its boundary, -N being outside), at T_max. A site k left out can matter only if its gap is below
// 2 T_max; such a k changes nothing if L_j - L_k > 0 over every region j (an affine function again: least
// on the arcs or at its critical point when inside the region). Otherwise k joins the candidates and the
// regions are found again: at most n rounds, each O(k^3) for k candidates (the regions' caps and arcs) plus
// O(n) for the gaps.
//
// Error estimate. The arcs' Gauss-Kronrod estimates, the meridians' (for the direction), the uncertain
// ends of arcs, and rounding of the magnitudes times the conditioning 1 + 16 |b| T_max, as exit_regions.h.
// The median Hessian and the volume derivatives have none (they only steer Newton's steps).
#pragma once

#include <limits>
#include <optional>
#include <vector>

#include "measure/cell_measures.h"
#include "predicates/axis_box.h"
#include "predicates/site.h"

namespace apollonius {

// The measures of the cell of sites[i] within `box` (which holds the site strictly inside), median
// integrals and volume derivatives included; `active[j]` says whether site j is not hidden, and `proposed`
// are the sites to start from (any; the vertex neighbours make it fast). Nothing when this method does
// not apply, and the line cubature (cell_cubature.h) must be used: a cut with a zero numerator (a pair
// hidden in floating point), a pair too close to measure at the cell's reach (exit_regions.h), a site on
// the box's boundary, or a region that rounding leaves unbounded. `reach_hint`: a guess at how far the
// cell reaches from its site (a wrong one costs time only; infinity: none).
std::optional<Cell_measure> integrate_box_cell(const std::vector<Site>& sites, const std::vector<bool>& active,
                                               Site_index i, const std::vector<Site_index>& proposed,
                                               const Axis_box& box, double relative_tolerance,
                                               double reach_hint = std::numeric_limits<double>::infinity());

}  // namespace apollonius
