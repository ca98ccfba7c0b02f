#include "certify/judge_links.h"

#include <algorithm>

namespace apollonius {
namespace {

// The edges with an end at each vertex (a loop once).
std::vector<std::vector<std::size_t>> edges_at_vertices(const Diagram_topology& topology) {
  std::vector<std::vector<std::size_t>> at(topology.vertices.vertices.size());
  for (std::size_t e = 0; e < topology.edges.size(); ++e) {
    const Diagram_edge& edge = topology.edges[e];
    if (edge.start) at[*edge.start].push_back(e);
    if (edge.end && edge.end != edge.start) at[*edge.end].push_back(e);
  }
  return at;
}

Link_judgement unjudged(Link_unjudged reason) {
  Link_judgement j;
  j.reason = reason;
  return j;
}

}  // namespace

const char* name_of(Link_verdict verdict) {
  switch (verdict) {
    case Link_verdict::right: return "right";
    case Link_verdict::wrong: return "wrong";
    case Link_verdict::missing: return "missing";
    case Link_verdict::not_judged: return "not_judged";
  }
  return "unknown";
}

const char* name_of(Link_unjudged reason) {
  switch (reason) {
    case Link_unjudged::no_links: return "no_links";
    case Link_unjudged::claim_not_a_vertex: return "claim_not_a_vertex";
    case Link_unjudged::degenerate_vertex: return "degenerate_vertex";
    case Link_unjudged::degenerate_edge: return "degenerate_edge";
  }
  return "unknown";
}

bool represents_vertex(Verdict verdict) { return verdict != Verdict::wrong_root && verdict != Verdict::not_a_vertex; }

Link_certification judge_links(const Diagram_topology& topology, const std::vector<Claimed_vertex>& claims,
                               const Certification& certification) {
  Link_certification result;
  result.represented_by.resize(topology.vertices.vertices.size());
  for (std::size_t c = 0; c < claims.size(); ++c)
    if (const Claim_judgement& j = certification.claims[c]; represents_vertex(j.verdict) && !result.represented_by[*j.vertex])
      result.represented_by[*j.vertex] = c;
  const std::vector<std::vector<std::size_t>> edges_at = edges_at_vertices(topology);

  // Each link costs one scan of the edges at its vertex: O(links x largest fan).
  for (std::size_t c = 0; c < claims.size(); ++c) {
    std::array<Link_judgement, 4>& links = result.claims.emplace_back();
    const Claimed_vertex& claim = claims[c];
    const Claim_judgement& judgement = certification.claims[c];
    if (!claim.links) continue;  // every link not_judged, no_links
    if (!represents_vertex(judgement.verdict)) {
      links.fill(unjudged(Link_unjudged::claim_not_a_vertex));
      continue;
    }
    const std::size_t v = *judgement.vertex;
    if (topology.vertices.vertices[v].tie_set.size() != 4) {
      links.fill(unjudged(Link_unjudged::degenerate_vertex));
      continue;
    }
    for (std::size_t i = 0; i < 4; ++i) {
      std::vector<Site_index> triple = claim.sites;
      triple.erase(triple.begin() + static_cast<std::ptrdiff_t>(i));
      std::vector<std::size_t> edges;
      for (const std::size_t e : edges_at[v])
        if (topology.edges[e].tie_set == triple) edges.push_back(e);
      if (edges.size() != 1) {
        links[i] = unjudged(Link_unjudged::degenerate_edge);
        continue;
      }
      const Diagram_edge& edge = topology.edges[edges.front()];
      Link_judgement& j = links[i];
      j.edge = edges.front();
      j.expected_vertex = edge.start == v ? edge.end : edge.start;
      const long long link = (*claim.links)[i];
      if (!j.expected_vertex) {
        j.verdict = link < 0 ? Link_verdict::right : Link_verdict::wrong;
      } else if (link < 0) {
        j.verdict = Link_verdict::missing;
      } else {
        const Claim_judgement& linked = certification.claims[static_cast<std::size_t>(link)];
        j.verdict = represents_vertex(linked.verdict) && linked.vertex == j.expected_vertex ? Link_verdict::right
                                                                                            : Link_verdict::wrong;
      }
    }
  }
  return result;
}

bool is_discrepancy(Link_verdict verdict) { return verdict == Link_verdict::wrong || verdict == Link_verdict::missing; }

Link_counts count_links(const Link_certification& certification) {
  Link_counts counts;
  for (const std::array<Link_judgement, 4>& links : certification.claims)
    for (const Link_judgement& j : links) {
      ++counts.links;
      switch (j.verdict) {
        case Link_verdict::right: ++counts.right; break;
        case Link_verdict::wrong: ++counts.wrong; break;
        case Link_verdict::missing: ++counts.missing; break;
        case Link_verdict::not_judged:
          ++counts.not_judged;
          ++counts.not_judged_by_reason[static_cast<std::size_t>(j.reason)];
          break;
      }
    }
  return counts;
}

}  // namespace apollonius
