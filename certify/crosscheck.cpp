#include "certify/crosscheck.h"

#include "io/round_trip.h"
#include "certify/judge_claims.h"

namespace apollonius {

const char* name_of(Disagreement_kind kind) {
  switch (kind) {
    case Disagreement_kind::missing:
      return "missing";
    case Disagreement_kind::spurious:
      return "spurious";
    case Disagreement_kind::moved:
      return "moved";
  }
  return "?";
}

Crosscheck crosscheck(const std::vector<Site>& sites, const Diagram& certified, const Diagram& floating,
                      const Coordinate_tolerance& tolerance) {
  std::vector<Claimed_vertex> claims;
  for (std::size_t i = 0; i < floating.vertices.size(); ++i)
    claims.push_back({floating.vertices[i].tie_set, floating.vertices[i].rounded, i + 1, std::nullopt});
  const Certification judged = judge_claims(sites, certified, claims, tolerance);

  Crosscheck check;
  check.certified_vertices = certified.vertices.size();
  check.float_vertices = floating.vertices.size();
  for (std::size_t v : judged.missing)
    check.disagreements.push_back({Disagreement_kind::missing, certified.vertices[v].tie_set, certified.vertices[v].rounded, {}, {}});
  for (std::size_t c = 0; c < claims.size(); ++c) {
    const Claim_judgement& j = judged.claims[c];
    const bool represents = j.verdict == Verdict::confirmed || j.verdict == Verdict::coordinates_off;
    const bool whole_tie_set = represents && certified.vertices[*j.vertex].tie_set == claims[c].sites;
    if (represents && whole_tie_set && j.verdict == Verdict::confirmed) {
      ++check.agreeing;
      continue;
    }
    Disagreement d{represents ? Disagreement_kind::moved : Disagreement_kind::spurious, claims[c].sites, claims[c].point,
                   {}, j.error};
    if (represents) d.certified_point = certified.vertices[*j.vertex].rounded;
    check.disagreements.push_back(std::move(d));
  }
  return check;
}

void write_disagreements(std::ostream& out, const Crosscheck& check) {
  for (const Disagreement& d : check.disagreements) {
    out << name_of(d.kind);
    for (Site_index s : d.sites) out << ' ' << s;
    for (double x : d.point) out << ' ' << round_trip(x);
    if (d.kind == Disagreement_kind::moved) {
      out << " certified";
      for (double x : d.certified_point) out << ' ' << round_trip(x);
      out << " error " << round_trip(d.error.absolute) << " relative " << round_trip(d.error.relative);
    }
    out << '\n';
  }
}

}  // namespace apollonius
