// The centroidal Apollonius diagram in a box (paper section 7): sites at the geometric medians of their
// cells, weights such that each cell holds its target volume, a stationary point of E4 (eq. 41, energy.h).
//
// The loop, one iteration:
//  1. Weight step at fixed sites: Newton's direction for the concave E4, halved until accepted
//     (weight_step.h: E4 never decreases, up to quadrature error).
//  2. Stop if, at the accepted weights, every cell's relative volume error |M_i - m_i| / M_i and every
//     median residual |G_i| / m_i (median_step.h), each plus its quadrature error estimate, are at most
//     the tolerance (the residuals: the median tolerance, when one is given).
//  3. Site step: one Newton step toward each cell's geometric median, halved while it would hide a site
//     or nearly empty a cell, shortened where it would leave the domain.
// Every diagram is the certified one; the integrals are cubatures (measure/cell_measures.h) whose
// tolerance follows the errors down to tolerance / 20, so that the stopping rule, which adds the
// estimates, can be met. Degenerate situations are handled and reported, never dropped: a site hidden by
// the input weights (all weights are then reset to 0, where every cell has a volume), a step that would
// leave the domain, a step that would hide a site or empty a cell, a weight step found nowhere.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "centroidal/centroidal_parameters.h"
#include "diagram/cancellation.h"
#include "predicates/axis_box.h"
#include "predicates/site.h"

namespace apollonius {

// One row of the history, at the end of an iteration.
struct Centroidal_iteration {
  int iteration;                  // 1-based
  double energy_before;           // E4 before the weight step (sites and weights of the iteration's start)
  double energy;                  // E4 after it (the state the stopping rule judged)
  double energy_error;            // the quadrature error estimates of the E4 values, added
  double mass_error;              // max_i (|M_i - m_i| + e_i) / M_i after the weight step
  double median_error;            // max_i (|G_i| + e_G) / m_i after the weight step
  double largest_move;            // the longest site step taken (0 on the last iteration when converged)
  int weight_retries;             // weight steps tried and refused before those accepted
  double seconds;                 // since the start
};

struct Centroidal_options {
  double tolerance = 1e-6;
  // Of the median residuals, when it differs from that of the volumes (say, volumes to 1e-4 and sites
  // within 1e-2 of their medians: capacity-constrained partitions that need the masses more than the
  // medians). Nothing: `tolerance`.
  std::optional<double> median_tolerance;
  int max_iterations = 100;
  int threads = 1;
  bool move_sites = true;  // false: only the weights (a capacity-constrained diagram of fixed sites)
  std::function<void(const Centroidal_iteration&)> on_iteration;  // called after each iteration
  std::function<void(const std::string&)> on_report;              // each degenerate situation, as it happens
  // When given, another thread may request it: the loop then throws Cancelled soon after (it checks once
  // per iteration, and its diagrams and cell measures check it: cancellation.h) and returns nothing.
  const Cancellation* cancellation = nullptr;
};

struct Centroidal_result {
  std::vector<Site> sites;  // the final centres and weights
  bool converged = false;
  std::vector<Centroidal_iteration> history;
  std::vector<std::string> reports;
  std::vector<double> volumes;  // of the final cells
  std::size_t evaluations = 0;  // diagrams and cubatures computed
};

// Target volumes as fractions of the domain's volume (positive, summing to 1 within 1e-9). Throws
// Centroidal_parameter_error on bad parameters (centroidal_parameters.h: the domain, the tolerance, the
// iterations, the sites and masses).
Centroidal_result centroidal_diagram(const std::vector<Site>& sites, const std::vector<double>& mass_fractions,
                                     const Axis_box& domain, const Centroidal_options& options = {});

}  // namespace apollonius
