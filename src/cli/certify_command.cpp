#include "cli/certify_command.h"

#include <memory>
#include <optional>

#include "certify/certify_report.h"
#include "certify/claimed_vertices.h"
#include "certify/judge_claims.h"
#include "io/atomic_file.h"
#include "io/read_sites.h"
#include "io/text_input.h"
#include "octree/octree_diagram.h"

namespace apollonius {
namespace {

struct Certify_command {
  std::string input;
  std::string claim;
  std::string format;  // empty: detect
  std::string report;  // empty: no report file
  bool strict = false;
  double relative_tolerance = 1e-9;
  Diagram_options diagram;
};

int run(const Certify_command& command, std::ostream& err) {
  if (command.input == "-" && command.claim == "-") throw Usage_error("INPUT and CLAIM cannot both be standard input");
  std::optional<Claim_format> format;
  if (!command.format.empty()) format = claim_format_from_name(command.format);
  // Every input is read and checked before the diagram is computed, so bad input fails at once.
  const std::vector<Site> sites = read_sites(command.input, command.diagram.read_options).sites;
  const std::string claim_name = input_name(command.claim);
  const Claimed_vertex_list claims = read_claimed_vertices(read_input_file(command.claim), claim_name, format, sites.size());

  const Diagram diagram = octree_diagram(sites, Octree_options{command.diagram.threads});
  const Coordinate_tolerance tolerance{command.relative_tolerance, input_scale(sites)};
  const Certification certification = judge_claims(sites, diagram, claims.vertices, tolerance);

  const Certify_report report{input_name(command.input), claim_name, diagram, claims, certification, command.strict};
  if (!command.report.empty())
    write_file_atomically(command.report, [&](std::ostream& out) { write_certify_report_json(out, report); });
  write_certify_summary(err, report);
  return count_verdicts(certification, command.strict).discrepancies == 0 ? EXIT_OK : EXIT_DISCREPANCIES;
}

}  // namespace

Command_run add_certify_command(CLI::App& app) {
  auto command = std::make_shared<Certify_command>();
  CLI::App* sub = app.add_subcommand(
      "certify",
      "Judges CLAIM, another implementation's vertex list for INPUT, against the exact diagram. Each claim\n"
      "is confirmed, surplus (another claim of a vertex with 5 or more tied sites), duplicate, coordinates\n"
      "off, wrong root (the other root of its sites) or not a vertex; certified vertices that no claim\n"
      "represents are missing. Exit 1 on a missing vertex or on any verdict but confirmed and surplus.\n"
      "A summary goes to standard error; --report writes every verdict as JSON.");
  sub->add_option("INPUT", command->input, "the sites, as for 'vertices' (- for standard input)")->required();
  sub->add_option("CLAIM", command->claim, "the claimed vertex list (- for standard input)")->required();
  sub->add_option("--format", command->format,
                  "text (4 or more site indices, then x y z r), json (as 'vertices --format json') or voronota\n"
                  "('calculate-vertices' output, with or without --link). Default: by content")
      ->check(CLI::IsMember({"text", "json", "voronota"}));
  sub->add_option("--report", command->report, "every verdict as JSON, written atomically")->type_name("R.json");
  sub->add_flag("--strict", command->strict, "surplus claims are discrepancies too");
  sub->add_option("--coord-tol", command->relative_tolerance,
                  "a claimed value c passes if |c - e| <= T max(S, |e|), e the correctly rounded exact value\n"
                  "and S the largest |x|, |y|, |z|, |w| of the sites")
      ->check(CLI::NonNegativeNumber & finite_number)
      ->type_name("T")
      ->capture_default_str();
  add_diagram_options(*sub, command->diagram);
  return [command](std::ostream&, std::ostream& err) { return run(*command, err); };
}

}  // namespace apollonius
