#include "cli/contacts_command.h"

#include <chrono>
#include <memory>

#include "io/round_trip.h"
#include "io/write_contacts.h"
#include "io/input_error.h"
#include "measure/contact_measures.h"
#include "measure/exit_regions.h"

namespace apollonius {
namespace {

// Below 1e-10 the cubature's rounding leaves its error estimates too little room (as for centroidal).
constexpr double kLeastTolerance = 1e-10, kGreatestTolerance = 0.5;

struct Contacts_command {
  std::string input;
  std::string output;
  std::string format = "text";
  std::string volumes_output;
  double probe = 1.4;
  double tolerance = 1e-4;
  bool stats = false;
  Diagram_options diagram;
};

int run(const Contacts_command& command, std::ostream& out, std::ostream& err) {
  if (!(command.probe >= 0)) throw Usage_error("--probe must be a number >= 0, not " + round_trip(command.probe));
  if (!(command.tolerance >= kLeastTolerance && command.tolerance <= kGreatestTolerance))
    throw Usage_error("--tolerance must lie in [1e-10, 0.5], not " + round_trip(command.tolerance));
  const Site_input input = read_sites(command.input, command.diagram.read_options);
  Contact_options options;
  options.probe = command.probe;
  options.relative_tolerance = command.tolerance;
  options.threads = command.diagram.threads;
  const auto start = std::chrono::steady_clock::now();
  Contact_measures measures;
  try {
    measures = measure_contacts(input.sites, options);
  } catch (const Unmeasurable_pair& e) {
    const std::size_t line = input.lines.empty() ? 0 : input.lines[e.b];
    throw Input_error(command.input, line, e.what());
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  write_command_output(command.output, out, [&](std::ostream& o) {
    if (command.format == "json")
      write_contacts_json(o, measures, options);
    else
      write_contacts_text(o, measures);
  });
  if (!command.volumes_output.empty())
    write_command_output(command.volumes_output, out, [&](std::ostream& o) { write_contact_volumes_text(o, measures); });
  if (command.stats)
    err << "contacts count\nballs " << input.sites.size() << "\nhidden " << measures.hidden.size() << "\ncontacts "
        << measures.contacts.size() << "\nrays " << measures.directions << "\ncontacts seconds\nmeasure " << seconds << '\n';
  return EXIT_OK;
}

}  // namespace

Command_run add_contacts_command(CLI::App& app) {
  auto command = std::make_shared<Contacts_command>();
  CLI::App* sub = app.add_subcommand(
      "contacts",
      "Contacts between balls as Voronota's calculate-contacts defines them, on the exact diagram: the area\n"
      "of each face where it lies within the probe of its balls (d <= P), each ball's solvent-accessible\n"
      "area (its sphere of radius w + P inside its cell) and its cell's volume there. Text: 'i j area' (i < j)\n"
      "and 'i i sas'. APPROXIMATE: cubatures; the JSON gives each estimated error. Hidden balls have none.");
  sub->add_option("INPUT", command->input, "the balls, as for 'vertices' (- for standard input)")->required();
  add_output_option(*sub, command->output);
  sub->add_option("--format", command->format, "text (as Voronota) or json (with the cells and every error estimate)")
      ->check(CLI::IsMember({"text", "json"}))
      ->capture_default_str();
  sub->add_option("--probe", command->probe, "the probe radius P (Voronota's default)")
      ->check(finite_number)
      ->type_name("P")
      ->capture_default_str();
  sub->add_option("--tolerance", command->tolerance,
                  "per cell, estimated errors at most T times its volume and its boundary's area")
      ->check(finite_number)
      ->type_name("T")
      ->capture_default_str();
  sub->add_option("--volumes-output", command->volumes_output, "writes 'i volume' per ball, atomically")
      ->type_name("F");
  sub->add_flag("--stats", command->stats, "counts (rays evaluated) and time on standard error");
  add_diagram_options(*sub, command->diagram);
  return [command](std::ostream& out, std::ostream& err) { return run(*command, out, err); };
}

}  // namespace apollonius
