// The energy E4 of the centroidal Apollonius diagram (paper eq. 41) and what it is computed from: the
// certified diagram of the sites and the measures of its cells in the domain (APPROXIMATE: cubature,
// measure/cell_measures.h, each with an error estimate).
//
//   E4(X, W) = sum_i [ integral over C_i of |x - x_i| - w_i (m_i - M_i) ] = integral over the domain of
//              min_i (|x - x_i| - w_i) + sum_i w_i M_i,
// a minimum of functions affine in W plus a linear term: concave in the weights, with gradient
// dE4/dw_i = M_i - m_i, and Hessian d^2 E4 / dw_i dw_j = -d m_i / d w_j (a negative graph Laplacian whose
// weights are the integrals over the faces of 1 / |u_i - u_j|).
#pragma once

#include <vector>

#include "diagram/cancellation.h"
#include "diagram/diagram.h"
#include "measure/cell_measures.h"

namespace apollonius {

// Invariant: measures[i] is the measure of the cell of sites[i] in the diagram's domain.
struct Energy_evaluation {
  Diagram diagram;
  std::vector<Cell_measure> measures;
  double energy = 0;        // E4
  double energy_error = 0;  // its error estimate: sum_i distance_error_i + |w_i| volume_error_i
};

// The certified diagram of `sites` (the brute-force reference below 9 sites, where it is the faster, else
// the octree), its measures in `domain` to the relative quadrature tolerance, and E4 for the target volumes
// (absolute, not fractions). Checks cancellation (cancellation.h) in the octree and per cell measured.
Energy_evaluation evaluate_energy(const std::vector<Site>& sites, const std::vector<double>& target_volumes,
                                  const Axis_box& domain, double quadrature_tolerance, int threads,
                                  const Cancellation* cancellation = nullptr);

}  // namespace apollonius
