// Another implementation's vertex list, and how it lines up with the exact diagram. This is the matching
// core of `certify` (judgement of each claim, with verdicts and reports, comes with the certify issue).
#pragma once

#include <array>
#include <iosfwd>
#include <string>
#include <vector>

#include "diagram.h"

namespace apollonius {

// One line of a claimed vertex list: our text format or Voronota's calculate-vertices output, i.e. 4 or
// more site indices (0-based) followed by x y z r.
struct Claimed_vertex {
  std::vector<Site_index> sites;  // ascending
  std::array<double, 4> point;
  std::size_t line;
};

// Throws Input_error (file, line, reason) on a malformed line.
std::vector<Claimed_vertex> read_claimed_vertices(std::istream& in, const std::string& name);

// A claim represents a diagram vertex when its sites are a subset of the vertex's tie set; among the
// vertices it could represent (two roots of one quadruple), the nearest one in coordinates is chosen.
// Invariant: every claim index appears in exactly one of matches or unmatched_claims.
struct Vertex_list_matching {
  struct Match {
    std::size_t claim;
    std::size_t vertex;  // index into Diagram::vertices
    double max_abs_error;  // max |claimed - rounded exact| over x, y, z, r
  };
  std::vector<Match> matches;
  std::vector<std::size_t> unmatched_claims;
  std::vector<std::size_t> vertices_without_claim;
};

Vertex_list_matching match_claims(const Diagram& diagram, const std::vector<Claimed_vertex>& claims);

}  // namespace apollonius
