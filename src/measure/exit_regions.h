// A clipped cell's volume, face areas and sphere area by integrals along the boundaries of its regions of
// one exit: the fast path of cell_cubature.h for contacts. APPROXIMATE, with an error estimate.
//
// Regions. Along the unit direction u from site i, site j cuts at t = c / (2 (alpha - u.D)) (radial_cut.h),
// so 1 / t = L_j(u) = a_j + b_j.u is affine in u: a_j = 2 alpha / c, b_j = -2 D / c. The clipping sphere
// has L = 1 / R. The cell's exit is 1 / max_k L_k(u), and the directions whose exit is k form
// Omega_k = {u on S^2 : L_k(u) >= L_m(u) for every m}: the sphere cut by the planes L_k = L_m, a region
// bounded by arcs of circles (a power diagram restricted to the sphere of directions).
//
// Integrals. On the region of cut j every integrand depends on u only through s = u.N, N = b_j / |b_j|
// (towards site j: the face is a surface of revolution about that axis). In spherical coordinates (theta,
// phi) about N, with G(theta) the integral of g(cos theta') sin theta' from 0 to theta, Stokes' theorem
// gives: integral over Omega of g dOmega = integral along the boundary of Omega of G dphi. G(0) = 0 keeps
// the form smooth at N, and -N is outside Omega_j (L_j(-N) = -2 / (|D| + alpha) < 0 < 1 / R), where it is
// singular. With v = L = a + b s (b = |b_j|), G = (1 - s) D(s), D a divided difference in closed form:
//   volume       g = v^-3 / 3:                         D = (2 a + b + b s) / (6 (a + b s)^2 (a + b)^2)
//   face area    g = 2 c^-1/2 v^-3 sqrt(1 + alpha v):  D = 2 c^-1/2 (H(a + b) - H(v)) / (a + b - v),
//                H(v) = -w (w^2 + 1) / (4 v^2) + alpha^2 / 8 ln((w + 1)^2 / (|alpha| v)), w = sqrt(1 + alpha v)
//                (its derivative is v^-3 w; the area element is cell_cubature.h's, in terms of L)
//   solid angle  g = 1:                                D = 1.
// Along an arc dphi = (x y' - y x') / (x^2 + y^2) dpsi, x, y the coordinates across N, and x^2 + y^2 =
// (1 - s)(1 + s), so the integrand D(s) (x y' - y x') / (1 + s) has no singularity at all on Omega_j.
// The sphere's region is the rest: solid angle 4 pi minus the cuts', times R^2 its area, R^3 / 3 its volume.
//
// Quadrature. Each arc by Gauss-Kronrod 7/15 in its angle, halved while its estimate exceeds 1e-3 of the
// tolerance (the integrands are analytic along an arc). Error estimate: the arcs' estimates; the
// uncertainty of each arc's ends (acos near a tangency) times the integrand there; and rounding, 64 unit
// roundoffs of the magnitudes summed (for the area, of the terms its closed form cancels), times the
// region's conditioning 1 + |b| R.
//
// Cost and termination: with k cuts within the clip, per region O(k) cap tests (no trigonometry), then
// for each of the k' caps that cross the clip's O(k') interval intersections, and the arcs' panels, at most
// 20,000 halvings per cell (beyond, panels are accepted with reached_tolerance false): O(k k'^2) plus
// O(20,000) per cell, every loop bounded. Degenerate inputs: circles equal to rounding are taken as one
// (three exits tied along a circle leave a region no interior); a cut whose |b| R exceeds 1e4 is refused.
#pragma once

#include <optional>
#include <stdexcept>

#include "measure/cell_measures.h"
#include "measure/cut_candidates.h"

namespace apollonius {

// Two balls too close for the measures in doubles: within about 1e-4 R of each other (R = w + P), neither
// hiding the other. Their face then passes within rounding of the site, where the inverse exit's gradient
// |b| = 2 |D| / c is beyond 1e4 / R.
struct Unmeasurable_pair : std::runtime_error {
  Unmeasurable_pair(Site_index a, Site_index b);
  Site_index a, b;  // a < b
};

// Whether `cut` is such a pair at this clip: |b| R = 2 |D| R / c > 1e4. Rounding errs by about 2,000
// roundoffs times |b| R (measured by fuzzing balls 3e-6 R apart), so at 1e4 by below 1e-8 of the value.
// Real structures never come near: atoms closer than 1e-4 of their radius are one atom.
bool too_close_to_measure(const Radial_cut& cut, double clip_radius);

// The measures of the cell of a site bounded by its candidates' cuts and the sphere of radius clip_radius
// about it: volume, sphere_area, contact_areas and their errors (the median integrals stay zero). Nothing
// when this method does not apply: a cut with a zero numerator (a pair hidden in floating point), a cut too
// close to measure, or a candidate clearance within the clip (cut_candidates.h).
std::optional<Cell_measure> integrate_clipped_cell(const Cut_candidates& candidates, double clip_radius,
                                                   double relative_tolerance);

}  // namespace apollonius
