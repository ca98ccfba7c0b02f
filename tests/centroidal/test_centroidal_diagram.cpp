// The centroidal loop (paper section 7) on the paper's 6-site example and on random inputs: it converges,
// E4 never decreases along an accepted weight step (up to the quadrature error estimates), and at
// convergence the volumes and the geometric-median property hold when checked by Monte Carlo, which
// shares nothing with the code path (plain doubles decide each sample's cell). Bad parameters throw.
#include <doctest/doctest.h>

#include <chrono>
#include <cmath>
#include <random>
#include <thread>
#include <tuple>

#include "centroidal/centroidal_diagram.h"
#include "io/read_masses.h"
#include "io/read_sites.h"

using namespace apollonius;

namespace {

const Axis_box kUnitCube{{0, 0, 0}, {1, 1, 1}};

// Monte Carlo estimates over the box: each cell's volume fraction and its mean unit vector (x - x_i) /
// |x - x_i| times its volume fraction (G_i / |box|), with their standard errors. A sample belongs to the
// site with the least |x - x_i| - w_i (ties have probability zero).
struct Monte_carlo_cell {
  double volume = 0, volume_sigma = 0;
  std::array<double, 3> direction{0, 0, 0};
  double direction_sigma = 0;  // of each component
};

std::vector<Monte_carlo_cell> monte_carlo(const std::vector<Site>& sites, std::uint64_t seed, std::size_t samples) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  const std::size_t n = sites.size();
  std::vector<double> count(n, 0);
  std::vector<std::array<double, 3>> sum(n, {0, 0, 0});
  for (std::size_t k = 0; k < samples; ++k) {
    const double x[3] = {unit(random), unit(random), unit(random)};
    std::size_t owner = 0;
    double best = INFINITY;
    for (std::size_t i = 0; i < n; ++i) {
      const double d = std::hypot(x[0] - sites[i].x, x[1] - sites[i].y, x[2] - sites[i].z) - sites[i].w;
      if (d < best) best = d, owner = i;
    }
    const double dx[3] = {x[0] - sites[owner].x, x[1] - sites[owner].y, x[2] - sites[owner].z};
    const double r = std::hypot(dx[0], dx[1], dx[2]);
    count[owner] += 1;
    for (int a = 0; a < 3; ++a) sum[owner][a] += dx[a] / r;
  }
  std::vector<Monte_carlo_cell> cells(n);
  const double N = static_cast<double>(samples);
  for (std::size_t i = 0; i < n; ++i) {
    const double p = count[i] / N;
    cells[i].volume = p;
    cells[i].volume_sigma = std::sqrt(p * (1 - p) / N);
    for (int a = 0; a < 3; ++a) cells[i].direction[a] = sum[i][a] / N;
    // Each component of the indicator times a unit vector has second moment at most p.
    cells[i].direction_sigma = std::sqrt(p / N);
  }
  return cells;
}

std::vector<double> example_masses() {
  return read_masses(std::string(APOLLONIUS_EXAMPLES) + "/centroidal6/masses.txt", 6);
}

std::vector<Site> example_sites() {
  return read_sites(std::string(APOLLONIUS_EXAMPLES) + "/centroidal6/sites.txt", {}).sites;
}

// E4 after the accepted weight steps of each iteration is at least E4 before them, less their errors.
void check_energy_never_decreases(const Centroidal_result& result) {
  for (const Centroidal_iteration& row : result.history) {
    CAPTURE(row.iteration);
    CAPTURE(row.energy_before);
    CAPTURE(row.energy);
    CAPTURE(row.energy_error);
    CHECK(row.energy >= row.energy_before - row.energy_error);
  }
}

}  // namespace

TEST_CASE("the paper's 6-site example: converged to 1e-6 within 20 iterations, E4 rising along weight steps") {
  const std::vector<double> masses = example_masses();
  const std::vector<Site> initial = example_sites();
  Centroidal_options options;
  options.tolerance = 1e-6;
  const Centroidal_result result = centroidal_diagram(initial, masses, kUnitCube, options);
  REQUIRE(result.converged);
  CHECK(result.history.size() <= 20);
  check_energy_never_decreases(result);
  // Newton's weight step that overshoots the maximum along its direction but raises E4 is taken
  // (weight_step.h, (c)); the slope rule alone refused 9 trials here, each a diagram and its measures.
  int refused_weight_trials = 0;
  for (const Centroidal_iteration& row : result.history) refused_weight_trials += row.weight_retries;
  CHECK(refused_weight_trials <= 2);
  const Centroidal_iteration& last = result.history.back();
  CHECK(last.mass_error <= 1e-6);
  CHECK(last.median_error <= 1e-6);
  for (std::size_t i = 0; i < masses.size(); ++i) {
    CAPTURE(i);
    CHECK(std::fabs(result.volumes[i] - masses[i]) <= 1e-6 * masses[i]);
  }

  // Independently, by Monte Carlo (seed printed): the volumes are the targets and the mean unit vector from
  // each site over its cell vanishes, within 5 standard errors. Sensitivity: the initial sites fail it.
  const std::uint64_t seed = 20261125;
  const std::size_t samples = 2000000;
  CAPTURE(seed);
  const std::vector<Monte_carlo_cell> final_cells = monte_carlo(result.sites, seed, samples);
  for (std::size_t i = 0; i < masses.size(); ++i) {
    CAPTURE(i);
    const Monte_carlo_cell& c = final_cells[i];
    CHECK(std::fabs(c.volume - masses[i]) <= 5 * c.volume_sigma);
    for (int a = 0; a < 3; ++a) {
      CAPTURE(a);
      CHECK(std::fabs(c.direction[a]) <= 5 * c.direction_sigma);
    }
  }
  std::vector<Site> unweighted = initial;
  const std::vector<Monte_carlo_cell> initial_cells = monte_carlo(unweighted, seed, samples);
  double worst = 0;  // the largest component of the mean unit vector, in standard errors
  for (const Monte_carlo_cell& c : initial_cells)
    for (int a = 0; a < 3; ++a) worst = std::max(worst, std::fabs(c.direction[a]) / c.direction_sigma);
  CHECK(worst > 50);
}

TEST_CASE("random sites and masses: converged to 1e-4, E4 rising along weight steps, medians by Monte Carlo") {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> unit(0, 1);
    const std::size_t n = 10;
    std::vector<Site> sites(n);
    for (Site& s : sites) s = {unit(random), unit(random), unit(random), 0};
    std::vector<double> masses(n);
    double sum = 0;
    for (double& m : masses) sum += (m = 1 + 2 * unit(random));
    for (double& m : masses) m /= sum;
    Centroidal_options options;
    options.tolerance = 1e-4;
    // The site steps pass near saddles of max_W E4, where the medians' residuals first shrink, then grow
    // while the sites leave them; 17 to 306 iterations on the first 8 seeds.
    options.max_iterations = 500;
    const Centroidal_result result = centroidal_diagram(sites, masses, kUnitCube, options);
    CAPTURE(seed);
    CAPTURE(result.history.size());
    CAPTURE(result.history.back().mass_error);
    CAPTURE(result.history.back().median_error);
    CAPTURE(result.reports.size());
    REQUIRE(result.converged);
    check_energy_never_decreases(result);
    const std::vector<Monte_carlo_cell> cells = monte_carlo(result.sites, seed, 1000000);
    for (std::size_t i = 0; i < n; ++i) {
      CAPTURE(i);
      CHECK(std::fabs(cells[i].volume - masses[i]) <= 5 * cells[i].volume_sigma);
      for (int a = 0; a < 3; ++a) CHECK(std::fabs(cells[i].direction[a]) <= 5 * cells[i].direction_sigma);
    }
  }
}

TEST_CASE("fixed sites (move_sites false): only the weights move, and the volumes reach their targets") {
  const std::vector<double> masses = example_masses();
  const std::vector<Site> initial = example_sites();
  Centroidal_options options;
  options.tolerance = 1e-8;
  options.move_sites = false;
  const Centroidal_result result = centroidal_diagram(initial, masses, kUnitCube, options);
  REQUIRE(result.converged);
  check_energy_never_decreases(result);
  for (std::size_t i = 0; i < initial.size(); ++i) {
    CAPTURE(i);
    CHECK(result.sites[i].x == initial[i].x);
    CHECK(result.sites[i].y == initial[i].y);
    CHECK(result.sites[i].z == initial[i].z);
    CHECK(std::fabs(result.volumes[i] - masses[i]) <= 1e-8 * masses[i]);
  }
}

TEST_CASE("input weights that hide a site are reset to 0, and that is reported") {
  std::vector<Site> sites = example_sites();
  sites[1].w = 2;  // a ball of radius 2 around a site of the unit cube swallows every other
  Centroidal_options options;
  options.tolerance = 1e-4;
  const Centroidal_result result = centroidal_diagram(sites, example_masses(), kUnitCube, options);
  REQUIRE_FALSE(result.reports.empty());
  CHECK(result.reports.front().find("reset to 0") != std::string::npos);
  CHECK(result.converged);
}

TEST_CASE("bad parameters throw Centroidal_parameter_error naming the site or mass") {
  const std::vector<Site> sites = example_sites();
  const std::vector<double> masses = example_masses();
  const auto error_site = [&](const std::vector<Site>& s, const std::vector<double>& m, const Axis_box& box) -> long {
    try {
      centroidal_diagram(s, m, box);
    } catch (const Centroidal_parameter_error& e) {
      return e.site;
    }
    return -2;  // no error
  };
  std::vector<double> negative = masses;
  negative[2] = -negative[2];
  CHECK(error_site(sites, negative, kUnitCube) == 2);
  std::vector<double> too_much = masses;
  too_much[0] += 0.01;
  CHECK(error_site(sites, too_much, kUnitCube) == -1);
  CHECK(error_site(sites, std::vector<double>(5, 0.2), kUnitCube) == -1);
  std::vector<Site> outside = sites;
  outside[4].z = 1.5;
  CHECK(error_site(outside, masses, kUnitCube) == 4);
  std::vector<Site> same_centre = sites;
  same_centre[3] = same_centre[0];
  CHECK(error_site(same_centre, masses, kUnitCube) == 3);
  CHECK(error_site(sites, masses, Axis_box{{0, 0, 0}, {1, 0, 1}}) == -1);
}

TEST_CASE("each bad parameter names its parameter, with the reason the command line gives") {
  const std::vector<Site> sites = example_sites();
  const std::vector<double> masses = example_masses();
  const auto refused = [&](const std::vector<double>& m, const Axis_box& box, double tolerance, int iterations) {
    Centroidal_options options;
    options.tolerance = tolerance;
    options.max_iterations = iterations;
    try {
      centroidal_diagram(sites, m, box, options);
    } catch (const Centroidal_parameter_error& e) {
      return std::make_tuple(e.parameter, e.site, std::string(e.what()));
    }
    return std::make_tuple(Centroidal_parameter::sites, -2L, std::string("no error"));
  };
  using P = Centroidal_parameter;
  CHECK(refused(masses, kUnitCube, 0.7, 100) ==
        std::make_tuple(P::tolerance, -1L, std::string("must lie in [1e-10, 0.5], not 0.69999999999999996")));
  CHECK(refused(masses, kUnitCube, 1e-6, 0) ==
        std::make_tuple(P::max_iterations, -1L, std::string("needs an integer from 1 to 100000, not 0")));
  CHECK(refused(masses, Axis_box{{0, 0, 0}, {1, 1, INFINITY}}, 1e-6, 100) ==
        std::make_tuple(P::domain, -1L, std::string("needs a finite number, not inf")));
  CHECK(refused(masses, Axis_box{{0, 0, 0}, {1, 0, 1}}, 1e-6, 100) ==
        std::make_tuple(P::domain, -1L, std::string("needs X0 < X1, Y0 < Y1 and Z0 < Z1 (a box with a volume)")));
  std::vector<double> seven = masses;
  seven.push_back(0.1);
  CHECK(refused(seven, kUnitCube, 1e-6, 100) == std::make_tuple(P::masses, 6L, std::string("more masses than the 6 sites")));
  std::vector<double> not_a_number = masses;
  not_a_number[1] = NAN;
  CHECK(refused(not_a_number, kUnitCube, 1e-6, 100) ==
        std::make_tuple(P::masses, 1L, std::string("not a finite number: nan")));
  CHECK(std::get<0>(refused(masses, Axis_box{{0, 0, 0}, {0.5, 1, 1}}, 1e-6, 100)) == P::sites);
  Centroidal_options loose_medians;
  loose_medians.median_tolerance = 0.7;
  CHECK_THROWS_WITH_AS(centroidal_diagram(sites, masses, kUnitCube, loose_medians),
                       "must lie in [1e-10, 0.5], not 0.69999999999999996", Centroidal_parameter_error);
}

TEST_CASE("a median tolerance of its own: the volumes to the tolerance, the medians to theirs, sooner") {
  const std::vector<double> masses = example_masses();
  Centroidal_options both, own;
  both.tolerance = own.tolerance = 1e-8;
  own.median_tolerance = 1e-3;
  const Centroidal_result strict = centroidal_diagram(example_sites(), masses, kUnitCube, both);
  const Centroidal_result loose = centroidal_diagram(example_sites(), masses, kUnitCube, own);
  REQUIRE(strict.converged);
  REQUIRE(loose.converged);
  const Centroidal_iteration& last = loose.history.back();
  CHECK(last.mass_error <= 1e-8);
  CHECK(last.median_error <= 1e-3);
  CHECK(last.median_error > 1e-8);  // it stopped on the looser medians,
  CHECK(loose.history.size() < strict.history.size());  // and sooner
  check_energy_never_decreases(loose);
}

TEST_CASE("a cancellation stops the loop: requested before, at once; during, Cancelled or the whole answer") {
  const std::vector<Site> sites = example_sites();
  const std::vector<double> masses = example_masses();
  Cancellation cancellation;
  cancellation.request();
  Centroidal_options options;
  options.cancellation = &cancellation;
  CHECK_THROWS_AS(centroidal_diagram(sites, masses, kUnitCube, options), Cancelled);
  // 30 sites: the octree's diagrams, whose phases and the cell measures check it too.
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> inside(0.05, 0.95);
  std::vector<Site> many;
  for (int i = 0; i < 30; ++i) many.push_back({inside(random), inside(random), inside(random), 0});
  const std::vector<double> equal(30, 1.0 / 30);
  Centroidal_options few;
  few.max_iterations = 3;
  const Centroidal_result whole = centroidal_diagram(many, equal, kUnitCube, few);
  CHECK_THROWS_AS(centroidal_diagram(many, equal, kUnitCube, options), Cancelled);
  // One never requested changes nothing.
  const Cancellation never;
  Centroidal_options unrequested = few;
  unrequested.cancellation = &never;
  const Centroidal_result same = centroidal_diagram(many, equal, kUnitCube, unrequested);
  REQUIRE(same.history.size() == whole.history.size());
  for (std::size_t i = 0; i < many.size(); ++i) {
    CHECK(same.sites[i].x == whole.sites[i].x);
    CHECK(same.sites[i].y == whole.sites[i].y);
    CHECK(same.sites[i].z == whole.sites[i].z);
    CHECK(same.sites[i].w == whole.sites[i].w);
  }
  int cancelled = 0;
  for (int delay_ms : {1, 20, 100, 400}) {
    CAPTURE(delay_ms);
    Cancellation later;
    Centroidal_options cancellable = few;
    cancellable.cancellation = &later;
    std::thread requester([&] {
      std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms));
      later.request();
    });
    try {
      const Centroidal_result r = centroidal_diagram(many, equal, kUnitCube, cancellable);
      CHECK(r.history.size() == whole.history.size());
      for (std::size_t i = 0; i < many.size(); ++i) {
        CHECK(r.sites[i].x == whole.sites[i].x);
        CHECK(r.sites[i].w == whole.sites[i].w);
      }
    } catch (const Cancelled&) {
      ++cancelled;
    }
    requester.join();
  }
  CHECK(cancelled >= 1);
}
