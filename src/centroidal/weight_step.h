// The weight step of the centroidal loop: Newton's direction for the concave E4 at fixed sites, and the
// rule that accepts a step along it.
//
// Direction. The Hessian of E4 in the weights is -L, L the graph Laplacian of the cells whose edge weights
// are L_ij = -(d m_i / d w_j + d m_j / d w_i) / 2 >= 0 (the face integrals of 1 / |u_i - u_j|, symmetrised
// against quadrature noise; energy.h). Newton's step solves L delta = M - m; L's kernel is the constant
// vector (a common shift of the weights changes nothing), so one cell is pinned and delta is then shifted
// to mean zero. The cells of a partition of a connected box are connected by their faces, so the pinned L
// is positive definite while every cell has a volume.
//
// Acceptance (from s = 1, shortened by regula falsi on the slope). A step W' = W + s delta is accepted when
//   (a) no site is hidden in the certified diagram of W' and every cell keeps at least half of
//       min(1, min_i m_i(W) / M_i) of its target (the damping of Kitagawa, Merigot and Thibert, 2019, which
//       keeps the cells from vanishing), and either
//   (b) (M - m(W')) . delta >= -sum_i |delta_i| e_i(W'), e_i the volume's error estimate, or
//   (c) E4(W') - E4(W) >= max(c s (M - m(W)) . delta, E(W) + E(W')), with c = 1e-4 and E the energy's error
//       estimate: Armijo's sufficient increase, and beyond the quadrature error.
// Why E4 never decreases: under (b), E4 is concave along the segment from W to W', so its derivative there,
// (M - m) . delta, decreases along it; it is still >= 0 at W' up to quadrature error, hence >= 0 on the
// whole segment, and E4(W') >= E4(W) - s sum_i |delta_i| e_i. Under (c), by its comparison itself.
// Newton's full step usually overshoots the maximum along delta a little (E4 is not quadratic), which
// fails (b) but passes (c); (b) alone cost a refused trial, one more diagram and its measures, in most
// iterations.
#pragma once

#include <vector>

#include "measure/cell_measures.h"

namespace apollonius {

// Newton's direction for the weights from the measures at W and the target volumes (absolute). Cells
// without volume get 0.
std::vector<double> newton_weight_direction(const std::vector<Cell_measure>& measures,
                                            const std::vector<double>& target_volumes);

// (M - m) . delta and its quadrature uncertainty sum_i |delta_i| e_i, for the measures at W + s delta.
struct Directional_derivative {
  double value, uncertainty;
};
Directional_derivative directional_derivative(const std::vector<Cell_measure>& measures,
                                              const std::vector<double>& target_volumes,
                                              const std::vector<double>& direction);

}  // namespace apollonius
