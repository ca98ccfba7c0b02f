// The verdict on each vertex of a claimed list, against the certified diagram of the same sites
// (docs/contract.md, `certify`). Whether a point is a vertex, which vertex a claim's sites can name, and
// why a claim is not a vertex are decided by exact predicates only. Doubles do two things, both reports:
// they pick which of a claim's candidate points its coordinates mean (the nearest, by the correctly
// rounded values), and they measure how far off the claimed coordinates are (coordinate_tolerance.h).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "certify/claimed_vertices.h"
#include "certify/coordinate_tolerance.h"
#include "diagram/diagram.h"

namespace apollonius {

// A claim represents a diagram vertex V when its sites are a subset of V's tie set and, of the points
// equidistant from its sites, its coordinates are nearest V. Then it is, in this order of precedence:
// - duplicate: an earlier claim with the same sites represents V;
// - coordinates_off: the coordinates are outside the tolerance;
// - surplus: an earlier claim with other sites (so V's tie set has 5 or more) represents V;
// - confirmed.
// Otherwise it is:
// - wrong_root: its sites are a subset of a vertex's tie set, but its coordinates are nearer another
//   equidistant point of its sites (the other root of its quadruple), which is no vertex;
// - not_a_vertex: no vertex has all its sites in its tie set.
enum class Verdict { confirmed, surplus, duplicate, coordinates_off, wrong_root, not_a_vertex };

// Why a claim is not a vertex.
enum class Not_a_vertex_reason {
  hidden_site,      // a claimed site is hidden (inside another ball, or a duplicate): it has no vertex
  closer_site,      // at the equidistant point nearest the claim, `site` is strictly closer
  rank_deficient,   // the claimed sites have no isolated equidistant point (Equidistant_points)
  no_valid_root,    // no equidistant point with a valid radius
  not_equidistant,  // no point is at equal distance from all the claimed sites
};

const char* name_of(Verdict verdict);              // "confirmed", "surplus", ..., "not_a_vertex"
const char* name_of(Not_a_vertex_reason reason);   // "hidden_site", "closer_site", ...

struct Claim_judgement {
  Verdict verdict = Verdict::confirmed;
  // Every verdict but not_a_vertex: the diagram vertex (index into Diagram::vertices) that the claim
  // represents, or, for wrong_root, that its sites name; and the claim's error against it.
  std::optional<std::size_t> vertex;
  Coordinate_error error;
  // duplicate: the earlier claim (index) with the same sites; surplus: the first claim of the vertex.
  std::optional<std::size_t> earlier_claim;
  // not_a_vertex only.
  Not_a_vertex_reason reason = Not_a_vertex_reason::closer_site;
  // wrong_root and closer_site: the point the claim was matched to (correctly rounded x y z r) and an
  // active site strictly closer to it than the claimed sites.
  std::optional<std::array<double, 4>> point;
  Site_index closer_site = 0;
  // hidden_site: the first hidden claimed site.
  std::optional<Hidden_site> hidden;
};

// Invariant: claims[i] judges the i-th claimed vertex; missing is ascending, and holds exactly the
// diagram vertices that no claim represents (a wrong_root claim represents none).
struct Certification {
  Coordinate_tolerance tolerance;
  std::vector<Claim_judgement> claims;
  std::vector<std::size_t> missing;
};

// diagram must be the certified diagram of sites (octree_diagram or brute_force_diagram). Throws
// std::logic_error if the two disagree (an internal error).
Certification judge_claims(const std::vector<Site>& sites, const Diagram& diagram,
                           const std::vector<Claimed_vertex>& claims, const Coordinate_tolerance& tolerance);

// A discrepancy is every verdict but confirmed and surplus, and every missing vertex; surplus claims too
// when strict.
bool is_discrepancy(Verdict verdict, bool strict);

struct Verdict_counts {
  std::size_t claims = 0, confirmed = 0, surplus = 0, duplicate = 0, coordinates_off = 0, wrong_root = 0,
              not_a_vertex = 0, missing = 0;
  std::size_t discrepancies = 0;
  // The largest errors over the claims that represent a vertex (0 when none does).
  Coordinate_error largest_error;
};

Verdict_counts count_verdicts(const Certification& certification, bool strict);

}  // namespace apollonius
