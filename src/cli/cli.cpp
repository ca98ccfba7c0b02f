#include "cli/cli.h"

#include <functional>
#include <optional>
#include <ostream>
#include <stdexcept>

#include "reference/brute_force_diagram.h"
#include "cli/certify_command.h"
#include "cli/crosscheck_command.h"
#include "cli/arguments.h"
#include "cli/generate_command.h"
#include "octree/octree_diagram.h"
#include "io/input_error.h"
#include "io/read_sites.h"
#include "io/write_vertices.h"
#include "predicates/predicate_counter.h"

namespace apollonius {
namespace {

constexpr const char* kVerticesUsage =
    "usage: apollonius3d vertices INPUT [-o OUT] [--format text|json] [--algorithm octree|brute]\n"
    "                             [--arith certified|float] [--threads N] [--box X0 Y0 Z0 X1 Y1 Z1] [--stats]\n"
    "                             [--keep-hydrogens] [--keep-waters]\n"
    "  INPUT: balls text 'x y z w', vdrc .txt, PDB/mmCIF (optionally .gz), or - for stdin\n"
    "  Prints every vertex of the Apollonius diagram in R^3 (or in the closed --box): its tie-set site\n"
    "  indices (0-based), then x y z r. --algorithm brute is the O(n^5) reference. --arith float runs the\n"
    "  octree in plain doubles, no filter and no exact stage: uncertified, for comparison only.\n";

constexpr const char* kExitCodes =
    "exit codes: 0 ok, 1 discrepancies (certify, crosscheck), 2 usage or input error, 3 internal error\n";

void print_usage(std::ostream& out) {
  out << kVerticesUsage << certify_usage << crosscheck_usage << generate_usage << kExitCodes;
}

struct Vertices_command {
  std::string input;
  std::string output;  // empty: standard output
  std::string format = "text";
  bool format_given = false;
  bool stats = false;
  bool brute_force = false;
  Arithmetic arithmetic = Arithmetic::certified;
  std::optional<Axis_box> box;
  Diagram_options diagram;
};

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

Vertices_command parse_vertices(const std::vector<std::string>& args) {
  Vertices_command command;
  for (std::size_t i = 1; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "-o" || a == "--output") {
      command.output = option_value(args, i);
    } else if (a == "--format") {
      command.format = option_value(args, i);
      command.format_given = true;
      if (command.format != "text" && command.format != "json")
        throw Usage_error("unknown format '" + command.format + "' (text or json)");
    } else if (a == "--algorithm") {
      const std::string& algorithm = option_value(args, i);
      if (algorithm != "brute" && algorithm != "octree")
        throw Usage_error("unknown algorithm '" + algorithm + "' (octree or brute)");
      command.brute_force = algorithm == "brute";
    } else if (a == "--arith") {
      const std::string& arithmetic = option_value(args, i);
      if (arithmetic != "certified" && arithmetic != "float")
        throw Usage_error("unknown arithmetic '" + arithmetic + "' (certified or float)");
      command.arithmetic = arithmetic == "float" ? Arithmetic::floating : Arithmetic::certified;
    } else if (a == "--box") {
      if (i + 6 >= args.size()) throw Usage_error("option --box needs 6 numbers X0 Y0 Z0 X1 Y1 Z1");
      Axis_box box;
      for (int k = 0; k < 6; ++k) (k < 3 ? box.lo[k] : box.hi[k - 3]) = parse_option_number(args[++i], a);
      for (int k = 0; k < 3; ++k)
        if (!(box.lo[k] <= box.hi[k])) throw Usage_error("option --box needs X0 <= X1, Y0 <= Y1, Z0 <= Z1");
      command.box = box;
    } else if (a == "--stats") {
      command.stats = true;
    } else {
      parse_diagram_option_or_input(args, i, command.diagram, command.input);
    }
  }
  if (command.input.empty()) throw Usage_error("missing INPUT");
  if (command.brute_force && command.arithmetic == Arithmetic::floating)
    throw Usage_error("--arith float runs the octree only (--algorithm brute is the certified reference)");
  if (!command.format_given && ends_with(command.output, ".json")) command.format = "json";
  return command;
}

void print_statistics(std::ostream& err, const std::vector<Predicate_statistics>& stats) {
  err << "predicate evaluations exact_stages\n";
  for (const Predicate_statistics& s : stats) err << s.name << ' ' << s.evaluations << ' ' << s.exact_stages << '\n';
}

void print_octree_statistics(std::ostream& err, const Octree_statistics& s) {
  err << "phase seconds\n"
      << "partition " << s.partition_seconds << "\npropagation " << s.propagation_seconds << "\nrefinement "
      << s.refinement_seconds << "\nfar_field " << s.far_field_seconds << "\nassembly " << s.assembly_seconds << '\n'
      << "octree count\n"
      << "seed_boxes " << s.seed_boxes << "\nseed_candidates " << s.seed_candidates << "\nescaping_sites "
      << s.escaping_sites << "\nboxes " << s.boxes << "\nleaves " << s.leaves << "\nleaf_candidates "
      << s.leaf_candidates << "\nquadruples " << s.quadruples << "\ndistinct_quadruples " << s.distinct_quadruples
      << "\nfar_field_quadruples " << s.far_field_quadruples << '\n';
}

int run_vertices(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  const Vertices_command command = parse_vertices(args);
  const Site_input input = read_sites(command.input, command.diagram.read_options);
  reset_predicate_statistics();
  Octree_statistics octree_statistics;
  Diagram diagram = command.brute_force
                        ? brute_force_diagram(input.sites)
                        : octree_diagram(input.sites, Octree_options{command.diagram.threads, &octree_statistics, command.arithmetic});
  if (command.box) restrict_to_box(diagram, *command.box);
  const std::vector<Predicate_statistics> stats = predicate_statistics();

  const std::function<void(std::ostream&)> write = [&](std::ostream& o) {
    if (command.format == "json")
      write_vertices_json(o, diagram, command.stats ? &stats : nullptr);
    else
      write_vertices_text(o, diagram);
  };
  write_command_output(command.output, out, write);
  if (command.stats) {
    print_statistics(err, stats);
    if (!command.brute_force) print_octree_statistics(err, octree_statistics);
  }
  return EXIT_OK;
}

}  // namespace

int run_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  try {
    if (args.empty()) throw Usage_error("missing command");
    if (args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
      print_usage(out);
      return EXIT_OK;
    }
    if (args[0] == "vertices") return run_vertices(args, out, err);
    if (args[0] == "certify") return run_certify(args, err);
    if (args[0] == "crosscheck") return run_crosscheck(args, out, err);
    if (args[0] == "generate") return run_generate(args, out);
    throw Usage_error("unknown command '" + args[0] + "'");
  } catch (const Usage_error& e) {
    err << "apollonius3d: " << e.what() << '\n';
    print_usage(err);
    return EXIT_BAD_INPUT;
  } catch (const Input_error& e) {
    err << "apollonius3d: " << e.what() << '\n';
    return EXIT_BAD_INPUT;
  } catch (const std::exception& e) {
    err << "apollonius3d: internal error: " << e.what() << '\n';
    return EXIT_INTERNAL_ERROR;
  }
}

}  // namespace apollonius
