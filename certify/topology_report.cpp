#include "certify/topology_report.h"

#include "io/json_output.h"

namespace apollonius {
namespace {

std::string sites_text(const std::vector<Site_index>& sites) {
  std::string text;
  for (const Site_index s : sites) text += (text.empty() ? "" : " ") + std::to_string(s);
  return text;
}

Set_counts counts_of(const Topology_report& report, Topology_category category) {
  return count_sets(report.certification[category], exact_sets(report.certification.exact, category).size(), report.strict);
}

// One line: what is wrong with the s-th claimed set of a category.
std::string describe_set(const Topology_report& report, Topology_category category, std::size_t s) {
  const Claimed_set& set = report.claim[category].sets[s];
  const Set_judgement& j = report.certification[category].sets[s];
  std::string text = report.claim_name + ":" + std::to_string(set.line) + ": " + name_of(category) + " " +
                     sites_text(set.sites) + ": " + name_of(j.verdict);
  if (j.verdict == Set_verdict::duplicate)
    text += " of line " + std::to_string(report.claim[category].sets[*j.earlier_set].line);
  if (j.verdict == Set_verdict::partial)
    text += " of the tie set " + sites_text(exact_sets(report.certification.exact, category)[*j.exact_set]);
  return text;
}

}  // namespace

std::size_t discrepancy_count(const Topology_report& report) {
  std::size_t count = 0;
  for (const Topology_category category : topology_categories) count += counts_of(report, category).discrepancies;
  return count;
}

void write_topology_report_json(std::ostream& out, const Topology_report& report) {
  Json document{{"format", "apollonius3d-certify-report"},
                {"version", 1},
                {"input", report.input_name},
                {"sites", report.diagram.site_count},
                {"hidden_sites", report.diagram.hidden.size()},
                {"certified_vertices", report.diagram.vertices.size()},
                {"claim", report.claim_name},
                {"claim_format", "topology"},
                {"strict", report.strict},
                {"counts", {{"discrepancies", discrepancy_count(report)}}}};
  Json& topology = document["topology"] = Json::object();
  for (const Topology_category category : topology_categories) {
    const Category_judgement& judgement = report.certification[category];
    if (!judgement.judged) {
      topology[name_of(category)] = nullptr;
      continue;
    }
    const Set_counts counts = counts_of(report, category);
    const std::vector<std::vector<Site_index>>& exact = exact_sets(report.certification.exact, category);
    Json sets = Json::array();
    for (std::size_t s = 0; s < judgement.sets.size(); ++s) {
      const Set_judgement& j = judgement.sets[s];
      if (j.verdict == Set_verdict::confirmed) continue;
      const Claimed_set& set = report.claim[category].sets[s];
      Json json{{"index", s}, {"line", set.line}, {"sites", set.sites}, {"verdict", name_of(j.verdict)},
                {"discrepancy", is_discrepancy(j.verdict, report.strict)}};
      if (j.exact_set) json["tie_set"] = exact[*j.exact_set];
      if (j.earlier_set) json["earlier_line"] = report.claim[category].sets[*j.earlier_set].line;
      sets.push_back(json);
    }
    Json missing = Json::array();
    for (const std::size_t e : judgement.missing) missing.push_back(exact[e]);
    topology[name_of(category)] = {{"counts",
                                    {{"claimed", counts.claimed},
                                     {"exact", counts.exact},
                                     {"confirmed", counts.confirmed},
                                     {"partial", counts.partial},
                                     {"duplicate", counts.duplicate},
                                     {"spurious", counts.spurious},
                                     {"missing", counts.missing},
                                     {"discrepancies", counts.discrepancies}}},
                                   {"not_confirmed", sets},
                                   {"missing", missing}};
  }
  write_json_document(out, document);
}

void write_topology_summary(std::ostream& out, const Topology_report& report, std::size_t listed) {
  out << "certify: a claimed topology against the whole diagram of " << report.diagram.site_count << " sites ("
      << report.diagram.hidden.size() << " hidden)\n";
  for (const Topology_category category : topology_categories) {
    if (!report.certification[category].judged) {
      out << "  " << name_of(category) << ": not claimed, not judged\n";
      continue;
    }
    const Set_counts c = counts_of(report, category);
    out << "  " << name_of(category) << ": " << c.claimed << " claimed, " << c.exact << " exact; confirmed " << c.confirmed
        << ", partial " << c.partial << ", duplicate " << c.duplicate << ", spurious " << c.spurious << ", missing "
        << c.missing << "\n";
  }
  const std::size_t discrepancies = discrepancy_count(report);
  if (discrepancies == 0) {
    out << "  no discrepancies\n";
    return;
  }
  out << "  " << discrepancies << " discrepancies" << (discrepancies > listed ? ", the first ones:" : ":") << "\n";
  std::size_t shown = 0;
  for (const Topology_category category : topology_categories) {
    const Category_judgement& judgement = report.certification[category];
    for (std::size_t s = 0; s < judgement.sets.size() && shown < listed; ++s)
      if (is_discrepancy(judgement.sets[s].verdict, report.strict)) {
        out << "  " << describe_set(report, category, s) << "\n";
        ++shown;
      }
    const std::vector<std::vector<Site_index>>& exact = exact_sets(report.certification.exact, category);
    for (std::size_t m = 0; m < judgement.missing.size() && shown < listed; ++m, ++shown)
      out << "  missing: " << name_of(category) << " " << sites_text(exact[judgement.missing[m]]) << "\n";
  }
}

}  // namespace apollonius
