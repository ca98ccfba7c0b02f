// Cubature of one cell over the sphere of directions around its site. APPROXIMATE, with an error estimate.
//
// Geometry. The cell is star-shaped from its site x (paper Theorem 2), so it is {x + tau p : 0 <= tau <
// T(p)}, T the first exit along p: a cut (radial_cut.h) or a plane of the box. The directions p run over
// the six faces of the cube [-1, 1]^3 (the cubed sphere): on the face p[k] = +-1, p[k+1] = a, p[k+2] = b the
// volume element is tau^2 dtau da db exactly (|det(p, dp/da, dp/db)| = 1), so the volume is the integral
// over the faces of T^3 / 3, and the other measures are integrals of closed forms in T and p.
//
// Kinks. T is the least of several smooth exits, so the integrand has kinks along curves, which defeat
// plain adaptive cubature (it must refine along whole curves). But two exits tie where |p| A = p.V for a
// number A and a vector V (two cuts: A = c_j alpha_k - c_k alpha_j, V = c_j D_k - c_k D_j with
// c = |D|^2 - alpha^2; a cut and the plane p[m] tau = h: A = 2 h alpha_j, V = c_j e_m + 2 h D_j; two planes:
// A = 0, V = h_m e_n - h_n e_m), so along a line of fixed b the ties are the roots of a quadratic in a.
//
// Along a line every exit is tau(a) = N / (alpha |p| - e0 - e1 a) where that is positive (cell_cubature.cpp,
// Line_exit), tabulated once per line, so that a ray costs one division per exit and a tie one quadratic.
//
// Quadrature, nested. Inner, along each line of fixed b: the least exit and its breakpoints by a walk
// through those roots (a kinetic lower envelope), then Gauss-Kronrod 7/15 on each smooth piece, halved
// while its estimate is large. Outer, over b: the lines' sequences of exits change only at isolated
// events (a vertex of the cell, a tie curve tangent to the line direction, a curve leaving the face);
// events are bracketed by bisection on that sequence to a width w (the tolerance, within [1e-6, 1e-4]),
// narrower where the line integrals jump across it (a cut nearly through the site), and integrated by a
// two-point rule; between them the integrals are smooth in b but for (b - b*)^(1/2), ^(3/2) terms at the
// events, which the substitution b = l + (r - l)(3 s^2 - 2 s^3) smooths, and Gauss-Kronrod 15/31 in s
// integrates, halving a panel whose estimate misses its budget.
//
// Boundary areas (with a clip radius R). A face with site j is the radial graph t(u) of the cut, so its
// area element is t^2 dOmega / cos(theta), theta between the ray u and the face's normal u - u_j (u_j the
// unit vector from x_j): on the face |x - x_j| = t + alpha, so cos(theta) = sqrt((alpha - u.D) / (2 (t +
// alpha))), and with dOmega = da db / |p|^3 the element is tau^2 / |p| sqrt(2 (t + alpha) |p| / (alpha |p|
// - p.D)) da db; alpha - u.D = c / (2 t) >= c / (2 R) > 0 below the clip, so it stays bounded. The sphere's
// element is R^2 / |p|^3 da db. The sphere ties a cut where |p| (c - 2 R alpha) = -2 R p.D, and the plane
// p[m] tau = h where |p| h = p.(R e_m): the same form |p| A = p.V as the other ties.
//
// Error estimate. Per panel |Kronrod - Gauss| plus the inner estimates, per bracket its variation; summed,
// they must stay within tolerance x volume (volume, direction integral, whose norm is at most the volume)
// and tolerance x distance integral. This is an ESTIMATE of quadrature error in floating point, not a
// bound (an event both samples and rules miss goes unseen); the tests measure it against independent
// volumes (tests/measure). Rounding errors (about 1e-16 relative per ray) are far below any tolerance.
#pragma once

#include <limits>

#include "diagram/cancellation.h"
#include "measure/cell_measures.h"
#include "measure/cut_candidates.h"

namespace apollonius {

struct Cell_cubature_options {
  double relative_tolerance = 1e-8;
  // Finite: the cell is clipped by the ball of this radius about the site (contacts: d_i <= probe), and
  // the boundary areas are integrated and their errors controlled too (Cell_measure::contact_areas,
  // sphere_area). The box must then contain that ball.
  double clip_radius = std::numeric_limits<double>::infinity();
  const Cancellation* cancellation = nullptr;  // checked once per outer panel and bracket
  // False: only the volume and the boundary areas are integrated (contacts); the distance, direction and
  // Hessian integrals and the volume derivatives stay zero, which spares most of each ray's arithmetic.
  bool median_integrals = true;
  // Clipped and without the median integrals: integrate along the boundaries of the regions of one exit
  // (exit_regions.h) where that applies. False: always the line cubature below (the tests compare them).
  bool exit_regions = true;
};

struct Cell_cubature_result {
  Cell_measure measure;
  bool clearance_exceeded = false;          // some ray's exit reached its face's clearance: more candidates
  std::array<double, 6> largest_exit{};     // per face of the cubed sphere, the largest exit seen
};

// The box whose planes lie at least `distance` from the site's centre, exactly: centre -+ distance, rounded
// outwards (far from the origin, x + d may round back to x).
Axis_box box_beyond(const Site& site, double distance);

// The measures of the cell of `site` bounded by the candidates' cuts and the box (which contains the site).
// When clearance_exceeded, the measure is incomplete and must not be used.
Cell_cubature_result integrate_cell(const Site& site, const Cut_candidates& candidates, const Axis_box& box,
                                    const Cell_cubature_options& options);

}  // namespace apollonius
