// The verdict on a claimed topology (claimed_topology.h) against the exact tie sets of the whole diagram
// of the same sites (topology_tie_sets.h). Sets are compared as sets of site indices: exact.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "certify/claimed_topology.h"
#include "topology/topology_tie_sets.h"

namespace apollonius {

// A claimed set is, in this order of precedence:
// - duplicate: an earlier claimed set of the category is the same;
// - confirmed: an exact set of the category;
// - partial: a proper subset of an exact set of the category (a degenerate edge or vertex named by some
//   of its sites, as codes that keep 3 or 4 sites do); the exact set counts as found;
// - spurious: none of these.
// An exact set that no claimed set equals or is part of is missing.
enum class Set_verdict { confirmed, partial, duplicate, spurious };

const char* name_of(Set_verdict verdict);  // "confirmed", "partial", "duplicate", "spurious"

// Invariant: verdicts[i] judges the category's i-th claimed set; missing ascending (indices into the
// category's exact list); exact_set is set for confirmed and partial (index into the exact list),
// earlier_set for duplicate (index of the first claimed set).
struct Set_judgement {
  Set_verdict verdict = Set_verdict::spurious;
  std::optional<std::size_t> exact_set, earlier_set;
};

struct Category_judgement {
  bool judged = false;  // the claim has the category
  std::vector<Set_judgement> sets;
  std::vector<std::size_t> missing;
};

struct Topology_certification {
  Topology_tie_sets exact;
  std::array<Category_judgement, 3> categories;  // indexed by Topology_category
  const Category_judgement& operator[](Topology_category c) const { return categories[static_cast<std::size_t>(c)]; }
};

// The exact sets of a category (a reference into certification.exact).
const std::vector<std::vector<Site_index>>& exact_sets(const Topology_tie_sets& exact, Topology_category category);

Topology_certification judge_topology(Topology_tie_sets exact, const Claimed_topology& claim);

// A discrepancy is every spurious and duplicate set and every missing one; partial sets too when strict.
bool is_discrepancy(Set_verdict verdict, bool strict);

struct Set_counts {
  std::size_t claimed = 0, exact = 0, confirmed = 0, partial = 0, duplicate = 0, spurious = 0, missing = 0;
  std::size_t discrepancies = 0;
};

Set_counts count_sets(const Category_judgement& judgement, std::size_t exact_count, bool strict);

}  // namespace apollonius
