#include "centroidal/centroidal_diagram.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "centroidal/anderson_acceleration.h"
#include "centroidal/energy.h"
#include "centroidal/median_step.h"
#include "centroidal/weight_step.h"
#include "io/round_trip.h"

namespace apollonius {
namespace {

// Halvings of one step before it is given up (2^-30 of a step is no step), and trials of a weight step.
constexpr int kMaxHalvings = 30, kMaxTrials = 40;
// The fraction of the first-order gain that an overshooting weight step must keep (Armijo's condition).
constexpr double kSufficientIncrease = 1e-4;
// Newton steps for the weights in one iteration, at most.
constexpr int kWeightStepsPerIteration = 3;
// Site steps mixed by Anderson acceleration.
constexpr std::size_t kAndersonDepth = 5;

double max_mass_error(const Energy_evaluation& e, const std::vector<double>& targets) {
  double worst = 0;
  for (std::size_t i = 0; i < targets.size(); ++i)
    worst = std::max(worst, (std::fabs(targets[i] - e.measures[i].volume) + e.measures[i].volume_error) / targets[i]);
  return worst;
}

double max_median_error(const Energy_evaluation& e) {
  double worst = 0;
  for (const Cell_measure& m : e.measures) worst = std::max(worst, median_residual(m));
  return worst;
}

// Why a state cannot be accepted, or empty: a hidden site, or a cell below `floor` of its target.
std::string defect(const Energy_evaluation& e, const std::vector<double>& targets, double floor) {
  if (!e.diagram.hidden.empty()) {
    const Hidden_site& h = e.diagram.hidden.front();
    return "site " + std::to_string(h.site) + " is hidden by site " + std::to_string(h.hidden_by);
  }
  for (std::size_t i = 0; i < targets.size(); ++i)
    if (e.measures[i].volume < floor * targets[i])
      return "the cell of site " + std::to_string(i) + " has only " + round_trip(e.measures[i].volume / targets[i]) +
             " of its target volume";
  return {};
}

double least_volume_ratio(const Energy_evaluation& e, const std::vector<double>& targets) {
  double least = 1;
  for (std::size_t i = 0; i < targets.size(); ++i) least = std::min(least, e.measures[i].volume / targets[i]);
  return least;
}

}  // namespace

Centroidal_result centroidal_diagram(const std::vector<Site>& initial, const std::vector<double>& mass_fractions,
                                     const Axis_box& domain, const Centroidal_options& options) {
  check_centroidal_domain(domain);
  check_centroidal_tolerance(options.tolerance);
  if (options.median_tolerance) check_centroidal_tolerance(*options.median_tolerance, Centroidal_parameter::median_tolerance);
  check_centroidal_iterations(options.max_iterations);
  check_centroidal_sites(initial, mass_fractions, domain);
  const auto start = std::chrono::steady_clock::now();
  const auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  const std::size_t n = initial.size();
  const double volume = (domain.hi[0] - domain.lo[0]) * (domain.hi[1] - domain.lo[1]) * (domain.hi[2] - domain.lo[2]);
  std::vector<double> targets(n);
  for (std::size_t i = 0; i < n; ++i) targets[i] = mass_fractions[i] * volume;
  const double tolerance = options.tolerance;
  const double median_tolerance = options.median_tolerance.value_or(tolerance);

  Centroidal_result result;
  const auto report = [&](const std::string& message) {
    result.reports.push_back(message);
    if (options.on_report) options.on_report(message);
  };
  // The quadrature tolerance follows the errors: loose while they are large, the tighter tolerance / 20 at
  // the end.
  double quadrature = 1e-4;
  const double quadrature_floor = std::min(tolerance, median_tolerance) / 20;
  const auto next_quadrature = [&](double error) { quadrature = std::clamp(0.05 * error, quadrature_floor, 1e-4); };

  const auto evaluate = [&](const std::vector<Site>& at, const std::vector<double>& volumes, const Axis_box& box,
                            double quadrature_tolerance, int threads) {
    ++result.evaluations;
    return evaluate_energy(at, volumes, box, quadrature_tolerance, threads, options.cancellation);
  };
  std::vector<Site> sites = initial;
  Anderson_acceleration acceleration(kAndersonDepth);
  Energy_evaluation state = evaluate(sites, targets, domain, quadrature, options.threads);
  std::string why = defect(state, targets, 0);
  if (why.empty() && !(least_volume_ratio(state, targets) > 0)) why = "a cell has no volume";
  if (!why.empty()) {
    report("with the input weights " + why + "; every weight is reset to 0 (equal weights give every site a "
           "cell with a volume)");
    for (Site& s : sites) s.w = 0;
    state = evaluate(sites, targets, domain, quadrature, options.threads);
  }
  next_quadrature(std::max(max_mass_error(state, targets), max_median_error(state)));

  for (int iteration = 1; iteration <= options.max_iterations; ++iteration) {
    throw_if_cancelled(options.cancellation);
    Centroidal_iteration row{};
    row.iteration = iteration;
    row.energy_before = state.energy;

    // 1. Weight steps (weight_step.h), a second or third while the volumes lag far behind the medians.
    row.energy_error = state.energy_error;
    for (int newton = 0; newton < kWeightStepsPerIteration; ++newton) {
      if (newton > 0 && max_mass_error(state, targets) <= std::max(tolerance, 0.1 * tolerance / median_tolerance *
                                                                                  max_median_error(state)))
        break;
      const std::vector<double> direction = newton_weight_direction(state.measures, targets);
      const double floor = 0.5 * std::min(1.0, least_volume_ratio(state, targets));
      // The step s along it: from 1, then by safeguarded regula falsi on the slope (M - m) . delta, which
      // decreases in s (concavity) from its positive value at 0; a step with a defect counts as too long.
      // Accepted while the slope is still >= 0, or when E4 rose by enough (weight_step.h, (b) and (c)).
      const Directional_derivative at_zero = directional_derivative(state.measures, targets, direction);
      double low = 0, low_slope = at_zero.value, high = 1, step = 1;
      bool accepted = false;
      std::string last_defect;
      for (int trial_count = 0; trial_count < kMaxTrials && !accepted; ++trial_count) {
        std::vector<Site> trial = sites;
        for (std::size_t i = 0; i < n; ++i) trial[i].w += step * direction[i];
        Energy_evaluation evaluation = evaluate(trial, targets, domain, quadrature, options.threads);
        last_defect = defect(evaluation, targets, floor);
        const Directional_derivative slope = directional_derivative(evaluation.measures, targets, direction);
        const double gain = evaluation.energy - state.energy;
        const bool increases = gain >= std::max(kSufficientIncrease * step * at_zero.value,
                                                evaluation.energy_error + state.energy_error);
        if (last_defect.empty() && (slope.value >= -slope.uncertainty || increases)) {
          accepted = true;
          row.weight_retries += trial_count;
          row.energy_error += evaluation.energy_error;
          sites = std::move(trial);
          state = std::move(evaluation);
          break;
        }
        high = step;
        if (!last_defect.empty() || !(low_slope > 0)) {
          step = 0.5 * (low + high);
        } else {
          const double secant = low + (high - low) * low_slope / (low_slope - slope.value);
          step = std::clamp(secant, low + 0.1 * (high - low), low + 0.9 * (high - low));
        }
      }
      if (!accepted) {
        report("iteration " + std::to_string(iteration) + ": no weight step was accepted in " +
               std::to_string(kMaxTrials) + " trials (" +
               (last_defect.empty() ? "E4 would decrease" : "after it " + last_defect) + "); the weights are kept");
        row.weight_retries += kMaxTrials;
        break;
      }
    }
    row.energy = state.energy;
    row.mass_error = max_mass_error(state, targets);
    row.median_error = options.move_sites ? max_median_error(state) : 0;

    // 2. Stop?
    if (row.mass_error <= tolerance && row.median_error <= median_tolerance) {
      row.seconds = seconds();
      result.history.push_back(row);
      if (options.on_iteration) options.on_iteration(row);
      result.converged = true;
      break;
    }

    // 3. Site step (median_step.h).
    if (options.move_sites) {
      const Median_steps plain = median_steps(sites, state.measures, domain);
      // The accelerated step first, the plain one if it is refused (anderson_acceleration.h).
      std::vector<double> x(3 * n), f(3 * n);
      for (std::size_t i = 0; i < n; ++i) {
        x[3 * i] = sites[i].x, x[3 * i + 1] = sites[i].y, x[3 * i + 2] = sites[i].z;
        for (int a = 0; a < 3; ++a) f[3 * i + a] = plain.step[i][a];
      }
      const std::vector<double> mixed = acceleration.step(x, f);
      std::vector<Vector3> accelerated(n);
      bool inside = true;
      for (std::size_t i = 0; i < n; ++i)
        for (int a = 0; a < 3; ++a) {
          accelerated[i][a] = mixed[3 * i + a];
          const double c = x[3 * i + a] + mixed[3 * i + a];
          inside = inside && c > domain.lo[a] && c < domain.hi[a];
        }
      for (Site_index i : plain.shortened)
        report("iteration " + std::to_string(iteration) + ": the median step of site " + std::to_string(i) +
               " would leave the domain or come near its boundary; shortened");
      const double site_floor = 0.5 * std::min(1.0, least_volume_ratio(state, targets));
      const auto try_steps = [&](const std::vector<Vector3>& steps, bool quiet) {
        double fraction = 1;
        for (int halving = 0; halving <= kMaxHalvings; ++halving, fraction *= 0.5) {
          std::vector<Site> trial = sites;
          for (std::size_t i = 0; i < n; ++i) {
            trial[i].x += fraction * steps[i][0];
            trial[i].y += fraction * steps[i][1];
            trial[i].z += fraction * steps[i][2];
          }
          Energy_evaluation evaluation = evaluate(trial, targets, domain, quadrature, options.threads);
          const std::string why = defect(evaluation, targets, site_floor);
          if (why.empty()) {
            for (std::size_t i = 0; i < n; ++i)
              row.largest_move = std::max(row.largest_move, fraction * std::sqrt(dot(steps[i], steps[i])));
            sites = std::move(trial);
            state = std::move(evaluation);
            return true;
          }
          if (quiet) return false;
          report("iteration " + std::to_string(iteration) + ": the site step is halved: after it " + why);
        }
        report("iteration " + std::to_string(iteration) + ": the sites are kept");
        return false;
      };
      if (!inside || !try_steps(accelerated, true)) {
        acceleration.restart();
        try_steps(plain.step, false);
      }
    }
    next_quadrature(std::min(row.mass_error, std::max(row.median_error, max_mass_error(state, targets))));
    row.seconds = seconds();
    result.history.push_back(row);
    if (options.on_iteration) options.on_iteration(row);
  }
  result.sites = sites;
  for (const Cell_measure& m : state.measures) result.volumes.push_back(m.volume);
  return result;
}

}  // namespace apollonius
