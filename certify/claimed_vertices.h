// Another implementation's vertex list, the CLAIM that `certify` judges, in one of three formats:
// - text: our `vertices` output, one vertex a line: 4 or more site indices, then x y z r;
// - json: our `vertices --format json` output (the "vertices" array; other members are ignored);
// - voronota: `voronota calculate-vertices` output, `q1 q2 q3 q4 x y z r`, with `--link` followed by 4
//   more integers l1 l2 l3 l4: l_i is the 0-based index of the claim at the other end of the edge of the
//   three sites other than q_i, -1 for none (judge_links.h).
// Plain Voronota output is also valid text, with the same meaning. The fourth format, topology (the GPU
// codes' tie sets of faces, edges and vertices), is read by claimed_topology.h.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "predicates/site.h"

namespace apollonius {

enum class Claim_format { text, json, voronota, topology };

const char* name_of(Claim_format format);
std::optional<Claim_format> claim_format_from_name(const std::string& name);

// Invariant: sites ascending, distinct, 4 or more, each below the input's site count; point is never NaN
// (it may be infinite: our writers print coordinates that overflow as inf); links, when present, are -1
// or the index of a claim of the same list, links[i] for the edge of the sites other than sites[i].
struct Claimed_vertex {
  std::vector<Site_index> sites;
  std::array<double, 4> point;  // x, y, z, r as claimed
  std::size_t line;             // 1-based line of the claim in its file
  std::optional<std::array<long long, 4>> links;  // Voronota's --link, permuted with the sites
};

struct Claimed_vertex_list {
  Claim_format format;  // as given, or as detected
  std::vector<Claimed_vertex> vertices;
};

// The format of content by its first data: '{' means json, or topology when the object has a
// "bisectors", "trisectors" or "quadrisectors" member; a first line of 12 fields whose fifth is not
// an integer is Voronota's --link output (in text, the fifth field of a 12-field line is a site index,
// while Voronota prints every coordinate with a decimal point); anything else is text.
Claim_format detect_claim_format(const std::string& content);

// Reads a claimed vertex list for an input of site_count sites; with no format given, detects it.
// Site indices may come in any order. Throws Input_error (name, line, reason) for anything malformed:
// wrong field counts, non-numbers, NaN, a repeated or out-of-range site index, fewer than 4 sites,
// binary data, a JSON list made for a different number of sites, a link to no claim of the list. An
// empty list is valid. format must not be topology (std::logic_error).
Claimed_vertex_list read_claimed_vertices(const std::string& content, const std::string& name,
                                          std::optional<Claim_format> format, std::size_t site_count);

}  // namespace apollonius
