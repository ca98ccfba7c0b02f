#include "certify/certify_report.h"

#include <cstdio>

#include "io/json_output.h"
#include "io/round_trip.h"

namespace apollonius {
namespace {

Json json_vertex(const Diagram& diagram, std::size_t v) {
  const Diagram_vertex& vertex = diagram.vertices[v];
  Json json{{"index", v}, {"sites", vertex.tie_set}};
  add_point_members(json, vertex.rounded);
  return json;
}

Json json_claim(const Certify_report& report, std::size_t c) {
  const Claimed_vertex& claim = report.claims.vertices[c];
  const Claim_judgement& j = report.certification.claims[c];
  Json json{{"claim", c}, {"line", claim.line}, {"sites", claim.sites}};
  add_point_members(json, claim.point);
  json["verdict"] = name_of(j.verdict);
  json["discrepancy"] = is_discrepancy(j.verdict, report.strict);
  if (j.verdict == Verdict::not_a_vertex) json["reason"] = name_of(j.reason);
  if (j.vertex) {
    json["vertex"] = json_vertex(report.diagram, *j.vertex);
    json["absolute_error"] = json_number(j.error.absolute);
    json["relative_error"] = json_number(j.error.relative);
  }
  if (j.earlier_claim) {
    json["earlier_claim"] = *j.earlier_claim;
    json["earlier_line"] = report.claims.vertices[*j.earlier_claim].line;
  }
  if (j.point) {
    Json point = Json::object();
    add_point_members(point, *j.point);
    json["point"] = point;
    json["closer_site"] = j.closer_site;
  }
  if (j.hidden) {
    json["hidden_site"] = j.hidden->site;
    json["hidden_by"] = j.hidden->hidden_by;
    json["duplicate"] = j.hidden->duplicate;
  }
  return json;
}

std::string sites_text(const std::vector<Site_index>& sites) {
  std::string text;
  for (const Site_index s : sites) text += (text.empty() ? "" : " ") + std::to_string(s);
  return text;
}

std::string point_text(const std::array<double, 4>& p) {
  return "x y z r " + round_trip(p[0]) + " " + round_trip(p[1]) + " " + round_trip(p[2]) + " " + round_trip(p[3]);
}

std::string vertex_text(const Diagram& diagram, std::size_t v) {
  return "vertex " + std::to_string(v) + " (sites " + sites_text(diagram.vertices[v].tie_set) + ", " +
         point_text(diagram.vertices[v].rounded) + ")";
}

// Three significant digits: errors and tolerances for people to read.
std::string short_number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

std::string error_text(const Coordinate_error& error) {
  return "absolute " + short_number(error.absolute) + ", relative " + short_number(error.relative);
}

// One line: what is wrong with a claim.
std::string describe_claim(const Certify_report& report, std::size_t c) {
  const Claim_judgement& j = report.certification.claims[c];
  const std::vector<Claimed_vertex>& claims = report.claims.vertices;
  const std::string where = report.claim_name + ":" + std::to_string(claims[c].line) + ": ";
  switch (j.verdict) {
    case Verdict::confirmed:
      return where + "confirmed " + vertex_text(report.diagram, *j.vertex);
    case Verdict::surplus:
      return where + "surplus: another claim of " + vertex_text(report.diagram, *j.vertex) + ", first claimed on line " +
             std::to_string(claims[*j.earlier_claim].line);
    case Verdict::duplicate:
      return where + "duplicate of line " + std::to_string(claims[*j.earlier_claim].line);
    case Verdict::coordinates_off:
      return where + "coordinates off (" + error_text(j.error) + ") from " + vertex_text(report.diagram, *j.vertex);
    case Verdict::wrong_root:
      return where + "wrong root: the sites' vertex is " + vertex_text(report.diagram, *j.vertex) +
             "; the claim is nearer their other root (" + point_text(*j.point) + "), where site " +
             std::to_string(j.closer_site) + " is strictly closer";
    case Verdict::not_a_vertex:
      break;
  }
  const std::string not_a_vertex = where + "not a vertex: ";
  switch (j.reason) {
    case Not_a_vertex_reason::hidden_site:
      return not_a_vertex + "site " + std::to_string(j.hidden->site) + " is hidden (" +
             (j.hidden->duplicate ? "a duplicate of site " : "inside site ") + std::to_string(j.hidden->hidden_by) + ")";
    case Not_a_vertex_reason::closer_site:
      return not_a_vertex + "site " + std::to_string(j.closer_site) +
             " is strictly closer to the sites' equidistant point (" + point_text(*j.point) + ")";
    case Not_a_vertex_reason::rank_deficient:
      return not_a_vertex + "the sites have no isolated equidistant point (rank-deficient)";
    case Not_a_vertex_reason::no_valid_root:
      return not_a_vertex + "the sites have no equidistant point with a valid radius";
    case Not_a_vertex_reason::not_equidistant:
      return not_a_vertex + "no point is at equal distance from all the sites";
  }
  return not_a_vertex;
}

}  // namespace

void write_certify_report_json(std::ostream& out, const Certify_report& report) {
  const Verdict_counts counts = count_verdicts(report.certification, report.strict);
  const Coordinate_tolerance& tolerance = report.certification.tolerance;
  Json document{{"format", "apollonius3d-certify-report"},
                {"version", 1},
                {"input", report.input_name},
                {"sites", report.diagram.site_count},
                {"hidden_sites", report.diagram.hidden.size()},
                {"certified_vertices", report.diagram.vertices.size()},
                {"claim", report.claim_name},
                {"claim_format", name_of(report.claims.format)},
                {"tolerance", {{"relative", json_number(tolerance.relative)}, {"scale", json_number(tolerance.scale)}}},
                {"strict", report.strict},
                {"counts",
                 {{"claims", counts.claims},
                  {"confirmed", counts.confirmed},
                  {"surplus", counts.surplus},
                  {"duplicate", counts.duplicate},
                  {"coordinates_off", counts.coordinates_off},
                  {"wrong_root", counts.wrong_root},
                  {"not_a_vertex", counts.not_a_vertex},
                  {"missing", counts.missing},
                  {"discrepancies", counts.discrepancies},
                  {"largest_absolute_error", json_number(counts.largest_error.absolute)},
                  {"largest_relative_error", json_number(counts.largest_error.relative)}}}};
  Json& claims = document["claims"] = Json::array();
  for (std::size_t c = 0; c < report.claims.vertices.size(); ++c) claims.push_back(json_claim(report, c));
  Json& missing = document["missing"] = Json::array();
  for (const std::size_t v : report.certification.missing) missing.push_back(json_vertex(report.diagram, v));
  write_json_document(out, document);
}

void write_certify_summary(std::ostream& out, const Certify_report& report, std::size_t listed) {
  const Verdict_counts counts = count_verdicts(report.certification, report.strict);
  const Coordinate_tolerance& tolerance = report.certification.tolerance;
  out << "certify: " << counts.claims << " claimed vertices (" << name_of(report.claims.format) << ") against "
      << report.diagram.vertices.size() << " certified vertices of " << report.diagram.site_count << " sites ("
      << report.diagram.hidden.size() << " hidden)\n"
      << "  confirmed " << counts.confirmed << ", surplus " << counts.surplus << ", duplicate " << counts.duplicate
      << ", coordinates off " << counts.coordinates_off << ", wrong root " << counts.wrong_root << ", not a vertex "
      << counts.not_a_vertex << ", missing " << counts.missing << "\n"
      << "  largest coordinate error of a claimed vertex: " << error_text(counts.largest_error) << " (tolerance "
      << short_number(tolerance.relative) << " x max(" << short_number(tolerance.scale) << ", |value|))\n";
  if (counts.discrepancies == 0) {
    out << "  no discrepancies" << (counts.surplus > 0 && !report.strict ? " (surplus claims allowed without --strict)" : "")
        << "\n";
    return;
  }
  out << "  " << counts.discrepancies << " discrepancies" << (counts.discrepancies > listed ? ", the first ones:" : ":")
      << "\n";
  std::size_t shown = 0;
  for (std::size_t c = 0; c < report.certification.claims.size() && shown < listed; ++c)
    if (is_discrepancy(report.certification.claims[c].verdict, report.strict)) {
      out << "  " << describe_claim(report, c) << "\n";
      ++shown;
    }
  for (std::size_t i = 0; i < report.certification.missing.size() && shown < listed; ++i, ++shown)
    out << "  missing: " << vertex_text(report.diagram, report.certification.missing[i]) << "\n";
}

}  // namespace apollonius
