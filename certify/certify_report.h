// What `certify` tells: the full JSON report (schema in certify/README.md) and a short human summary.
#pragma once

#include <cstddef>
#include <ostream>
#include <string>

#include "certify/claimed_vertices.h"
#include "certify/judge_claims.h"
#include "certify/judge_links.h"
#include "diagram/diagram.h"
#include "topology/topology.h"

namespace apollonius {

// One certification and what it was made of; the references are the caller's.
struct Certify_report {
  std::string input_name;
  std::string claim_name;
  const Diagram& diagram;
  const Claimed_vertex_list& claims;
  const Certification& certification;
  bool strict;
  // When the claims have links: their verdicts, and the whole diagram they were judged against.
  const Link_certification* links = nullptr;
  const Diagram_topology* topology = nullptr;
};

// Every discrepancy: of the claims (count_verdicts) and of their links.
std::size_t discrepancy_count(const Certify_report& report);

// Every claim with its verdict and details, every missing vertex, the vertex-free cells, the counts; with
// links, each claim's link verdicts and every wrong or missing link.
void write_certify_report_json(std::ostream& out, const Certify_report& report);

// The counts per verdict (and per link verdict), the vertex-free cells, and the first `listed`
// discrepancies, one line each, claims as FILE:LINE.
void write_certify_summary(std::ostream& out, const Certify_report& report, std::size_t listed = 10);

}  // namespace apollonius
