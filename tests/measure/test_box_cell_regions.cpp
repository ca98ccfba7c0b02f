// The box cells by the regions of one exit (box_cell_regions.h) against the line cubature (cell_cubature.h),
// a different method (rays over the cubed sphere, min over the exits per ray): every measure of every cell
// of random inputs, within the two error estimates for the controlled ones. APOLLONIUS_BOX_REGION_SEEDS
// sets the inputs per family (default 12;
// the line cubature takes most of the time).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <random>
#include <string>

#include "measure/box_cell_regions.h"
#include "measure/cell_measures.h"
#include "measure/cut_candidates.h"
#include "octree/octree_diagram.h"

using namespace apollonius;

namespace {

int seeds() {
  const char* text = std::getenv("APOLLONIUS_BOX_REGION_SEEDS");
  return text ? std::atoi(text) : 12;
}

// Families: uniform centres with weights spread over [0, spread); equal weights; a cluster in a corner
// (long cells reaching the far walls); sites near the walls (planes steep in 1 / t).
std::vector<Site> family_sites(const std::string& family, std::mt19937_64& random, std::size_t n) {
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<Site> sites;
  for (std::size_t k = 0; k < n; ++k) {
    Site s{unit(random), unit(random), unit(random), 0};
    if (family == "weighted") s.w = 0.3 * unit(random) / std::cbrt(static_cast<double>(n));
    if (family == "cluster") s.x *= 0.3, s.y *= 0.3, s.z *= 0.3, s.w = 0.05 * unit(random);
    if (family == "walls")
      for (double* c : {&s.x, &s.y, &s.z})
        if (random() % 2 == 0) *c = random() % 2 == 0 ? 1e-3 * unit(random) + 1e-6 : 1 - 1e-3 * unit(random) - 1e-6;
    sites.push_back(s);
  }
  return sites;
}

double largest_magnitude(const std::array<double, 6>& h) {
  double m = 0;
  for (double x : h) m = std::max(m, std::fabs(x));
  return m;
}

}  // namespace

TEST_CASE("box cells by regions equal the line cubature: every measure, within the estimates") {
  const Axis_box box{{0, 0, 0}, {1, 1, 1}};
  std::size_t cells = 0, by_regions = 0, walls_by_lines = 0, unreached = 0;
  for (const std::string family : {"weighted", "equal", "cluster", "walls"})
    for (int seed = 0; seed < seeds(); ++seed) {
      std::mt19937_64 random(static_cast<std::uint64_t>(seed) * 7919 + family.size());
      const std::size_t n = 5 + static_cast<std::size_t>(random() % 56);
      const std::vector<Site> sites = family_sites(family, random, n);
      const Diagram diagram = octree_diagram(sites);
      Measure_options regions, lines;
      regions.relative_tolerance = lines.relative_tolerance = 1e-8;
      lines.exit_regions = false;
      const std::vector<Cell_measure> a = measure_cells(sites, diagram, box, regions);
      const std::vector<Cell_measure> b = measure_cells(sites, diagram, box, lines);
      std::vector<bool> active(n, true);
      for (const Hidden_site& h : diagram.hidden) active[h.site] = false;
      const std::vector<std::vector<Site_index>> neighbours = vertex_neighbours(diagram);
      for (std::size_t i = 0; i < n; ++i) {
        CAPTURE(family);
        CAPTURE(seed);
        CAPTURE(i);
        if (!active[i]) continue;
        ++cells;
        if (integrate_box_cell(sites, active, static_cast<Site_index>(i), neighbours[i], box, 1e-8))
          ++by_regions;
        else if (family == "walls")
          ++walls_by_lines;  // a site within 1e-4 of another, relative to the cell's reach (exit_regions.h)
        const Cell_measure &x = a[i], &y = b[i];
        CHECK(x.reached_tolerance);
        // The line cubature stops at its panel limit on some cells beside a wall (then its estimate is
        // not its error): no reference there.
        if (!y.reached_tolerance) {
          ++unreached;
          continue;
        }
        CHECK(std::fabs(x.volume - y.volume) <= x.volume_error + y.volume_error + 1e-14);
        CHECK(x.volume_error <= 1e-7 * x.volume + 1e-14);
        CHECK(std::fabs(x.distance_integral - y.distance_integral) <= x.distance_error + y.distance_error + 1e-14);
        const Vector3 d{x.direction_integral[0] - y.direction_integral[0], x.direction_integral[1] - y.direction_integral[1],
                        x.direction_integral[2] - y.direction_integral[2]};
        CHECK(std::sqrt(dot(d, d)) <= x.direction_error + y.direction_error + 1e-14);
        // No estimates for these two: they steer Newton's steps; both methods reach about 1e-8 of them.
        const double scale = largest_magnitude(y.median_hessian);
        for (int k = 0; k < 6; ++k) CHECK(std::fabs(x.median_hessian[k] - y.median_hessian[k]) <= 1e-6 * scale);
        double derivative_scale = 0;
        for (const auto& [j, value] : y.volume_derivatives) derivative_scale = std::max(derivative_scale, std::fabs(value));
        const auto derivative = [](const Cell_measure& m, Site_index j) {
          for (const auto& [k, value] : m.volume_derivatives)
            if (k == j) return value;
          return 0.0;
        };
        for (const auto& [j, value] : x.volume_derivatives) CHECK(std::fabs(value - derivative(y, j)) <= 1e-6 * derivative_scale);
        for (const auto& [j, value] : y.volume_derivatives) CHECK(std::fabs(value - derivative(x, j)) <= 1e-6 * derivative_scale);
      }
    }
  MESSAGE("cells ", cells, ", by regions ", by_regions, ", without a reference ", unreached);
  // Every site strictly inside: the regions apply to every cell, but where two sites near a wall are too
  // close to measure at that cell's reach.
  CHECK(by_regions + walls_by_lines == cells);
  CHECK(walls_by_lines <= cells / 100);
  CHECK(unreached <= cells / 100);
}
