// The cell measures against independent computations: exact volumes of convex Voronoi cells (equal weights,
// CGAL's halfspace intersection and convex hull), Cartesian nested quadrature for a single site and for a
// two-site hyperboloid split, Monte Carlo with a stated confidence for weighted cells; the error estimates
// against the actual errors; the volume derivatives against finite differences; candidate sufficiency when
// the diagram proposes nothing (vertex-free faces); the same answer for every thread count.
#include <doctest/doctest.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Convex_hull_3/dual/halfspace_intersection_3.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include "io/read_sites.h"
#include "measure/cell_cubature.h"
#include "measure/cell_measures.h"
#include "measure/gauss_kronrod_rule.h"
#include "octree/octree_diagram.h"

using namespace apollonius;

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Plane = Kernel::Plane_3;
using Mesh = CGAL::Surface_mesh<Point>;

const Axis_box kUnitCube{{0, 0, 0}, {1, 1, 1}};

double box_volume(const Axis_box& b) { return (b.hi[0] - b.lo[0]) * (b.hi[1] - b.lo[1]) * (b.hi[2] - b.lo[2]); }

// The Voronoi cell of site i (equal weights) clipped to the box, as the intersection of halfspaces, and its
// volume (CGAL: a different method from the radial cubature entirely).
double voronoi_cell_volume(const std::vector<Site>& sites, std::size_t i, const Axis_box& box) {
  std::vector<Plane> planes;
  const Point xi(sites[i].x, sites[i].y, sites[i].z);
  for (std::size_t j = 0; j < sites.size(); ++j) {
    if (j == i) continue;
    const Point xj(sites[j].x, sites[j].y, sites[j].z);
    // |x - xi|^2 <= |x - xj|^2  <=>  2 (xj - xi).x + |xi|^2 - |xj|^2 <= 0 (the negative side)
    const Kernel::Vector_3 n = 2 * (xj - xi);
    planes.emplace_back(n.x(), n.y(), n.z(), (xi - CGAL::ORIGIN).squared_length() - (xj - CGAL::ORIGIN).squared_length());
  }
  for (int a = 0; a < 3; ++a) {
    double n[3] = {0, 0, 0};
    n[a] = 1;
    planes.emplace_back(n[0], n[1], n[2], -box.hi[a]);
    n[a] = -1;
    planes.emplace_back(n[0], n[1], n[2], box.lo[a]);
  }
  Mesh cell;
  // A site on a wall is no interior point: CGAL then finds one itself.
  const bool inside = xi.x() > box.lo[0] && xi.x() < box.hi[0] && xi.y() > box.lo[1] && xi.y() < box.hi[1] &&
                      xi.z() > box.lo[2] && xi.z() < box.hi[2];
  CGAL::halfspace_intersection_3(planes.begin(), planes.end(), cell,
                                 inside ? boost::optional<Point>(xi) : boost::optional<Point>());
  std::vector<Point> corners(cell.points().begin(), cell.points().end());
  Mesh hull;
  CGAL::convex_hull_3(corners.begin(), corners.end(), hull);
  return CGAL::Polygon_mesh_processing::volume(hull);
}

std::vector<Site> random_sites(std::mt19937_64& random, std::size_t n, const Axis_box& box, double weight_spread) {
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<Site> sites;
  for (std::size_t k = 0; k < n; ++k) {
    Site s;
    s.x = box.lo[0] + (box.hi[0] - box.lo[0]) * unit(random);
    s.y = box.lo[1] + (box.hi[1] - box.lo[1]) * unit(random);
    s.z = box.lo[2] + (box.hi[2] - box.lo[2]) * unit(random);
    s.w = weight_spread * unit(random);
    sites.push_back(s);
  }
  return sites;
}

std::vector<Cell_measure> measure(const std::vector<Site>& sites, const Axis_box& box, double tolerance, int threads = 1) {
  Measure_options options;
  options.relative_tolerance = tolerance;
  options.threads = threads;
  return measure_cells(sites, octree_diagram(sites), box, options);
}

// Nested adaptive Gauss-Kronrod over a rectangle of a function of y, z (Cartesian, independent of the
// cubature over directions).
template <class F>
double nested_rectangle_integral(const F& f, double y0, double y1, double z0, double z1, double tolerance) {
  using boost::math::quadrature::gauss_kronrod;
  return gauss_kronrod<double, 31>::integrate(
      [&](double y) { return gauss_kronrod<double, 31>::integrate([&](double z) { return f(y, z); }, z0, z1, 10, tolerance); },
      y0, y1, 10, tolerance);
}

}  // namespace

TEST_CASE("the Gauss-Kronrod pairs from Boost's tables: degrees 3n + 1 and 2n - 1") {
  const auto check = [](const Gauss_kronrod_rule& rule, int n) {
    for (int degree = 0; degree <= 3 * n + 3; ++degree) {
      const double exact = degree % 2 == 0 ? 2.0 / (degree + 1) : 0.0;
      double kronrod = 0, gauss = 0;
      for (std::size_t k = 0; k < rule.node.size(); ++k) {
        kronrod += rule.kronrod[k] * std::pow(rule.node[k], degree);
        gauss += rule.gauss[k] * std::pow(rule.node[k], degree);
      }
      CAPTURE(n);
      CAPTURE(degree);
      if (degree <= 3 * n + 1) CHECK(std::fabs(kronrod - exact) < 1e-14);
      if (degree <= 2 * n - 1) CHECK(std::fabs(gauss - exact) < 1e-14);
      if (degree == 2 * n) CHECK(std::fabs(gauss - exact) > 1e-12);  // no more than its degree
    }
  };
  check(make_gauss_kronrod_rule<15>(), 7);
  check(make_gauss_kronrod_rule<31>(), 15);
}

TEST_CASE("one site: the cell is the box; volume, distance and direction integrals against nested quadrature") {
  const Axis_box box{{-0.3, -1, 0.2}, {1.1, 0.5, 2}};
  const std::vector<Site> sites = {{0.1, -0.2, 0.7, 0.25}};
  const std::vector<Cell_measure> m = measure(sites, box, 1e-10);
  REQUIRE(m.size() == 1);
  CHECK(m[0].reached_tolerance);
  CHECK(std::fabs(m[0].volume - box_volume(box)) <= 1e-10 * box_volume(box));
  // Over x in [x0, x1] in closed form, with rho^2 = y^2 + z^2 (coordinates from c): the integral of
  // |v| is [x r + rho^2 asinh(x / rho)] / 2 and that of x / |v| is r, that of y / |v| is y asinh(x / rho);
  // then y and z by nested Gauss-Kronrod, split at c where the integrands are not smooth.
  const double c[3] = {0.1, -0.2, 0.7};
  const double x0 = box.lo[0] - c[0], x1 = box.hi[0] - c[0];
  const auto along_x = [&](double y, double z, int what) {
    const double rho = std::hypot(y, z);
    const auto primitive = [&](double x) {
      const double r = std::hypot(x, rho);
      if (what == 0) return 0.5 * (x * r + (rho > 0 ? rho * rho * std::asinh(x / rho) : 0.0));
      if (what == 1) return r;
      const double a = rho > 0 ? std::asinh(x / rho) : 0.0;
      return (what == 2 ? y : z) * a;
    };
    return primitive(x1) - primitive(x0);
  };
  double distance = 0, direction[3] = {0, 0, 0};
  const double ys[3] = {box.lo[1] - c[1], 0, box.hi[1] - c[1]}, zs[3] = {box.lo[2] - c[2], 0, box.hi[2] - c[2]};
  for (int iy = 0; iy < 2; ++iy)
    for (int iz = 0; iz < 2; ++iz)
      for (int what = 0; what < 4; ++what) {
        const double part = nested_rectangle_integral([&](double y, double z) { return along_x(y, z, what); },
                                                      ys[iy], ys[iy + 1], zs[iz], zs[iz + 1], 1e-12);
        (what == 0 ? distance : direction[what - 1]) += part;
      }
  CAPTURE(m[0].distance_integral - distance);
  CAPTURE(m[0].distance_error);
  CHECK(std::fabs(m[0].distance_integral - distance) <= 1e-9 * distance);
  CHECK(std::fabs(m[0].distance_integral - distance) <= m[0].distance_error + 1e-12 * distance);
  const double direction_difference = std::hypot(m[0].direction_integral[0] - direction[0],
                                                 m[0].direction_integral[1] - direction[1],
                                                 m[0].direction_integral[2] - direction[2]);
  CAPTURE(direction_difference);
  CHECK(direction_difference <= 1e-9 * m[0].volume);
  CHECK(m[0].volume_derivatives.empty());

  // The median Hessian is -dG/dc, G the direction integral about c, for a cell that does not move with c
  // (the box, for a single site): central differences of G as the site moves.
  const double h = 1e-4;
  for (int a = 0; a < 3; ++a) {
    std::vector<Site> plus = sites, minus = sites;
    (a == 0 ? plus[0].x : a == 1 ? plus[0].y : plus[0].z) += h;
    (a == 0 ? minus[0].x : a == 1 ? minus[0].y : minus[0].z) -= h;
    const Cell_measure mp = measure(plus, box, 1e-11)[0], mm = measure(minus, box, 1e-11)[0];
    const int index[3][3] = {{0, 3, 4}, {3, 1, 5}, {4, 5, 2}};  // xx yy zz xy xz yz
    for (int b = 0; b < 3; ++b) {
      CAPTURE(a);
      CAPTURE(b);
      const double difference = -(mp.direction_integral[b] - mm.direction_integral[b]) / (2 * h);
      CHECK(m[0].median_hessian[index[a][b]] == doctest::Approx(difference).epsilon(1e-6));
    }
  }
}

TEST_CASE("equal weights: the volumes of the convex Voronoi cells (CGAL) within the error estimates") {
  // Error estimates over all cells: how often and by how much the actual error exceeded the estimate.
  std::size_t cells = 0, within_estimate = 0;
  double worst_ratio = 0;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    std::mt19937_64 random(seed);
    const std::size_t n = 2 + seed % 20;
    const std::vector<Site> sites = random_sites(random, n, kUnitCube, 0);
    const double tolerance = seed % 2 == 0 ? 1e-6 : 1e-9;
    const std::vector<Cell_measure> m = measure(sites, kUnitCube, tolerance);
    double total = 0;
    for (std::size_t i = 0; i < n; ++i) {
      CAPTURE(seed);
      CAPTURE(i);
      const double exact = voronoi_cell_volume(sites, i, kUnitCube);
      const double error = std::fabs(m[i].volume - exact);
      CAPTURE(error);
      CAPTURE(m[i].volume_error);
      CHECK(m[i].reached_tolerance);
      CHECK(error <= tolerance * exact);  // what the tolerance promises
      ++cells;
      if (error <= m[i].volume_error + 1e-15) ++within_estimate;
      worst_ratio = std::max(worst_ratio, error / m[i].volume_error);
      total += m[i].volume;
    }
    CHECK(std::fabs(total - 1) <= 2 * tolerance);
  }
  MESSAGE("cells " << cells << ", actual volume error within the estimate in " << within_estimate
                   << ", largest actual/estimate " << worst_ratio);
  CHECK(within_estimate == cells);
}

TEST_CASE("two weighted sites: the hyperboloid split against Cartesian nested quadrature") {
  // Sites on the x axis: along each line parallel to it, |x - x1| - |x - x2| increases, so the cell of
  // site 1 is x < x_b(y, z) (a hyperboloid sheet, closed form); the volume is the integral of that length
  // over (y, z).
  const Axis_box box{{-1, -0.7, -0.6}, {1.2, 0.8, 0.5}};
  for (double weight_difference : {0.0, 0.3, -0.5, 0.85}) {
    const std::vector<Site> sites = {{-0.4, 0, 0, weight_difference}, {0.5, 0, 0, 0}};
    const std::vector<Cell_measure> m = measure(sites, box, 1e-10);
    // |x - x1| - |x - x2| = delta, foci 0.9 apart about m = 0.05: the hyperbola X^2 / A^2 - rho^2 / B^2 = 1
    // with X = x - m, A = delta / 2, B^2 = 0.45^2 - A^2, on the side of X with the sign of delta. The length
    // is clamped to the box where the sheet leaves it, at radii rho*: the integrals are split there (a kink
    // inside a Gauss-Kronrod interval costs it digits it cannot see).
    const double A = 0.5 * weight_difference, B2 = 0.45 * 0.45 - A * A;
    const auto length = [&](double y, double z) {
      const double X = A * std::sqrt(1 + (y * y + z * z) / B2);
      return std::clamp(0.05 + X, box.lo[0], box.hi[0]) - box.lo[0];
    };
    std::vector<double> kink_radii;
    for (double bound : {box.lo[0], box.hi[0]}) {
      const double X = bound - 0.05;
      if (A != 0 && X / A > 1) kink_radii.push_back(std::sqrt(B2 * ((X / A) * (X / A) - 1)));
    }
    const auto split_integral = [](double a, double b, std::vector<double> cuts, const auto& f) {
      cuts.push_back(a), cuts.push_back(b);
      std::sort(cuts.begin(), cuts.end());
      double sum = 0;
      for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
        const double l = std::max(a, cuts[k]), r = std::min(b, cuts[k + 1]);
        if (r > l) sum += boost::math::quadrature::gauss_kronrod<double, 31>::integrate(f, l, r, 12, 1e-14);
      }
      return sum;
    };
    std::vector<double> y_cuts;
    for (double r : kink_radii) y_cuts.push_back(r), y_cuts.push_back(-r);
    const double exact = split_integral(box.lo[1], box.hi[1], y_cuts, [&](double y) {
      std::vector<double> z_cuts;
      for (double r : kink_radii)
        if (r > std::fabs(y)) z_cuts.push_back(std::sqrt(r * r - y * y)), z_cuts.push_back(-std::sqrt(r * r - y * y));
      return split_integral(box.lo[2], box.hi[2], z_cuts, [&](double z) { return length(y, z); });
    });
    CAPTURE(weight_difference);
    CAPTURE(m[0].volume - exact);
    CAPTURE(m[0].volume_error);
    CHECK(std::fabs(m[0].volume - exact) <= 1e-10 * exact + 1e-12);
    CHECK(std::fabs(m[0].volume - exact) <= m[0].volume_error + 1e-12);
    CHECK(std::fabs(m[0].volume + m[1].volume - box_volume(box)) <= 1e-9 * box_volume(box));
    // The face between them: d m_0 / d w_1 = d m_1 / d w_0 (the Hessian of E4 is symmetric), both < 0.
    REQUIRE(m[0].volume_derivatives.size() == 1);
    REQUIRE(m[1].volume_derivatives.size() == 1);
    CHECK(m[0].volume_derivatives[0].second < 0);
    CHECK(m[0].volume_derivatives[0].second == doctest::Approx(m[1].volume_derivatives[0].second).epsilon(1e-6));
  }
}

// Sites on the box's walls, edges and corners: each coordinate moved onto a wall with probability 1/3.
std::vector<Site> sites_on_walls(std::mt19937_64& random, std::size_t n, double weight_spread) {
  std::vector<Site> sites = random_sites(random, n, kUnitCube, weight_spread);
  for (Site& s : sites)
    for (double* c : {&s.x, &s.y, &s.z})
      if (random() % 3 == 0) *c = random() % 2 == 0 ? 0.0 : 1.0;
  return sites;
}

// The owner of a point by brute force over all sites: independent of the diagram and of the cubature.
std::size_t nearest_site(const std::vector<Site>& sites, double x, double y, double z) {
  std::size_t best = 0;
  double best_distance = INFINITY;
  for (std::size_t j = 0; j < sites.size(); ++j) {
    const double d = std::hypot(x - sites[j].x, y - sites[j].y, z - sites[j].z) - sites[j].w;
    if (d < best_distance) best_distance = d, best = j;
  }
  return best;
}

// Regression (tests/data/regression/measure_cells_volumes_exceed_box.balls): a plane of the box through the
// site is the exit 0 on its outer side and none on the other, a jump that no tie marks; the walk along a
// line missed it and gave such cells the volume beyond the wall (10% too much), and then the outer rule
// bracketed the jump at b = 0 instead of ending an interval there (errors of 1e-7 at any tolerance).
TEST_CASE("regression: measure_cells_volumes_exceed_box, sites on the box's walls, edges and corners") {
  std::size_t cells = 0;
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    CAPTURE(seed);
    std::mt19937_64 random(seed);
    const std::size_t n = 2 + seed % 12;
    const bool equal_weights = seed % 2 == 0;
    const std::vector<Site> sites = sites_on_walls(random, n, equal_weights ? 0 : 0.15);
    const double tolerance = seed % 4 < 2 ? 1e-6 : 1e-9;
    const std::vector<Cell_measure> m = measure(sites, kUnitCube, tolerance);
    std::vector<std::size_t> count(n, 0);
    const std::size_t samples = equal_weights ? 0 : 200000;
    std::uniform_real_distribution<double> unit(0, 1);
    for (std::size_t s = 0; s < samples; ++s) {
      const double x = unit(random), y = unit(random), z = unit(random);
      ++count[nearest_site(sites, x, y, z)];
    }
    double total = 0, total_error = 0;
    for (std::size_t i = 0; i < n; ++i) {
      CAPTURE(i);
      CAPTURE(sites[i].x);
      CAPTURE(sites[i].y);
      CAPTURE(sites[i].z);
      CAPTURE(m[i].volume);
      CAPTURE(m[i].volume_error);
      CHECK(m[i].reached_tolerance);
      total += m[i].volume;
      total_error += m[i].volume_error;
      ++cells;
      if (equal_weights) {  // convex cells: CGAL's exact halfspace intersection
        const double exact = voronoi_cell_volume(sites, i, kUnitCube);
        CAPTURE(exact);
        CHECK(std::fabs(m[i].volume - exact) <= tolerance * exact + 1e-15);
        CHECK(std::fabs(m[i].volume - exact) <= m[i].volume_error + 1e-15);
      } else {  // 5 standard deviations of the binomial count
        const double p = m[i].volume, sigma = std::sqrt(samples * p * (1 - p));
        CAPTURE(count[i]);
        CHECK(std::fabs(static_cast<double>(count[i]) - samples * p) <= 5 * sigma + 1);
      }
    }
    CAPTURE(total);
    CHECK(std::fabs(total - 1) <= 2 * total_error + 1e-15);
  }
  CHECK(cells > 150);
}

// Regressions of fuzz_box_cells beside two sites one ulp apart, or 4 apart in a box 4e5 wide: measure_cells
// must end (it looped for ever, or ran for minutes), with finite measures whose volumes fill the box within
// their estimates (they overfilled it by 0.5%, or fell short by 1e-7, beyond estimates 100 times smaller).
TEST_CASE("regression: sites one ulp apart (a ray without an exit, a refinement without end, a lost tie, a jump), a pole") {
  struct Case {
    const char* file;
    Axis_box box;
    bool within_tolerance;  // whether every cell reaches the tolerance
  };
  const Case cases[] = {
      {"measure_cells_loop_on_a_ray_without_exit_beside_sites_one_ulp_apart.balls",
       {{-7, -7, -7}, {7, 7.0000000000000009, 7.0000000000000009}}, false},
      {"cell_cubature_refines_for_minutes_beside_sites_one_ulp_apart.balls",
       {{-5.34375, -5.34375, -5.34375}, {-1.28125, -1.6562499999999996, -1.65625}}, false},
      {"cell_cubature_loses_a_tie_of_a_cut_and_a_plane_with_weights_one_ulp_apart.balls",
       {{-5.5, -5.5, -5.5}, {-2.4999999999999996, -2.5, -0.5}}, true},
      {"cell_cubature_bracket_blind_to_a_jump_beside_sites_one_ulp_apart.balls",
       {{-6.75, -6.75, -6.75}, {-1.2499999999999996, 5.75, -1.25}}, true},
      {"cell_cubature_misses_the_pole_of_a_near_plane_in_a_huge_box.balls",
       {{-71686, -71686, -71686}, {358402, 358402, 358402}}, true}};
  for (const Case& c : cases) {
    const std::string file = c.file;
    CAPTURE(file);
    const std::vector<Site> sites = read_sites(std::string(APOLLONIUS_TEST_DATA) + "/regression/" + c.file, {}).sites;
    const std::vector<Cell_measure> m = measure(sites, c.box, 1e-6);
    const double volume = (c.box.hi[0] - c.box.lo[0]) * (c.box.hi[1] - c.box.lo[1]) * (c.box.hi[2] - c.box.lo[2]);
    double total = 0, total_error = 0;
    bool every_cell_reached = true;
    for (const Cell_measure& cell : m) {
      CHECK(std::isfinite(cell.volume));
      CHECK(std::isfinite(cell.volume_error));
      CHECK(cell.volume >= 0);
      total += cell.volume, total_error += cell.volume_error;
      every_cell_reached = every_cell_reached && cell.reached_tolerance;
    }
    CAPTURE(total);
    CAPTURE(total_error);
    CHECK(std::fabs(total - volume) <= total_error + 1e-9 * volume);
    CHECK(every_cell_reached == c.within_tolerance);
    if (c.within_tolerance) CHECK(total_error <= 1e-7 * volume);  // tolerance 1e-6, with room
  }
}

TEST_CASE("weighted cells against Monte Carlo (5 standard deviations)") {
  // Each sample's owner by brute force over all sites: independent of the diagram and of the cubature.
  // A cell's sample count is binomial: sigma = sqrt(N p (1 - p)); 5 sigma fails by chance with probability
  // below 1e-6 per cell (the seeds are fixed).
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    std::mt19937_64 random(seed);
    const std::size_t n = 5 + 5 * seed;
    const std::vector<Site> sites = random_sites(random, n, kUnitCube, 0.15);
    const std::vector<Cell_measure> m = measure(sites, kUnitCube, 1e-8);
    const std::size_t samples = 400000;
    std::vector<std::size_t> count(n, 0);
    std::uniform_real_distribution<double> unit(0, 1);
    for (std::size_t s = 0; s < samples; ++s) {
      const double x = unit(random), y = unit(random), z = unit(random);
      std::size_t best = 0;
      double best_distance = INFINITY;
      for (std::size_t j = 0; j < n; ++j) {
        const double d = std::hypot(x - sites[j].x, y - sites[j].y, z - sites[j].z) - sites[j].w;
        if (d < best_distance) best_distance = d, best = j;
      }
      ++count[best];
    }
    for (std::size_t i = 0; i < n; ++i) {
      const double p = m[i].volume, sigma = std::sqrt(samples * p * (1 - p));
      CAPTURE(seed);
      CAPTURE(i);
      CAPTURE(count[i]);
      CAPTURE(samples * p);
      CHECK(std::fabs(static_cast<double>(count[i]) - samples * p) <= 5 * sigma + 1);
    }
  }
}

TEST_CASE("volume derivatives against central differences of the volumes") {
  for (std::uint64_t seed = 11; seed <= 12; ++seed) {
    std::mt19937_64 random(seed);
    const std::size_t n = 6;
    std::vector<Site> sites = random_sites(random, n, kUnitCube, 0.1);
    const std::vector<Cell_measure> m = measure(sites, kUnitCube, 1e-10);
    const double h = 1e-4;
    for (std::size_t j = 0; j < n; ++j) {
      std::vector<Site> plus = sites, minus = sites;
      plus[j].w += h, minus[j].w -= h;
      const std::vector<Cell_measure> mp = measure(plus, kUnitCube, 1e-10), mm = measure(minus, kUnitCube, 1e-10);
      for (std::size_t i = 0; i < n; ++i) {
        double analytic = 0, row_sum = 0;
        for (const auto& [k, d] : m[i].volume_derivatives) {
          row_sum += d;
          if (k == j) analytic = d;
        }
        if (i == j) analytic = -row_sum;
        const double difference = (mp[i].volume - mm[i].volume) / (2 * h);
        CAPTURE(seed);
        CAPTURE(i);
        CAPTURE(j);
        CAPTURE(analytic);
        CAPTURE(difference);
        // Truncation h^2 m''' about 1e-8 and quadrature noise 1e-10 m / h about 1e-6; the derivatives are
        // of order 0.1 to 1 (face areas).
        CHECK(std::fabs(analytic - difference) <= 1e-4 * (1 + std::fabs(analytic)));
      }
    }
  }
}

TEST_CASE("candidates: without any proposal from the diagram, the clearance finds every cutting site") {
  // Faces without a vertex (two or three sites have no vertex at all) and neighbours whose shared vertices
  // lie outside the box: measure_cells must not depend on the vertex neighbours being complete.
  for (std::uint64_t seed = 21; seed <= 26; ++seed) {
    std::mt19937_64 random(seed);
    const std::size_t n = 2 + seed % 5;
    const std::vector<Site> sites = random_sites(random, n, kUnitCube, 0.2);
    const Diagram diagram = octree_diagram(sites);
    std::vector<bool> active(n, true);
    for (const Hidden_site& h : diagram.hidden) active[h.site] = false;
    const std::vector<Cell_measure> m = measure_cells(sites, diagram, kUnitCube, {1e-9, 1});
    for (std::size_t i = 0; i < n; ++i) {
      if (!active[i]) continue;
      std::vector<Site_index> everyone;
      for (Site_index j = 0; j < n; ++j) everyone.push_back(j);
      const Cell_cubature_result all =
          integrate_cell(sites[i], cut_candidates(sites, active, static_cast<Site_index>(i), everyone, {}, kUnitCube), kUnitCube, {1e-9});
      REQUIRE_FALSE(all.clearance_exceeded);
      CAPTURE(seed);
      CAPTURE(i);
      CHECK(m[i].volume == doctest::Approx(all.measure.volume).epsilon(1e-12));
      // With no proposal at all, the clearance turns the first rays away.
      if (n > 1) {
        const Cell_cubature_result none =
            integrate_cell(sites[i], cut_candidates(sites, active, static_cast<Site_index>(i), {}, {}, kUnitCube), kUnitCube, {1e-9});
        CHECK(none.clearance_exceeded);
      }
    }
  }
}

TEST_CASE("the same measures for every thread count") {
  std::mt19937_64 random(7);
  const std::vector<Site> sites = random_sites(random, 40, kUnitCube, 0.05);
  const std::vector<Cell_measure> one = measure(sites, kUnitCube, 1e-7, 1), two = measure(sites, kUnitCube, 1e-7, 2);
  for (std::size_t i = 0; i < sites.size(); ++i) {
    CHECK(one[i].volume == two[i].volume);
    CHECK(one[i].direction_integral == two[i].direction_integral);
    CHECK(one[i].volume_derivatives == two[i].volume_derivatives);
  }
}
