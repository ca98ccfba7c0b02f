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
  if (claim.links) {
    json["links"] = *claim.links;
    if (report.links != nullptr) {
      Json& verdicts = json["link_verdicts"] = Json::array();
      for (const Link_judgement& link : report.links->claims[c])
        verdicts.push_back(link.verdict == Link_verdict::not_judged ? name_of(link.reason) : name_of(link.verdict));
    }
  }
  return json;
}

// The sites of a claim without its i-th: the triple of link i.
std::vector<Site_index> link_triple(const Claimed_vertex& claim, std::size_t i) {
  std::vector<Site_index> triple = claim.sites;
  triple.erase(triple.begin() + static_cast<std::ptrdiff_t>(i));
  return triple;
}

// A wrong or missing link, with what the edge's other end is and which claims stand for the vertices.
Json json_link(const Certify_report& report, std::size_t c, std::size_t i) {
  const Claimed_vertex& claim = report.claims.vertices[c];
  const Link_judgement& j = report.links->claims[c][i];
  const long long link = (*claim.links)[i];
  Json json{{"claim", c}, {"line", claim.line}, {"slot", i}, {"sites", link_triple(claim, i)}, {"link", link},
            {"verdict", name_of(j.verdict)}, {"edge", *j.edge}};
  json["vertex"] = json_vertex(report.diagram, *report.certification.claims[c].vertex);
  if (link >= 0) {
    const Claim_judgement& linked = report.certification.claims[static_cast<std::size_t>(link)];
    json["linked_line"] = report.claims.vertices[static_cast<std::size_t>(link)].line;
    json["linked_vertex"] = represents_vertex(linked.verdict) ? Json(*linked.vertex) : Json(nullptr);
  }
  if (j.expected_vertex) {
    json["expected"] = json_vertex(report.diagram, *j.expected_vertex);
    const std::optional<std::size_t> by = report.links->represented_by[*j.expected_vertex];
    json["expected_line"] = by ? Json(report.claims.vertices[*by].line) : Json(nullptr);
  } else {
    json["expected"] = "infinity";
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

// One line: what is wrong with link i of claim c.
std::string describe_link(const Certify_report& report, std::size_t c, std::size_t i) {
  const Claimed_vertex& claim = report.claims.vertices[c];
  const Link_judgement& j = report.links->claims[c][i];
  const long long link = (*claim.links)[i];
  std::string text = report.claim_name + ":" + std::to_string(claim.line) + ": link " + std::to_string(i + 1) +
                     " (edge of sites " + sites_text(link_triple(claim, i)) + "): " + name_of(j.verdict) + ": ";
  if (link < 0) {
    text += "-1";
  } else {
    const Claim_judgement& linked = report.certification.claims[static_cast<std::size_t>(link)];
    text += "line " + std::to_string(report.claims.vertices[static_cast<std::size_t>(link)].line) +
            (represents_vertex(linked.verdict) ? ", vertex " + std::to_string(*linked.vertex) : ", no vertex");
  }
  text += "; the edge leaves vertex " + std::to_string(*report.certification.claims[c].vertex) + " for ";
  if (!j.expected_vertex) return text + "infinity";
  const std::optional<std::size_t> by = report.links->represented_by[*j.expected_vertex];
  return text + vertex_text(report.diagram, *j.expected_vertex) +
         (by ? ", claimed on line " + std::to_string(report.claims.vertices[*by].line) : ", claimed by no line");
}

std::size_t link_discrepancies(const Certify_report& report) {
  if (report.links == nullptr) return 0;
  const Link_counts counts = count_links(*report.links);
  return counts.wrong + counts.missing;
}

}  // namespace

std::size_t discrepancy_count(const Certify_report& report) {
  return count_verdicts(report.certification, report.strict).discrepancies + link_discrepancies(report);
}

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
                  {"discrepancies", discrepancy_count(report)},
                  {"largest_absolute_error", json_number(counts.largest_error.absolute)},
                  {"largest_relative_error", json_number(counts.largest_error.relative)}}}};
  Json& claims = document["claims"] = Json::array();
  for (std::size_t c = 0; c < report.claims.vertices.size(); ++c) claims.push_back(json_claim(report, c));
  Json& missing = document["missing"] = Json::array();
  for (const std::size_t v : report.certification.missing) missing.push_back(json_vertex(report.diagram, v));
  document["vertex_free_cells"] = report.diagram.sites_without_vertex;
  if (report.links != nullptr) {
    const Link_counts links = count_links(*report.links);
    Json reasons = Json::object();
    for (const Link_unjudged reason : {Link_unjudged::no_links, Link_unjudged::claim_not_a_vertex,
                                       Link_unjudged::degenerate_vertex, Link_unjudged::degenerate_edge})
      reasons[name_of(reason)] = links.not_judged_by_reason[static_cast<std::size_t>(reason)];
    Json discrepancies = Json::array();
    for (std::size_t c = 0; c < report.links->claims.size(); ++c)
      for (std::size_t i = 0; i < 4; ++i)
        if (is_discrepancy(report.links->claims[c][i].verdict)) discrepancies.push_back(json_link(report, c, i));
    document["links"] = {{"counts",
                          {{"links", links.links},
                           {"right", links.right},
                           {"wrong", links.wrong},
                           {"missing", links.missing},
                           {"not_judged", links.not_judged},
                           {"not_judged_reasons", reasons}}},
                         {"discrepancies", discrepancies}};
  }
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
  if (report.links != nullptr) {
    const Link_counts links = count_links(*report.links);
    const auto& by = links.not_judged_by_reason;
    out << "  links " << links.links << ": right " << links.right << ", wrong " << links.wrong << ", missing "
        << links.missing << ", not judged " << links.not_judged << " (degenerate vertex "
        << by[static_cast<std::size_t>(Link_unjudged::degenerate_vertex)] << ", degenerate edge "
        << by[static_cast<std::size_t>(Link_unjudged::degenerate_edge)] << ", claim not a vertex "
        << by[static_cast<std::size_t>(Link_unjudged::claim_not_a_vertex)] << ", no links "
        << by[static_cast<std::size_t>(Link_unjudged::no_links)] << ")\n";
  }
  const std::vector<Site_index>& vertex_free = report.diagram.sites_without_vertex;
  if (!vertex_free.empty()) {
    out << "  vertex-free cells (no vertex list shows them): " << vertex_free.size() << ", sites";
    for (std::size_t i = 0; i < vertex_free.size() && i < listed; ++i) out << ' ' << vertex_free[i];
    out << (vertex_free.size() > listed ? " ...\n" : "\n");
  }
  const std::size_t discrepancies = discrepancy_count(report);
  if (discrepancies == 0) {
    out << "  no discrepancies" << (counts.surplus > 0 && !report.strict ? " (surplus claims allowed without --strict)" : "")
        << "\n";
    return;
  }
  out << "  " << discrepancies << " discrepancies" << (discrepancies > listed ? ", the first ones:" : ":")
      << "\n";
  std::size_t shown = 0;
  for (std::size_t c = 0; c < report.certification.claims.size() && shown < listed; ++c)
    if (is_discrepancy(report.certification.claims[c].verdict, report.strict)) {
      out << "  " << describe_claim(report, c) << "\n";
      ++shown;
    }
  for (std::size_t i = 0; i < report.certification.missing.size() && shown < listed; ++i, ++shown)
    out << "  missing: " << vertex_text(report.diagram, report.certification.missing[i]) << "\n";
  if (report.links == nullptr) return;
  std::size_t links_shown = 0;  // links have their own `listed` lines
  for (std::size_t c = 0; c < report.links->claims.size() && links_shown < listed; ++c)
    for (std::size_t i = 0; i < 4 && links_shown < listed; ++i)
      if (is_discrepancy(report.links->claims[c][i].verdict)) {
        out << "  " << describe_link(report, c, i) << "\n";
        ++links_shown;
      }
}

}  // namespace apollonius
