#include "certify/judge_topology.h"

#include <algorithm>
#include <map>
#include <utility>

namespace apollonius {
namespace {

// Complexity: O((C + E) log E) comparisons of sets for C claimed and E exact sets, plus, for each claimed
// set not exact, one inclusion test per degenerate exact set (more sites than the category's least)
// holding its smallest site.
Category_judgement judge_category(const std::vector<std::vector<Site_index>>& exact, const Claimed_category& claim,
                                  std::size_t least_size) {
  Category_judgement judgement;
  judgement.judged = claim.present;
  if (!claim.present) return judgement;
  // The degenerate exact sets by each of their sites.
  std::multimap<Site_index, std::size_t> degenerate_by_site;
  for (std::size_t e = 0; e < exact.size(); ++e)
    if (exact[e].size() > least_size)
      for (const Site_index s : exact[e]) degenerate_by_site.emplace(s, e);
  std::vector<bool> found(exact.size(), false);
  std::map<std::vector<Site_index>, std::size_t> first_claim;
  for (std::size_t c = 0; c < claim.sets.size(); ++c) {
    const std::vector<Site_index>& sites = claim.sets[c].sites;
    Set_judgement j;
    if (const auto [earlier, inserted] = first_claim.emplace(sites, c); !inserted) {
      j.verdict = Set_verdict::duplicate;
      j.earlier_set = earlier->second;
    } else if (const auto e = std::lower_bound(exact.begin(), exact.end(), sites); e != exact.end() && *e == sites) {
      j.verdict = Set_verdict::confirmed;
      j.exact_set = static_cast<std::size_t>(e - exact.begin());
    } else {
      const auto [begin, end] = degenerate_by_site.equal_range(sites.front());
      for (auto it = begin; it != end && !j.exact_set; ++it) {
        const std::vector<Site_index>& whole = exact[it->second];
        if (whole.size() > sites.size() && std::includes(whole.begin(), whole.end(), sites.begin(), sites.end())) {
          j.verdict = Set_verdict::partial;
          j.exact_set = it->second;
        }
      }
    }
    if (j.exact_set) found[*j.exact_set] = true;
    judgement.sets.push_back(j);
  }
  for (std::size_t e = 0; e < exact.size(); ++e)
    if (!found[e]) judgement.missing.push_back(e);
  return judgement;
}

}  // namespace

const char* name_of(Set_verdict verdict) {
  switch (verdict) {
    case Set_verdict::confirmed: return "confirmed";
    case Set_verdict::partial: return "partial";
    case Set_verdict::duplicate: return "duplicate";
    case Set_verdict::spurious: return "spurious";
  }
  return "unknown";
}

const std::vector<std::vector<Site_index>>& exact_sets(const Topology_tie_sets& exact, Topology_category category) {
  switch (category) {
    case Topology_category::bisectors: return exact.bisectors;
    case Topology_category::trisectors: return exact.trisectors;
    case Topology_category::quadrisectors: break;
  }
  return exact.quadrisectors;
}

Topology_certification judge_topology(Topology_tie_sets exact, const Claimed_topology& claim) {
  Topology_certification certification;
  certification.exact = std::move(exact);
  for (const Topology_category category : topology_categories)
    certification.categories[static_cast<std::size_t>(category)] =
        judge_category(exact_sets(certification.exact, category), claim[category], least_size(category));
  return certification;
}

bool is_discrepancy(Set_verdict verdict, bool strict) {
  return verdict == Set_verdict::spurious || verdict == Set_verdict::duplicate || (strict && verdict == Set_verdict::partial);
}

Set_counts count_sets(const Category_judgement& judgement, std::size_t exact_count, bool strict) {
  Set_counts counts;
  counts.exact = exact_count;
  counts.claimed = judgement.sets.size();
  for (const Set_judgement& j : judgement.sets) {
    switch (j.verdict) {
      case Set_verdict::confirmed: ++counts.confirmed; break;
      case Set_verdict::partial: ++counts.partial; break;
      case Set_verdict::duplicate: ++counts.duplicate; break;
      case Set_verdict::spurious: ++counts.spurious; break;
    }
    if (is_discrepancy(j.verdict, strict)) ++counts.discrepancies;
  }
  counts.missing = judgement.missing.size();
  counts.discrepancies += counts.missing;
  return counts;
}

}  // namespace apollonius
