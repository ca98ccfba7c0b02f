#include "cli/centroidal_command.h"

#include <iomanip>
#include <memory>
#include <optional>
#include <sstream>
#include <vector>

#include "centroidal/centroidal_diagram.h"
#include "io/input_error.h"
#include "io/read_masses.h"
#include "io/round_trip.h"
#include "io/write_sites.h"

namespace apollonius {
namespace {

// Runs longer than this print a progress line per iteration on standard error.
constexpr double kQuietSeconds = 1;

struct Centroidal_command {
  std::string input;
  std::vector<double> domain;  // X0 Y0 Z0 X1 Y1 Z1
  std::string masses;          // empty: equal masses
  double tolerance = 1e-6;
  std::optional<double> median_tolerance;  // nothing: tolerance
  int max_iterations = 100;
  std::string output;
  std::string history;
  Diagram_options diagram;
};

void write_history(std::ostream& out, const std::vector<Centroidal_iteration>& history) {
  out << "iteration,E4,max_relative_mass_error,largest_site_move,seconds,median_residual,E4_before_weight_step,"
         "E4_error_estimate,weight_retries\n";
  for (const Centroidal_iteration& r : history)
    out << r.iteration << ',' << round_trip(r.energy) << ',' << round_trip(r.mass_error) << ','
        << round_trip(r.largest_move) << ',' << round_trip(r.seconds) << ',' << round_trip(r.median_error) << ','
        << round_trip(r.energy_before) << ',' << round_trip(r.energy_error) << ',' << r.weight_retries << '\n';
}

int run(const Centroidal_command& command, std::ostream& out, std::ostream& err) {
  Axis_box domain;
  for (int a = 0; a < 3; ++a) domain.lo[a] = command.domain[a], domain.hi[a] = command.domain[a + 3];
  // The options first, as the library checks them (centroidal_parameters.h), before any file is read.
  try {
    check_centroidal_domain(domain);
    check_centroidal_tolerance(command.tolerance);
    if (command.median_tolerance)
      check_centroidal_tolerance(*command.median_tolerance, Centroidal_parameter::median_tolerance);
    check_centroidal_iterations(command.max_iterations);
  } catch (const Centroidal_parameter_error& e) {
    const char* option = e.parameter == Centroidal_parameter::domain             ? "--domain"
                         : e.parameter == Centroidal_parameter::tolerance        ? "--tolerance"
                         : e.parameter == Centroidal_parameter::median_tolerance ? "--median-tolerance"
                                                                                 : "--max-iterations";
    throw Usage_error(std::string(option) + ": " + e.what());
  }

  const Site_input input = read_sites(command.input, command.diagram.read_options);
  const std::string input_file = command.input == "-" ? "<stdin>" : command.input;
  std::vector<double> masses;
  if (command.masses.empty())
    masses.assign(input.sites.size(), 1.0 / static_cast<double>(input.sites.size()));
  else
    masses = read_masses(command.masses, input.sites.size());
  Centroidal_options options;
  options.tolerance = command.tolerance;
  options.median_tolerance = command.median_tolerance;
  options.max_iterations = command.max_iterations;
  options.threads = command.diagram.threads;
  options.on_report = [&](const std::string& message) { err << "centroidal: " << message << '\n'; };
  options.on_iteration = [&](const Centroidal_iteration& r) {
    if (r.seconds < kQuietSeconds) return;
    err << "centroidal: iteration " << r.iteration << ", max relative mass error " << std::setprecision(3)
        << r.mass_error << ", median residual " << r.median_error << ", largest move " << r.largest_move
        << ", E4 " << std::setprecision(12) << r.energy << ", " << std::setprecision(3) << r.seconds << " s\n";
  };
  Centroidal_result result;
  try {
    result = centroidal_diagram(input.sites, masses, domain, options);
  } catch (const Centroidal_parameter_error& e) {
    // Bad parameters the library found (a site outside the domain, two sites at one centre), at the line of
    // the site they concern. The masses' own errors were found by read_masses, at theirs, with the same
    // reasons as the library's.
    const bool about_site = e.parameter == Centroidal_parameter::sites && e.site >= 0 &&
                            static_cast<std::size_t>(e.site) < input.lines.size();
    throw Input_error(input_file, about_site ? input.lines[e.site] : 0,
                      (e.site >= 0 ? "site " + std::to_string(e.site) + ": " : std::string()) + e.what());
  }

  const Centroidal_iteration& last = result.history.back();
  std::ostringstream comment;
  comment << "apollonius3d centroidal: " << (result.converged ? "converged" : "not converged") << " after "
          << result.history.size() << " iterations; max relative mass error " << round_trip(last.mass_error)
          << ", median residual " << round_trip(last.median_error) << " (each with its quadrature error estimate), E4 "
          << round_trip(last.energy);
  write_command_output(command.output, out, [&](std::ostream& o) { write_sites_text(o, result.sites, comment.str()); });
  if (!command.history.empty())
    write_command_output(command.history, out, [&](std::ostream& o) { write_history(o, result.history); });
  if (!result.converged) {
    err << "centroidal: not converged within " << command.max_iterations << " iterations (max relative mass error "
        << round_trip(last.mass_error) << ", median residual " << round_trip(last.median_error) << ", tolerance "
        << round_trip(command.tolerance);
    if (command.median_tolerance) err << ", median tolerance " << round_trip(*command.median_tolerance);
    err << "); the outputs hold the state reached\n";
    return EXIT_DISCREPANCIES;
  }
  return EXIT_OK;
}

}  // namespace

Command_run add_centroidal_command(CLI::App& app) {
  auto command = std::make_shared<Centroidal_command>();
  CLI::App* sub = app.add_subcommand(
      "centroidal",
      "The centroidal Apollonius diagram in a box (paper section 7): moves the sites to the geometric medians\n"
      "of their cells and sets the weights so that each cell holds its target volume. Writes the final sites\n"
      "'x y z w'. The diagrams are certified; the volumes and medians are cubatures with error estimates.");
  sub->add_option("INPUT", command->input, "the initial sites: balls text 'x y z w', vdrc, PDB/mmCIF, or -")
      ->required();
  sub->add_option("--domain", command->domain, "the box X0 Y0 Z0 X1 Y1 Z1, which must contain every site")
      ->required()
      ->expected(6)
      ->check(finite_number)
      ->type_name("X0 Y0 Z0 X1 Y1 Z1");
  sub->add_option("--masses", command->masses,
                  "one target volume per site per line, as fractions of the domain's volume summing to 1\n"
                  "(default: equal)")
      ->type_name("FILE");
  sub->add_option("--tolerance", command->tolerance,
                  "stop when every relative volume error |M_i - m_i| / M_i and every median residual, each\n"
                  "with its quadrature error estimate, is at most T")
      ->check(finite_number)
      ->type_name("T")
      ->capture_default_str();
  sub->add_option("--median-tolerance", command->median_tolerance,
                  "stop on the median residuals at T2 instead (default: T); the volumes still at T")
      ->check(finite_number)
      ->type_name("T2");
  sub->add_option("--max-iterations", command->max_iterations, "stop after K iterations (exit 1 if not converged)")
      ->check(integer_in_range(1, kMostCentroidalIterations))
      ->type_name("K")
      ->capture_default_str();
  add_output_option(*sub, command->output);
  sub->add_option("--history", command->history, "one CSV row per iteration, written atomically")->type_name("H.csv");
  add_diagram_options(*sub, command->diagram);
  return [command](std::ostream& out, std::ostream& err) { return run(*command, out, err); };
}

}  // namespace apollonius
