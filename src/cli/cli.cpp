#include "cli/cli.h"

#include <ostream>
#include <utility>

#include "cli/centroidal_command.h"
#include "cli/contacts_command.h"
#include "cli/certify_command.h"
#include "cli/crosscheck_command.h"
#include "cli/diagram_command.h"
#include "cli/generate_command.h"
#include "cli/mesh_command.h"
#include "cli/vertices_command.h"
#include "io/atomic_file.h"
#include "io/input_error.h"

namespace apollonius {
namespace {

constexpr const char* kExitCodes =
    "Exit codes: 0 ok, 1 discrepancies (certify, crosscheck) or not converged (centroidal), 2 usage or input\n"
    "error, 3 internal error.";

// "apollonius3d" or "apollonius3d COMMAND", whichever the arguments reached.
std::string command_path(const CLI::App& app) {
  for (const CLI::App* sub : app.get_subcommands()) return app.get_name() + " " + sub->get_name();
  return app.get_name();
}

// One line saying what is wrong, one pointing to the help.
int usage_error(std::ostream& err, const CLI::App& app, const std::string& message) {
  const std::string path = command_path(app);
  err << path << ": " << message << "\nRun '" << path << " --help' for the options.\n";
  return EXIT_BAD_INPUT;
}

}  // namespace

int run_cli(const std::vector<std::string>& arguments, std::ostream& out, std::ostream& err) {
  CLI::App app("apollonius3d: the exact 3D Apollonius diagram (additively weighted Voronoi diagram, Voronoi\n"
               "diagram of balls), every decision an exact sign.",
               "apollonius3d");
  app.set_version_flag("--version", std::string("apollonius3d ") + APOLLONIUS3D_VERSION);
  app.require_subcommand(1);
  app.footer(kExitCodes);
  app.get_formatter()->column_width(30);
  const std::pair<const char*, Command_registration> registrations[] = {
      {"vertices", add_vertices_command},
      {"diagram", add_diagram_command},
      {"certify", add_certify_command},
      {"crosscheck", add_crosscheck_command},
      {"generate", add_generate_command},
      {"centroidal", add_centroidal_command},
      {"contacts", add_contacts_command},
      {"mesh", add_mesh_command},
  };
  std::vector<std::pair<CLI::App*, Command_run>> commands;
  for (const auto& [name, add] : registrations) {
    Command_run run = add(app);
    commands.emplace_back(app.get_subcommand(name), std::move(run));
  }

  // CLI11 would only say that a subcommand is required.
  if (!arguments.empty() && !arguments[0].empty() && arguments[0][0] != '-') {
    bool known = false;
    std::string names;
    for (const auto& [name, add] : registrations) {
      known = known || arguments[0] == name;
      names += (names.empty() ? "" : ", ") + std::string(name);
    }
    if (!known) return usage_error(err, app, "unknown command '" + arguments[0] + "' (" + names + ")");
  }
  try {
    std::vector<std::string> reversed(arguments.rbegin(), arguments.rend());  // CLI11 parses from the back
    app.parse(reversed);
  } catch (const CLI::CallForHelp&) {
    out << app.help();
    return EXIT_OK;
  } catch (const CLI::CallForAllHelp&) {
    out << app.help("", CLI::AppFormatMode::All);
    return EXIT_OK;
  } catch (const CLI::CallForVersion& e) {
    out << e.what() << '\n';
    return EXIT_OK;
  } catch (const CLI::ParseError& e) {
    return usage_error(err, app, e.what());
  }

  try {
    for (const auto& [sub, run] : commands)
      if (sub->parsed()) return run(out, err);
    return usage_error(err, app, "missing command");
  } catch (const Usage_error& e) {
    return usage_error(err, app, e.what());
  } catch (const Input_error& e) {
    err << "apollonius3d: " << e.what() << '\n';
    return EXIT_BAD_INPUT;
  } catch (const Output_error& e) {
    err << "apollonius3d: " << e.what() << '\n';
    return EXIT_BAD_INPUT;
  } catch (const std::exception& e) {
    err << "apollonius3d: internal error: " << e.what() << '\n';
    return EXIT_INTERNAL_ERROR;
  }
}

}  // namespace apollonius
