#include "cli/diagram_command.h"

#include <chrono>
#include <memory>

#include "cli/octree_statistics_output.h"
#include "io/write_topology.h"
#include "octree/octree_diagram.h"
#include "predicates/predicate_counter.h"
#include "topology/build_topology.h"
#include "topology/validate_topology.h"

namespace apollonius {
namespace {

struct Diagram_command {
  std::string input;
  std::string output;
  std::string format = "json";
  bool stats = false;
  Diagram_options diagram;
};

int run(const Diagram_command& command, std::ostream& out, std::ostream& err) {
  const Site_input input = read_sites(command.input, command.diagram.read_options);
  reset_predicate_statistics();
  const auto start = std::chrono::steady_clock::now();
  Octree_regions regions;
  Octree_statistics octree_statistics;
  Diagram vertices = octree_diagram(input.sites, Octree_options{command.diagram.threads, &octree_statistics,
                                                                Arithmetic::certified, &regions});
  const auto after_vertices = std::chrono::steady_clock::now();
  Diagram_topology topology = build_topology(input.sites, std::move(vertices), regions, {command.diagram.threads});
  validate_topology(input.sites, topology);  // a violation is an internal error: no output
  const auto end = std::chrono::steady_clock::now();
  const std::vector<Predicate_statistics> stats = predicate_statistics();
  write_command_output(command.output, out, [&](std::ostream& o) {
    if (command.format == "topology")
      write_diagram_topology(o, topology);
    else
      write_diagram_json(o, topology, command.stats ? &stats : nullptr);
  });
  const auto written = std::chrono::steady_clock::now();
  if (command.stats) {
    err << "predicate evaluations exact_stages\n";
    for (const Predicate_statistics& s : stats) err << s.name << ' ' << s.evaluations << ' ' << s.exact_stages << '\n';
    err << "phase seconds\nvertices " << std::chrono::duration<double>(after_vertices - start).count()
        << "\ntopology " << std::chrono::duration<double>(end - after_vertices).count()
        << "\noutput " << std::chrono::duration<double>(written - end).count() << "\ndiagram count\nvertices "
        << topology.vertices.vertices.size() << "\nedges " << topology.edges.size() << "\nfaces " << topology.faces.size()
        << "\ncells " << topology.cells.size() << "\ntopology seconds\nedges " << topology.statistics.edges_seconds
        << "\nvertex_free " << topology.statistics.vertex_free_seconds << "\nfaces " << topology.statistics.faces_seconds
        << "\ntopology count\ncandidate_triples " << topology.statistics.candidate_triples << "\ncandidate_pairs "
        << topology.statistics.candidate_pairs << "\nnested_pairs " << topology.statistics.nested_pairs << '\n';
    print_octree_statistics(err, octree_statistics);
  }
  release_or_keep_until_exit(std::move(topology));
  release_or_keep_until_exit(std::move(regions));
  return EXIT_OK;
}

}  // namespace

Command_run add_diagram_command(CLI::App& app) {
  auto command = std::make_shared<Diagram_command>();
  CLI::App* sub = app.add_subcommand(
      "diagram",
      "The whole diagram in R^3: vertices, edges (with their exact order along their curves, closed and\n"
      "infinite ones included), faces with their boundaries and holes, and cells, checked by the Euler\n"
      "relation before it is written.");
  sub->add_option("INPUT", command->input, "the sites, as for 'vertices' (- for standard input)")->required();
  add_output_option(*sub, command->output);
  sub->add_option("--format", command->format,
                  "json (ids, ends, boundaries) or topology (the tie sets of faces, edges and vertices)")
      ->check(CLI::IsMember({"json", "topology"}))
      ->capture_default_str();
  sub->add_flag("--stats", command->stats, "predicate counts and phase times on standard error");
  add_diagram_options(*sub, command->diagram);
  return [command](std::ostream& out, std::ostream& err) { return run(*command, out, err); };
}

}  // namespace apollonius
