#include "certify/judge_claims.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "predicates/compare_vertices.h"
#include "certify/equidistant_points.h"
#include "predicates/vertex_conflict.h"
#include "predicates/vertex_rounding.h"

namespace apollonius {
namespace {

// The same point: the same quadruple and root without arithmetic, otherwise by the exact comparison.
bool same_point(const Vertex& u, const Vertex& v) {
  if (u.sites() == v.sites() && u.root() == v.root()) return true;
  return compare_vertices(u, v) == Sign::ZERO;
}

// A lower bound of coordinate_error(claimed, rounded_coordinates(p)).absolute from p's interval enclosure, which
// holds the correctly rounded values. Rounding the distances is monotone, so when this bound exceeds a
// computed distance, so does the computed distance to the rounded point: the match comes out the same
// as without the shortcut, which spares the exact rounding of most other roots.
double distance_lower_bound(const std::array<double, 4>& claimed, const Vertex& p) {
  const std::array<Interval, 4> box = p.point_interval();
  double bound = 0;
  for (int j = 0; j < 4; ++j) {
    if (claimed[j] < box[j].inf()) bound = std::max(bound, box[j].inf() - claimed[j]);
    if (claimed[j] > box[j].sup()) bound = std::max(bound, claimed[j] - box[j].sup());
  }
  return bound;
}

class Judge {
 public:
  Judge(const std::vector<Site>& sites, const Diagram& diagram, const Coordinate_tolerance& tolerance)
      : sites_(sites), diagram_(diagram), tolerance_(tolerance), vertices_of_site_(sites.size()),
        claims_of_vertex_(diagram.vertices.size()) {
    for (std::size_t v = 0; v < diagram.vertices.size(); ++v)
      for (const Site_index s : diagram.vertices[v].tie_set) vertices_of_site_.at(s).push_back(v);
    hidden_.resize(sites.size());
    for (const Hidden_site& h : diagram.hidden) hidden_.at(h.site) = h;
  }

  Certification judge(const std::vector<Claimed_vertex>& claims) {
    Certification result;
    result.tolerance = tolerance_;
    for (std::size_t c = 0; c < claims.size(); ++c) {
      result.claims.push_back(judge_one(claims[c]));
      if (const auto& v = result.claims.back().vertex; v && result.claims.back().verdict != Verdict::wrong_root)
        claims_of_vertex_[*v].push_back(c);
      claimed_sites_.push_back(&claims[c].sites);
    }
    for (std::size_t v = 0; v < diagram_.vertices.size(); ++v)
      if (claims_of_vertex_[v].empty()) result.missing.push_back(v);
    return result;
  }

 private:
  Claim_judgement judge_one(const Claimed_vertex& claim) {
    for (const Site_index s : claim.sites)
      if (hidden_.at(s)) return hidden_site(*hidden_[s]);

    const std::vector<std::size_t> containing = vertices_containing(claim.sites);
    const Equidistant_points equidistant = equidistant_points(claim.sites, sites_);
    // The equidistant points of the claimed sites that are no vertex. A diagram vertex whose tie set holds
    // the sites is one of their equidistant points whenever those are isolated.
    std::vector<const Vertex*> other_roots;
    for (const Vertex& p : equidistant.points) {
      const bool is_vertex = std::any_of(containing.begin(), containing.end(),
                                         [&](std::size_t v) { return same_point(diagram_.vertices[v].vertex, p); });
      if (!is_vertex) other_roots.push_back(&p);
    }
    check_agreement(equidistant, equidistant.points.size() - other_roots.size(), containing.size());

    if (containing.empty() && other_roots.empty()) return without_point(equidistant.status);

    // The nearest candidate by coordinates (a report, not a geometric decision); on equal distances a
    // vertex wins over another root, and the earlier vertex over a later one.
    std::optional<std::size_t> nearest_vertex;
    double best = std::numeric_limits<double>::infinity();
    for (const std::size_t v : containing) {
      const double distance = coordinate_error(claim.point, diagram_.vertices[v].rounded, 0).absolute;
      if (!nearest_vertex || distance < best) nearest_vertex = v, best = distance;
    }
    const Vertex* nearest_root = nullptr;
    std::array<double, 4> nearest_root_point{};
    for (const Vertex* p : other_roots) {
      if (nearest_vertex && distance_lower_bound(claim.point, *p) > best) continue;
      const std::array<double, 4> rounded = rounded_coordinates(*p);
      const double distance = coordinate_error(claim.point, rounded, 0).absolute;
      if ((!nearest_vertex && !nearest_root) || distance < best) nearest_root = p, nearest_root_point = rounded, best = distance;
    }

    if (nearest_root != nullptr) return at_other_root(claim, *nearest_root, nearest_root_point, nearest_vertex);
    return representing(claim, *nearest_vertex);
  }

  static Claim_judgement hidden_site(const Hidden_site& h) {
    Claim_judgement j;
    j.verdict = Verdict::not_a_vertex;
    j.reason = Not_a_vertex_reason::hidden_site;
    j.hidden = h;
    return j;
  }

  // A diagram vertex whose tie set holds the claimed sites is an equidistant point of theirs: one of the
  // points when those are isolated, impossible when 4 of the sites have no valid or no common point.
  static void check_agreement(const Equidistant_points& equidistant, std::size_t points_that_are_vertices,
                              std::size_t containing) {
    using Status = Equidistant_points::Status;
    const bool agree = equidistant.status == Status::isolated ? points_that_are_vertices == containing
                                                              : equidistant.status == Status::rank_deficient || containing == 0;
    if (!agree) throw std::logic_error("certify: the diagram's vertices and the claimed sites' equidistant points disagree");
  }

  static Claim_judgement without_point(Equidistant_points::Status status) {
    Claim_judgement j;
    j.verdict = Verdict::not_a_vertex;
    switch (status) {
      case Equidistant_points::Status::rank_deficient: j.reason = Not_a_vertex_reason::rank_deficient; break;
      case Equidistant_points::Status::no_valid_root: j.reason = Not_a_vertex_reason::no_valid_root; break;
      case Equidistant_points::Status::not_equidistant: j.reason = Not_a_vertex_reason::not_equidistant; break;
      case Equidistant_points::Status::isolated: throw std::logic_error("certify: isolated points without a candidate");
    }
    return j;
  }

  // The claim means p, an equidistant point of its sites that is no vertex: some active site is strictly
  // closer to p (the diagram is complete). vertex: the diagram vertex its sites name, if any.
  Claim_judgement at_other_root(const Claimed_vertex& claim, const Vertex& p, const std::array<double, 4>& rounded,
                                std::optional<std::size_t> vertex) const {
    Claim_judgement j;
    j.point = rounded;
    j.closer_site = find_closer_site(p, rounded);
    if (vertex) {
      j.verdict = Verdict::wrong_root;
      j.vertex = vertex;
      j.error = coordinate_error(claim.point, diagram_.vertices[*vertex].rounded, tolerance_.scale);
    } else {
      j.verdict = Verdict::not_a_vertex;
      j.reason = Not_a_vertex_reason::closer_site;
    }
    return j;
  }

  Claim_judgement representing(const Claimed_vertex& claim, std::size_t vertex) const {
    Claim_judgement j;
    j.vertex = vertex;
    j.error = coordinate_error(claim.point, diagram_.vertices[vertex].rounded, tolerance_.scale);
    const std::vector<std::size_t>& earlier = claims_of_vertex_[vertex];
    const auto same_sites = std::find_if(earlier.begin(), earlier.end(),
                                         [&](std::size_t e) { return *claimed_sites_[e] == claim.sites; });
    if (same_sites != earlier.end()) {
      j.verdict = Verdict::duplicate;
      j.earlier_claim = *same_sites;
    } else if (!within(j.error, tolerance_)) {
      j.verdict = Verdict::coordinates_off;
    } else if (!earlier.empty()) {
      j.verdict = Verdict::surplus;
      j.earlier_claim = earlier.front();
    } else {
      j.verdict = Verdict::confirmed;
    }
    return j;
  }

  // The diagram vertices whose tie sets hold every claimed site, ascending.
  std::vector<std::size_t> vertices_containing(const std::vector<Site_index>& claimed) const {
    const Site_index rarest = *std::min_element(claimed.begin(), claimed.end(), [&](Site_index a, Site_index b) {
      return vertices_of_site_[a].size() < vertices_of_site_[b].size();
    });
    std::vector<std::size_t> containing;
    for (const std::size_t v : vertices_of_site_[rarest]) {
      const std::vector<Site_index>& tie = diagram_.vertices[v].tie_set;
      if (std::includes(tie.begin(), tie.end(), claimed.begin(), claimed.end())) containing.push_back(v);
    }
    return containing;
  }

  // An active site strictly closer to p than p's own sites (exact). The sites are tried in the order of
  // their approximate weighted distance from p's rounded point, so that the first try nearly always
  // succeeds; the order only saves time, the answer is checked exactly.
  Site_index find_closer_site(const Vertex& p, const std::array<double, 4>& rounded) const {
    std::vector<std::pair<double, Site_index>> order;
    for (Site_index s = 0; s < sites_.size(); ++s) {
      if (hidden_[s]) continue;
      const Site& site = sites_[s];
      const double distance = std::hypot(rounded[0] - site.x, rounded[1] - site.y, rounded[2] - site.z) - site.w;
      order.emplace_back(std::isnan(distance) ? std::numeric_limits<double>::infinity() : distance, s);
    }
    std::sort(order.begin(), order.end());
    for (const auto& [distance, s] : order)
      if (vertex_conflict(p, sites_[s]) == Sign::NEGATIVE) return s;
    throw std::logic_error("certify: a point missing from the diagram has no closer site");
  }

  const std::vector<Site>& sites_;
  const Diagram& diagram_;
  const Coordinate_tolerance tolerance_;
  std::vector<std::vector<std::size_t>> vertices_of_site_;  // diagram vertices whose tie set holds the site
  std::vector<std::optional<Hidden_site>> hidden_;          // by site
  std::vector<std::vector<std::size_t>> claims_of_vertex_;  // claims representing each vertex, in order
  std::vector<const std::vector<Site_index>*> claimed_sites_;  // the sites of each claim judged so far
};

}  // namespace

const char* name_of(Verdict verdict) {
  switch (verdict) {
    case Verdict::confirmed: return "confirmed";
    case Verdict::surplus: return "surplus";
    case Verdict::duplicate: return "duplicate";
    case Verdict::coordinates_off: return "coordinates_off";
    case Verdict::wrong_root: return "wrong_root";
    case Verdict::not_a_vertex: return "not_a_vertex";
  }
  return "unknown";
}

const char* name_of(Not_a_vertex_reason reason) {
  switch (reason) {
    case Not_a_vertex_reason::hidden_site: return "hidden_site";
    case Not_a_vertex_reason::closer_site: return "closer_site";
    case Not_a_vertex_reason::rank_deficient: return "rank_deficient";
    case Not_a_vertex_reason::no_valid_root: return "no_valid_root";
    case Not_a_vertex_reason::not_equidistant: return "not_equidistant";
  }
  return "unknown";
}

Certification judge_claims(const std::vector<Site>& sites, const Diagram& diagram,
                           const std::vector<Claimed_vertex>& claims, const Coordinate_tolerance& tolerance) {
  return Judge(sites, diagram, tolerance).judge(claims);
}

bool is_discrepancy(Verdict verdict, bool strict) {
  return verdict != Verdict::confirmed && (verdict != Verdict::surplus || strict);
}

Verdict_counts count_verdicts(const Certification& certification, bool strict) {
  Verdict_counts counts;
  counts.claims = certification.claims.size();
  counts.missing = certification.missing.size();
  counts.discrepancies = counts.missing;
  for (const Claim_judgement& j : certification.claims) {
    switch (j.verdict) {
      case Verdict::confirmed: ++counts.confirmed; break;
      case Verdict::surplus: ++counts.surplus; break;
      case Verdict::duplicate: ++counts.duplicate; break;
      case Verdict::coordinates_off: ++counts.coordinates_off; break;
      case Verdict::wrong_root: ++counts.wrong_root; break;
      case Verdict::not_a_vertex: ++counts.not_a_vertex; break;
    }
    if (is_discrepancy(j.verdict, strict)) ++counts.discrepancies;
    if (j.vertex && j.verdict != Verdict::wrong_root) {
      counts.largest_error.absolute = std::max(counts.largest_error.absolute, j.error.absolute);
      counts.largest_error.relative = std::max(counts.largest_error.relative, j.error.relative);
    }
  }
  return counts;
}

}  // namespace apollonius
