// What `certify` tells of a topology claim: the JSON report (schema in certify/README.md) and a short
// human summary.
#pragma once

#include <cstddef>
#include <ostream>
#include <string>

#include "certify/claimed_topology.h"
#include "certify/judge_topology.h"
#include "diagram/diagram.h"

namespace apollonius {

// One certification and what it was made of; the references are the caller's.
struct Topology_report {
  std::string input_name;
  std::string claim_name;
  const Diagram& diagram;  // the whole diagram's vertices
  const Claimed_topology& claim;
  const Topology_certification& certification;
  bool strict;
};

std::size_t discrepancy_count(const Topology_report& report);

// Per category: the counts, every set that is not confirmed with its verdict, every missing set.
void write_topology_report_json(std::ostream& out, const Topology_report& report);

// The counts per category and the first `listed` discrepancies, one line each, sets as FILE:LINE.
void write_topology_summary(std::ostream& out, const Topology_report& report, std::size_t listed = 10);

}  // namespace apollonius
