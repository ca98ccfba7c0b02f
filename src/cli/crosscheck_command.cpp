#include "cli/crosscheck_command.h"

#include <memory>

#include "certify/crosscheck.h"
#include "io/read_sites.h"
#include "octree/octree_diagram.h"

namespace apollonius {
namespace {

struct Crosscheck_command {
  std::string input;
  std::string output;
  double relative_tolerance = 1e-9;
  Diagram_options diagram;
};

int run(const Crosscheck_command& command, std::ostream& out, std::ostream& err) {
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

}  // namespace

Command_run add_crosscheck_command(CLI::App& app) {
  auto command = std::make_shared<Crosscheck_command>();
  CLI::App* sub = app.add_subcommand(
      "crosscheck",
      "Runs the octree certified and in plain doubles (--arith float) and prints every disagreement of the\n"
      "float diagram, one per line: missing (a certified vertex the float path lacks), spurious (a float\n"
      "vertex that is none), moved (the right vertex with coordinates off by more than T, as in certify, or\n"
      "with only part of its tie set). Exit 1 if there is any.");
  sub->add_option("INPUT", command->input, "the sites, as for 'vertices' (- for standard input)")->required();
  add_output_option(*sub, command->output);
  sub->add_option("--coord-tol", command->relative_tolerance, "as for certify")
      ->check(CLI::NonNegativeNumber & finite_number)
      ->type_name("T")
      ->capture_default_str();
  add_diagram_options(*sub, command->diagram);
  return [command](std::ostream& out, std::ostream& err) { return run(*command, out, err); };
}

}  // namespace apollonius
