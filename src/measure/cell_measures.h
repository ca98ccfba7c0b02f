// Integrals over the cells of an Apollonius diagram clipped to a box: volumes, the integrals behind the
// geometric median, and the derivatives of the volumes in the weights. APPROXIMATE: each is a floating-point
// cubature over the sphere of directions around the site (cells are star-shaped from their sites, paper
// Theorem 2), with an ESTIMATE of its quadrature error (cell_cubature.h), not a bound. The diagram they integrate over, and which sites are hidden, are the
// certified ones.
#pragma once

#include <array>
#include <cstddef>
#include <utility>
#include <vector>

#include "diagram/cancellation.h"
#include "diagram/diagram.h"
#include "measure/radial_cut.h"
#include "predicates/axis_box.h"
#include "predicates/site.h"

namespace apollonius {

// The measures of one cell C_i (x_i its site), each with its error estimate where it has one.
// Invariant: all zero for a hidden site, whose cell has no interior.
struct Cell_measure {
  double volume = 0, volume_error = 0;                        // m_i = integral of 1 over C_i
  double distance_integral = 0, distance_error = 0;           // integral of |x - x_i| over C_i
  Vector3 direction_integral{0, 0, 0};                        // integral of (x - x_i) / |x - x_i|: zero iff x_i is
  double direction_error = 0;                                 //   the geometric median of C_i (error: of its norm)
  std::array<double, 6> median_hessian{0, 0, 0, 0, 0, 0};     // integral of (I - u u^T) / |x - x_i|, u the unit
                                                              //   vector: xx yy zz xy xz yz (no error estimate)
  std::vector<std::pair<Site_index, double>> volume_derivatives;  // d m_i / d w_j <= 0 for each j sharing a
                                                                  //   face with C_i (no error estimate);
                                                                  //   d m_i / d w_i is minus their sum
  // With a clip radius (cell_cubature.h) only: the area of the face with each site j (ascending, nonzero),
  // and of the clipping sphere inside the cell, each with its error estimate.
  struct Face_area {
    Site_index site;
    double area, error;
  };
  std::vector<Face_area> contact_areas;
  double sphere_area = 0, sphere_area_error = 0;
  std::size_t directions = 0;      // rays evaluated
  std::size_t cut_candidates = 0;  // sites whose cuts were evaluated on each ray
  bool reached_tolerance = true;   // false: a refinement limit was hit first (the errors say by how much)
};

struct Measure_options {
  double relative_tolerance = 1e-8;  // per cell: estimated errors <= tolerance x volume (x distance
                                     //   integral for it)
  int threads = 1;
  // True: each cell by the regions of one exit (box_cell_regions.h) where that applies; false: always the
  // line cubature (cell_cubature.h; the tests compare them).
  bool exit_regions = true;
  // When given, another thread may request it: measure_cells then throws Cancelled (it checks once per
  // cell) and returns nothing.
  const Cancellation* cancellation = nullptr;
};

// The measures of every cell of `diagram` (the certified diagram of `sites`) within `domain`, in site
// order. Preconditions: every site centre lies in the closed domain; diagram is the diagram of sites.
// The result is the same for every thread count.
std::vector<Cell_measure> measure_cells(const std::vector<Site>& sites, const Diagram& diagram,
                                        const Axis_box& domain, const Measure_options& options = {});

}  // namespace apollonius
