// The site step of the centroidal loop: each site moves toward the geometric median of its cell, the
// minimiser of f(c) = integral over C_i of |x - c| (paper section 7, line 4 of the loop).
//
// f is strictly convex with gradient -G(c), G(c) = integral of (x - c) / |x - c|, and Hessian
// H(c) = integral of (I - u u^T) / |x - c|, positive definite. At c = x_i both are integrals around the
// cell's own site, which the radial cubature computes smoothly (cell_measures.h), so the step is one
// Newton step for the median of the current cell: x_i + H^-1 G. The loop repeats it on the new diagram;
// at a fixed point G = 0, which is exactly "x_i is the geometric median of its cell". The residual
// |G| / m_i in [0, 1] (the mean unit vector from the site over its cell) is what the stopping rule tests.
#pragma once

#include <string>
#include <vector>

#include "measure/cell_measures.h"
#include "predicates/axis_box.h"

namespace apollonius {

struct Median_steps {
  std::vector<Vector3> step;         // per site; zero for a cell without volume
  std::vector<Site_index> shortened;  // sites whose step would have left the domain (the true median
                                      //   lies in the cell, so only the quadratic model can overshoot)
};

// Newton steps toward the medians. A step that would take its site out of the domain, or closer to the
// boundary than a tenth of its distance to it, is shortened to keep the site at least that far inside.
Median_steps median_steps(const std::vector<Site>& sites, const std::vector<Cell_measure>& measures,
                          const Axis_box& domain);

// The residual with its error estimate, (|G_i| + e_G) / m_i; 0 for a cell without volume.
double median_residual(const Cell_measure& m);

}  // namespace apollonius
