#include "cli/certify_command.h"

#include <optional>

#include "certify/certify_report.h"
#include "certify/claimed_vertices.h"
#include "cli/arguments.h"
#include "cli/cli.h"
#include "io/atomic_file.h"
#include "io/read_sites.h"
#include "io/text_input.h"
#include "certify/judge_claims.h"
#include "octree/octree_diagram.h"

namespace apollonius {

const char* const certify_usage =
    "usage: apollonius3d certify INPUT CLAIM [--format text|json|voronota] [--report R.json] [--strict]\n"
    "                            [--coord-tol T] [--threads N] [--keep-hydrogens] [--keep-waters]\n"
    "  Judges CLAIM, another implementation's vertex list for INPUT (- reads stdin), against the exact\n"
    "  diagram. Each claim is confirmed, surplus (another claim of a vertex with 5 or more tied sites),\n"
    "  duplicate, coordinates off, wrong root (the other root of its sites) or not a vertex; certified\n"
    "  vertices that no claim represents are missing. Exit 1 on a missing vertex or on any verdict but\n"
    "  confirmed and surplus.\n"
    "  A summary goes to stderr; --report writes every verdict as JSON, atomically.\n"
    "  --format: text (4 or more site indices, then x y z r), json (as 'vertices --format json'),\n"
    "    voronota ('calculate-vertices' output, with or without --link). Default: by content; '{' is\n"
    "    json, a first line of 12 fields whose fifth is no integer is voronota --link, else text.\n"
    "  --coord-tol T: a claimed value c passes if |c - e| <= T * max(S, |e|), where e is the correctly\n"
    "    rounded exact value and S the largest |x|, |y|, |z|, |w| of INPUT's sites. Default T = 1e-9.\n"
    "  --strict: surplus claims are discrepancies too.\n";

namespace {

struct Certify_command {
  std::string input;
  std::string claim;
  std::optional<Claim_format> format;  // nothing: detect
  std::string report;                  // empty: no report file
  bool strict = false;
  double relative_tolerance = 1e-9;
  Diagram_options diagram;
};

Certify_command parse_certify(const std::vector<std::string>& args) {
  Certify_command command;
  std::vector<std::string> positional_arguments;
  for (std::size_t i = 1; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--format") {
      const std::string& name = option_value(args, i);
      command.format = claim_format_from_name(name);
      if (!command.format) throw Usage_error("unknown claim format '" + name + "' (text, json or voronota)");
    } else if (a == "--report") {
      command.report = option_value(args, i);
    } else if (a == "--strict") {
      command.strict = true;
    } else if (a == "--coord-tol") {
      command.relative_tolerance = parse_coordinate_tolerance(option_value(args, i));
    } else if (parse_diagram_option(args, i, command.diagram)) {
      // --threads, --keep-hydrogens, --keep-waters: recorded in command.diagram
    } else {
      positional_arguments.push_back(positional(a));
    }
  }
  if (positional_arguments.size() != 2) throw Usage_error("certify needs INPUT and CLAIM");
  command.input = positional_arguments[0];
  command.claim = positional_arguments[1];
  if (command.input == "-" && command.claim == "-") throw Usage_error("INPUT and CLAIM cannot both be stdin");
  return command;
}

}  // namespace

int run_certify(const std::vector<std::string>& args, std::ostream& err) {
  const Certify_command command = parse_certify(args);
  // Every input is read and checked before the diagram is computed, so bad input fails at once.
  const std::vector<Site> sites = read_sites(command.input, command.diagram.read_options).sites;
  const std::string claim_name = input_name(command.claim);
  const Claimed_vertex_list claims =
      read_claimed_vertices(read_input_file(command.claim), claim_name, command.format, sites.size());

  const Diagram diagram = octree_diagram(sites, Octree_options{command.diagram.threads});
  const Coordinate_tolerance tolerance{command.relative_tolerance, input_scale(sites)};
  const Certification certification = judge_claims(sites, diagram, claims.vertices, tolerance);

  const Certify_report report{input_name(command.input), claim_name, diagram, claims, certification, command.strict};
  if (!command.report.empty()) {
    try {
      write_file_atomically(command.report, [&](std::ostream& out) { write_certify_report_json(out, report); });
    } catch (const std::runtime_error& e) {
      throw Usage_error(e.what());
    }
  }
  write_certify_summary(err, report);
  return count_verdicts(certification, command.strict).discrepancies == 0 ? EXIT_OK : EXIT_DISCREPANCIES;
}

}  // namespace apollonius
