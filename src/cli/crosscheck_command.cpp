#include "cli/crosscheck_command.h"

#include "cli/arguments.h"
#include "cli/cli.h"
#include "certify/crosscheck.h"
#include "io/read_sites.h"
#include "octree/octree_diagram.h"

namespace apollonius {

const char* const crosscheck_usage =
    "usage: apollonius3d crosscheck INPUT [-o OUT] [--coord-tol T] [--threads N] [--keep-hydrogens]\n"
    "                               [--keep-waters]\n"
    "  Runs the octree certified and in plain doubles (--arith float) and prints every disagreement of\n"
    "  the float diagram, one per line: missing (a certified vertex the float path lacks), spurious (a float\n"
    "  vertex that is none), moved (the right vertex with coordinates off by more than T, as in certify, or\n"
    "  with only part of its tie set). Exit 1 if there is any.\n";

namespace {

struct Crosscheck_command {
  std::string input;
  std::string output;  // empty: standard output
  double relative_tolerance = 1e-9;
  Diagram_options diagram;
};

Crosscheck_command parse_crosscheck(const std::vector<std::string>& args) {
  Crosscheck_command command;
  for (std::size_t i = 1; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "-o" || a == "--output") {
      command.output = option_value(args, i);
    } else if (a == "--coord-tol") {
      command.relative_tolerance = parse_coordinate_tolerance(option_value(args, i));
    } else {
      parse_diagram_option_or_input(args, i, command.diagram, command.input);
    }
  }
  if (command.input.empty()) throw Usage_error("missing INPUT");
  return command;
}

}  // namespace

int run_crosscheck(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  const Crosscheck_command command = parse_crosscheck(args);
  const std::vector<Site> sites = read_sites(command.input, command.diagram.read_options).sites;
  const int threads = command.diagram.threads;
  const Diagram certified = octree_diagram(sites, Octree_options{threads});
  const Diagram floating = octree_diagram(sites, Octree_options{threads, nullptr, Arithmetic::floating});
  const Crosscheck check = crosscheck(sites, certified, floating, {command.relative_tolerance, input_scale(sites)});
  write_command_output(command.output, out, [&](std::ostream& o) { write_disagreements(o, check); });

  std::size_t count[3] = {0, 0, 0};
  for (const Disagreement& d : check.disagreements) ++count[static_cast<int>(d.kind)];
  err << "crosscheck: certified " << check.certified_vertices << " vertices, float " << check.float_vertices
      << "; agreeing " << check.agreeing << ", missing " << count[0] << ", spurious " << count[1] << ", moved "
      << count[2] << '\n';
  return check.disagreements.empty() ? EXIT_OK : EXIT_DISCREPANCIES;
}

}  // namespace apollonius
