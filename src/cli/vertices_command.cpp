#include "cli/vertices_command.h"

#include <iterator>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli/octree_statistics_output.h"
#include "io/write_vertices.h"
#include "octree/octree_diagram.h"
#include "octree/vertex_algorithm.h"
#include "predicates/predicate_counter.h"
#include "reference/brute_force_diagram.h"

namespace apollonius {
namespace {

struct Vertices_command {
  std::string input;
  std::string output;
  std::string format;  // empty: json for an OUT ending in .json, else text
  bool stats = false;
  std::string algorithm = "auto";
  std::string arithmetic = "certified";
  std::vector<double> box;  // empty, or X0 Y0 Z0 X1 Y1 Z1
  Diagram_options diagram;
};

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

void print_statistics(std::ostream& err, const std::vector<Predicate_statistics>& stats) {
  err << "predicate evaluations exact_stages\n";
  for (const Predicate_statistics& s : stats) err << s.name << ' ' << s.evaluations << ' ' << s.exact_stages << '\n';
}

int run(const Vertices_command& command, std::ostream& out, std::ostream& err) {
  const bool brute_force = command.algorithm == "brute";
  const Arithmetic arithmetic = command.arithmetic == "float" ? Arithmetic::floating : Arithmetic::certified;
  if (brute_force && arithmetic == Arithmetic::floating)
    throw Usage_error("--arith float runs the octree only (--algorithm brute is the certified reference)");
  std::optional<Axis_box> box;
  if (!command.box.empty()) {
    box.emplace();
    for (int k = 0; k < 3; ++k) box->lo[k] = command.box[k], box->hi[k] = command.box[k + 3];
    for (int k = 0; k < 3; ++k)
      if (!(box->lo[k] <= box->hi[k])) throw Usage_error("--box needs X0 <= X1, Y0 <= Y1, Z0 <= Z1");
  }
  const std::string format =
      !command.format.empty() ? command.format : ends_with(command.output, ".json") ? "json" : "text";

  const Site_input input = read_sites(command.input, command.diagram.read_options);
  reset_predicate_statistics();
  Octree_statistics octree_statistics;
  Octree_options options{command.diagram.threads, &octree_statistics, arithmetic};
  if (!brute_force) use_vertex_algorithm(command.algorithm, options);  // a name CLI11 checked
  Diagram diagram = brute_force ? brute_force_diagram(input.sites) : octree_diagram(input.sites, options);
  if (box) restrict_to_box(diagram, *box);
  const std::vector<Predicate_statistics> stats = predicate_statistics();

  write_command_output(command.output, out, [&](std::ostream& o) {
    if (format == "json")
      write_vertices_json(o, diagram, command.stats ? &stats : nullptr);
    else
      write_vertices_text(o, diagram, command.diagram.threads);
  });
  if (command.stats) {
    print_statistics(err, stats);
    if (!brute_force) print_octree_statistics(err, octree_statistics);
  }
  release_or_keep_until_exit(std::move(diagram));
  return EXIT_OK;
}

}  // namespace

Command_run add_vertices_command(CLI::App& app) {
  auto command = std::make_shared<Vertices_command>();
  CLI::App* sub = app.add_subcommand(
      "vertices",
      "Every vertex of the Apollonius diagram in R^3 (or in the closed --box): its tie-set site indices\n"
      "(0-based, ascending, 4 or more), then x y z r, each the correctly rounded double of the exact value.");
  sub->add_option("INPUT", command->input,
                  "balls text 'x y z w', vdrc .txt, PDB/mmCIF (optionally .gz), or - for standard input")
      ->required();
  add_output_option(*sub, command->output);
  sub->add_option("--format", command->format, "text or json (default: json for an OUT ending in .json)")
      ->check(CLI::IsMember({"text", "json"}));
  sub->add_option("--algorithm", command->algorithm,
                  "auto (lifted up to 256 active sites, for balls of one radius, or where the octree would refine\n"
                  "through far more binades than the sites' spacing needs; else octree), octree (paper\n"
                  "section 5.2; it turns to lifted past 512 boxes or 128 seed candidates per site), lifted\n"
                  "(the 3-faces of the lifted regular triangulation in R^4; for one radius, the Delaunay\n"
                  "triangulation of the centres), or brute (the O(n^5) reference); all but brute\n"
                  "give the same bytes")
      ->check(CLI::IsMember([] {
        std::vector<std::string> names(std::begin(kVertexAlgorithms), std::end(kVertexAlgorithms));
        names.push_back("brute");
        return names;
      }()))
      ->capture_default_str();
  sub->add_option("--arith", command->arithmetic,
                  "certified, or float: the octree in plain doubles, uncertified, for comparison only")
      ->check(CLI::IsMember({"certified", "float"}))
      ->capture_default_str();
  sub->add_option("--box", command->box, "only the vertices in the closed box X0 Y0 Z0 X1 Y1 Z1")
      ->expected(6)
      ->check(finite_number)
      ->type_name("X0 Y0 Z0 X1 Y1 Z1");
  sub->add_flag("--stats", command->stats, "predicate counts and the octree's phase times on standard error");
  add_diagram_options(*sub, command->diagram);
  return [command](std::ostream& out, std::ostream& err) { return run(*command, out, err); };
}

}  // namespace apollonius
