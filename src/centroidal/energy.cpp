#include "centroidal/energy.h"

#include <cmath>

#include "octree/octree_diagram.h"
#include "reference/brute_force_diagram.h"

namespace apollonius {

Energy_evaluation evaluate_energy(const std::vector<Site>& sites, const std::vector<double>& target_volumes,
                                  const Axis_box& domain, double quadrature_tolerance, int threads,
                                  const Cancellation* cancellation) {
  Energy_evaluation e;
  Octree_options octree;
  octree.threads = threads;
  octree.cancellation = cancellation;
  e.diagram = sites.size() <= 8 ? brute_force_diagram(sites) : octree_diagram(sites, octree);
  Measure_options options;
  options.relative_tolerance = quadrature_tolerance;
  options.threads = threads;
  options.cancellation = cancellation;
  e.measures = measure_cells(sites, e.diagram, domain, options);
  for (std::size_t i = 0; i < sites.size(); ++i) {
    const Cell_measure& m = e.measures[i];
    e.energy += m.distance_integral - sites[i].w * (m.volume - target_volumes[i]);
    e.energy_error += m.distance_error + std::fabs(sites[i].w) * m.volume_error;
  }
  return e;
}

}  // namespace apollonius
