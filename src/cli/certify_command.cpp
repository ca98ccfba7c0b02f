#include "cli/certify_command.h"

#include <algorithm>
#include <memory>
#include <optional>

#include "certify/certify_report.h"
#include "certify/claimed_topology.h"
#include "certify/claimed_vertices.h"
#include "certify/judge_claims.h"
#include "certify/judge_links.h"
#include "certify/judge_topology.h"
#include "certify/topology_report.h"
#include "io/atomic_file.h"
#include "io/read_sites.h"
#include "io/text_input.h"
#include "octree/octree_diagram.h"
#include "topology/build_topology.h"
#include "topology/topology_tie_sets.h"
#include "topology/validate_topology.h"

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

// The whole diagram, validated: what topology claims and links are judged against.
Diagram_topology whole_diagram(const std::vector<Site>& sites, int threads) {
  Octree_regions regions;
  Diagram vertices = octree_diagram(sites, Octree_options{threads, nullptr, Arithmetic::certified, &regions});
  Diagram_topology topology = build_topology(sites, std::move(vertices), regions, {threads});
  validate_topology(sites, topology);  // a violation is an internal error
  return topology;
}

int certify_topology(const Certify_command& command, const std::vector<Site>& sites, const std::string& content,
                     const std::string& claim_name, std::ostream& err) {
  const Claimed_topology claim = read_claimed_topology(content, claim_name, sites.size());
  const Diagram_topology topology = whole_diagram(sites, command.diagram.threads);
  const Topology_certification certification = judge_topology(topology_tie_sets(topology), claim);
  const Topology_report report{input_name(command.input), claim_name, topology.vertices, claim, certification, command.strict};
  if (!command.report.empty())
    write_file_atomically(command.report, [&](std::ostream& out) { write_topology_report_json(out, report); });
  write_topology_summary(err, report);
  return discrepancy_count(report) == 0 ? EXIT_OK : EXIT_DISCREPANCIES;
}

int run(const Certify_command& command, std::ostream& err) {
  if (command.input == "-" && command.claim == "-") throw Usage_error("INPUT and CLAIM cannot both be standard input");
  // Every input is read and checked before the diagram is computed, so bad input fails at once.
  const std::vector<Site> sites = read_sites(command.input, command.diagram.read_options).sites;
  const std::string claim_name = input_name(command.claim);
  const std::string content = read_input_file(command.claim);
  const Claim_format format = command.format.empty() ? detect_claim_format(content) : *claim_format_from_name(command.format);
  if (format == Claim_format::topology) return certify_topology(command, sites, content, claim_name, err);
  const Claimed_vertex_list claims = read_claimed_vertices(content, claim_name, format, sites.size());

  // Links are judged against the edges of the whole diagram; plain vertex lists need only the vertices.
  const bool has_links = std::any_of(claims.vertices.begin(), claims.vertices.end(),
                                     [](const Claimed_vertex& claim) { return claim.links.has_value(); });
  std::optional<Diagram_topology> topology;
  if (has_links) topology = whole_diagram(sites, command.diagram.threads);
  const Diagram diagram = has_links ? Diagram{} : octree_diagram(sites, Octree_options{command.diagram.threads});
  const Diagram& vertices = has_links ? topology->vertices : diagram;
  const Coordinate_tolerance tolerance{command.relative_tolerance, input_scale(sites)};
  const Certification certification = judge_claims(sites, vertices, claims.vertices, tolerance);
  std::optional<Link_certification> links;
  if (has_links) links = judge_links(*topology, claims.vertices, certification);

  const Certify_report report{input_name(command.input), claim_name, vertices, claims, certification, command.strict,
                              links ? &*links : nullptr, topology ? &*topology : nullptr};
  if (!command.report.empty())
    write_file_atomically(command.report, [&](std::ostream& out) { write_certify_report_json(out, report); });
  write_certify_summary(err, report);
  return discrepancy_count(report) == 0 ? EXIT_OK : EXIT_DISCREPANCIES;
}

}  // namespace

Command_run add_certify_command(CLI::App& app) {
  auto command = std::make_shared<Certify_command>();
  CLI::App* sub = app.add_subcommand(
      "certify",
      "Judges CLAIM, another implementation's vertex list or topology for INPUT, against the exact diagram.\n"
      "Each claimed vertex is confirmed, surplus (another claim of a vertex with 5 or more tied sites),\n"
      "duplicate, coordinates off, wrong root (the other root of its sites) or not a vertex; certified\n"
      "vertices that no claim represents are missing. Voronota's --link links are right, wrong, missing or\n"
      "not judged (degenerate). Each claimed bisector, trisector and quadrisector is confirmed, partial (part\n"
      "of a degenerate tie set), duplicate or spurious; exact ones not claimed are missing. Exit 1 on any\n"
      "discrepancy (every verdict but confirmed, surplus, partial, right and not judged).\n"
      "A summary goes to standard error; --report writes every verdict as JSON.");
  sub->add_option("INPUT", command->input, "the sites, as for 'vertices' (- for standard input)")->required();
  sub->add_option("CLAIM", command->claim, "the claimed vertex list (- for standard input)")->required();
  sub->add_option("--format", command->format,
                  "text (4 or more site indices, then x y z r), json (as 'vertices --format json'), voronota\n"
                  "('calculate-vertices' output, with or without --link) or topology (as 'diagram --format\n"
                  "topology': the tie sets of faces, edges and vertices). Default: by content")
      ->check(CLI::IsMember({"text", "json", "voronota", "topology"}));
  sub->add_option("--report", command->report, "every verdict as JSON, written atomically")->type_name("R.json");
  sub->add_flag("--strict", command->strict, "surplus claims and partial sets are discrepancies too");
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
