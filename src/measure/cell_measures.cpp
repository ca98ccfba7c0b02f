#include "measure/cell_measures.h"

#include <algorithm>
#include <limits>
#include <optional>
#include <stdexcept>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "diagram/threads.h"
#include "measure/box_cell_regions.h"
#include "measure/cell_cubature.h"
#include "measure/cut_candidates.h"

namespace apollonius {

std::vector<Cell_measure> measure_cells(const std::vector<Site>& sites, const Diagram& diagram,
                                        const Axis_box& domain, const Measure_options& options) {
  if (diagram.site_count != sites.size()) throw std::invalid_argument("measure_cells: diagram of other sites");
  for (const Site& s : sites) {
    const Vector3 x{s.x, s.y, s.z};
    for (int a = 0; a < 3; ++a)
      if (!(domain.lo[a] <= x[a] && x[a] <= domain.hi[a]))
        throw std::invalid_argument("measure_cells: a site lies outside the domain");
  }
  std::vector<bool> active(sites.size(), true);
  for (const Hidden_site& h : diagram.hidden) active[h.site] = false;
  const std::vector<std::vector<Site_index>> neighbours = vertex_neighbours(diagram);
  // How far each cell reaches, guessed from its vertices (box_cell_regions.h): 1.25 times the farthest,
  // |v - x_i| = r + w_i. Infinity for a cell without a vertex.
  std::vector<double> reach_hint(sites.size(), 0.0);
  for (const Diagram_vertex& v : diagram.vertices)
    for (Site_index i : v.tie_set) reach_hint[i] = std::max(reach_hint[i], 1.25 * (v.rounded[3] + sites[i].w));
  for (double& hint : reach_hint)
    if (!(hint > 0)) hint = std::numeric_limits<double>::infinity();
  Cell_cubature_options cubature;
  cubature.relative_tolerance = options.relative_tolerance;
  cubature.cancellation = options.cancellation;

  std::vector<Cell_measure> measures(sites.size());
  tbb::task_arena arena(usable_threads(options.threads));
  arena.execute([&] {
    tbb::parallel_for(std::size_t{0}, sites.size(), [&](std::size_t i) {
      throw_if_cancelled(options.cancellation);  // a throw cancels the parallel loop
      if (!active[i]) return;
      if (options.exit_regions)
        if (std::optional<Cell_measure> m = integrate_box_cell(sites, active, static_cast<Site_index>(i), neighbours[i],
                                                               domain, options.relative_tolerance, reach_hint[i])) {
          measures[i] = std::move(*m);
          return;
        }
      // Start from the vertex neighbours; while some ray reaches its face's clearance, take in every site
      // that can come within 1.5 times the exits seen on some face. Terminates: each round takes in at
      // least the site that set the clearance that was reached, and there are finitely many.
      std::array<double, 6> reach{0, 0, 0, 0, 0, 0};
      for (;;) {
        const Cut_candidates candidates =
            cut_candidates(sites, active, static_cast<Site_index>(i), neighbours[i], reach, domain);
        Cell_cubature_result result = integrate_cell(sites[i], candidates, domain, cubature);
        if (!result.clearance_exceeded) {
          measures[i] = std::move(result.measure);
          return;
        }
        for (int f = 0; f < 6; ++f) {
          reach[f] = std::max(reach[f], 1.5 * result.largest_exit[f]);
          if (result.largest_exit[f] * (1 + kClearanceMargin) >= candidates.clearance[f])
            reach[f] = std::max(reach[f], candidates.clearance[f]);
        }
      }
    });
  });
  return measures;
}

}  // namespace apollonius
