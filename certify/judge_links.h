// The verdict on Voronota's vertex links (`calculate-vertices --link`, claimed_vertices.h) against the
// edges of the whole diagram of the same sites. Which vertex a claim represents comes from judge_claims
// (exact); which edge leaves it, and where that edge ends, from build_topology (exact).
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "certify/claimed_vertices.h"
#include "certify/judge_claims.h"
#include "topology/topology.h"

namespace apollonius {

// Link i of a claim C that represents vertex v is for the triple T of C's sites without sites[i]. The
// edge of T at v (the one edge whose tie set is T with an end at v) ends, at its other end, at a vertex
// w (v itself for a loop) or at infinity. The link is:
// - right: -1 where the edge reaches infinity, or a claim that represents w;
// - wrong: a claim that does not represent w, or any claim where the edge reaches infinity;
// - missing: -1 where the edge ends at a vertex;
// - not_judged: see Link_unjudged.
enum class Link_verdict { right, wrong, missing, not_judged };

enum class Link_unjudged {
  no_links,            // the claim's line has no links (plain Voronota output)
  claim_not_a_vertex,  // the claim represents no vertex (not_a_vertex or wrong_root)
  degenerate_vertex,   // the vertex's tie set has 5 or more sites
  degenerate_edge,     // no single edge of exactly T at v (T's edge there has 4 or more tied sites)
};

const char* name_of(Link_verdict verdict);   // "right", "wrong", "missing", "not_judged"
const char* name_of(Link_unjudged reason);   // "no_links", "claim_not_a_vertex", ...

struct Link_judgement {
  Link_verdict verdict = Link_verdict::not_judged;
  Link_unjudged reason = Link_unjudged::no_links;  // not_judged only
  // Judged links: the edge (index into Diagram_topology::edges) and its other end (nullopt: infinity).
  std::optional<std::size_t> edge, expected_vertex;
};

// Invariant: claims[c][i] judges link i of the c-th claim; represented_by[w] is the first claim that
// represents vertex w, if any.
struct Link_certification {
  std::vector<std::array<Link_judgement, 4>> claims;
  std::vector<std::optional<std::size_t>> represented_by;
};

// Whether a claim with this verdict represents its vertex (judge_claims.h).
bool represents_vertex(Verdict verdict);

// topology must be the whole diagram whose vertices certification judged the claims against.
Link_certification judge_links(const Diagram_topology& topology, const std::vector<Claimed_vertex>& claims,
                               const Certification& certification);

bool is_discrepancy(Link_verdict verdict);  // wrong and missing

struct Link_counts {
  std::size_t links = 0, right = 0, wrong = 0, missing = 0, not_judged = 0;
  std::array<std::size_t, 4> not_judged_by_reason{};  // indexed by Link_unjudged
};

Link_counts count_links(const Link_certification& certification);

}  // namespace apollonius
