// certify: reading claimed vertex lists, the verdicts on planted defects in our own output (for several
// generator families and pept), our own output confirmed on every family, Voronota's output judged, and
// the command line (exit codes, --report written atomically, bad claims as FILE:LINE with exit 2).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <sstream>

#include "certify/claimed_vertices.h"
#include "support/cli_helpers.h"
#include "predicates/compare_vertices.h"
#include "support/diagram_checks.h"
#include "io/input_error.h"
#include "io/json_output.h"
#include "io/round_trip.h"
#include "io/json_input.h"
#include "io/read_sites.h"
#include "io/write_vertices.h"
#include "certify/judge_claims.h"
#include "octree/octree_diagram.h"
#include "reference/site_generators.h"
#include "predicates/vertex_rounding.h"
#include "predicates/vertices_of.h"

using namespace apollonius;
using namespace apollonius::testing;

namespace {

const std::string kPept = std::string(APOLLONIUS_TEST_DATA) + "/pept.balls";

// An input with its certified diagram and our own text output, one string a vertex.
struct Certified_input {
  std::string name;
  std::vector<Site> sites;
  Diagram diagram;
  std::vector<std::string> lines;
};

Certified_input certified_input(const std::string& name, std::vector<Site> sites) {
  Certified_input input{name, std::move(sites), {}, {}};
  input.diagram = octree_diagram(input.sites);
  std::ostringstream text;
  write_vertices_text(text, input.diagram);
  std::istringstream lines(text.str());
  for (std::string line; std::getline(lines, line);) input.lines.push_back(line);
  return input;
}

std::string claim_line(const std::vector<Site_index>& sites, const std::array<double, 4>& point) {
  std::string line;
  for (const Site_index s : sites) line += std::to_string(s) + " ";
  return line + round_trip(point[0]) + " " + round_trip(point[1]) + " " + round_trip(point[2]) + " " + round_trip(point[3]);
}

std::string joined(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& line : lines) text += line + "\n";
  return text;
}

struct Judged {
  Claimed_vertex_list claims;
  Certification certification;
  Verdict_counts counts;         // without --strict
  Verdict_counts strict_counts;  // with --strict
};

Judged judge(const Certified_input& input, const std::string& claim_text, std::optional<Claim_format> format = {}) {
  Judged j;
  j.claims = read_claimed_vertices(claim_text, "claim", format, input.sites.size());
  j.certification = judge_claims(input.sites, input.diagram, j.claims.vertices, {1e-9, input_scale(input.sites)});
  j.counts = count_verdicts(j.certification, false);
  j.strict_counts = count_verdicts(j.certification, true);
  return j;
}

// Whether some certified tie set holds every site of the set.
bool in_some_tie_set(const Diagram& diagram, const std::vector<Site_index>& set) {
  return std::any_of(diagram.vertices.begin(), diagram.vertices.end(), [&](const Diagram_vertex& v) {
    return std::includes(v.tie_set.begin(), v.tie_set.end(), set.begin(), set.end());
  });
}

std::vector<Site_index> sorted(std::vector<Site_index> sites) {
  std::sort(sites.begin(), sites.end());
  return sites;
}

// The first vertex at or after the middle of the list with exactly 4 tied sites.
std::optional<std::size_t> generic_vertex(const Diagram& diagram) {
  const std::size_t n = diagram.vertices.size();
  for (std::size_t k = 0; k < n; ++k)
    if (const std::size_t v = (n / 2 + k) % n; diagram.vertices[v].tie_set.size() == 4) return v;
  return std::nullopt;
}

// The first generic vertex whose quadruple has a second valid root that is no vertex, and that root.
std::optional<std::pair<std::size_t, Vertex>> other_root_of_a_vertex(const Diagram& d) {
  for (std::size_t v = 0; v < d.vertices.size(); ++v) {
    const Diagram_vertex& candidate = d.vertices[v];
    if (candidate.tie_set.size() != 4) continue;
    for (const Vertex& p : vertices_of(candidate.vertex.quadruple()).vertices) {
      const bool is_vertex = std::any_of(d.vertices.begin(), d.vertices.end(), [&](const Diagram_vertex& u) {
        return u.tie_set == candidate.tie_set && compare_vertices(u.vertex, p) == Sign::ZERO;
      });
      if (!is_vertex) return std::make_pair(v, p);
    }
  }
  return std::nullopt;
}

// Every claim confirmed but those listed, which must have the given verdicts.
void check_verdicts(const Judged& judged, const std::vector<std::pair<std::size_t, Verdict>>& expected) {
  for (std::size_t c = 0; c < judged.certification.claims.size(); ++c) {
    CAPTURE(c);
    Verdict verdict = Verdict::confirmed;
    for (const auto& [claim, v] : expected)
      if (claim == c) verdict = v;
    CHECK(name_of(judged.certification.claims[c].verdict) == std::string(name_of(verdict)));
  }
}

// The inputs that the planted defects are planted into: generic and degenerate families, and pept.
std::vector<Certified_input> planted_inputs() {
  std::vector<Certified_input> inputs;
  inputs.push_back(certified_input("pept", read_sites(kPept, {}).sites));
  for (const auto& [family, seed] : std::vector<std::pair<Site_family, int>>{{Site_family::uniform, 3},
                                                                            {Site_family::mixed_sign, 5},
                                                                            {Site_family::tangent, 2},
                                                                            {Site_family::nested, 4},
                                                                            {Site_family::far_vertices, 1},
                                                                            {Site_family::equal_weights, 7}})
    inputs.push_back(certified_input(std::string(name_of(family)) + " seed " + std::to_string(seed),
                                     generate_sites(family, 30, static_cast<std::uint64_t>(seed))));
  return inputs;
}

}  // namespace

TEST_CASE("claim formats: text, JSON and Voronota with --link are read and detected") {
  const std::string text = "# comment\n0 1 2 3 0.5 -1 2e3 inf\n\n3 2 1 0 4 1 2 3 4\n";
  const Claimed_vertex_list t = read_claimed_vertices(text, "t", std::nullopt, 5);
  CHECK(t.format == Claim_format::text);
  REQUIRE(t.vertices.size() == 2);
  CHECK(t.vertices[0].sites == std::vector<Site_index>{0, 1, 2, 3});
  CHECK(t.vertices[0].point == std::array<double, 4>{0.5, -1, 2000, INFINITY});
  CHECK(t.vertices[0].line == 2);
  CHECK(t.vertices[1].sites == std::vector<Site_index>{0, 1, 2, 3, 4});  // any order, sorted
  CHECK(t.vertices[1].line == 4);

  const std::string link = "0 1 2 3 5.000000000000000 -1.500000000000000 0.000000000000000 1.000000000000000 1 -1 -1 -1\n"
                           "0 1 2 4 5.500000000000000 -1.500000000000000 0.000000000000000 1.000000000000000 0 -1 -1 -1\n";
  CHECK(detect_claim_format(link) == Claim_format::voronota);
  const Claimed_vertex_list v = read_claimed_vertices(link, "v", std::nullopt, 5);
  REQUIRE(v.vertices.size() == 2);
  CHECK(v.vertices[1].sites == std::vector<Site_index>{0, 1, 2, 4});
  CHECK(v.vertices[1].point == std::array<double, 4>{5.5, -1.5, 0, 1});
  // Eight sites in our text format: the fifth field is a site index.
  CHECK(detect_claim_format("0 1 2 3 4 5 6 7 1 2 3 4\n") == Claim_format::text);
  CHECK(read_claimed_vertices("0 1 2 3 4 5 6 7 1 2 3 4\n", "t", std::nullopt, 8).vertices[0].sites.size() == 8);
  // Plain Voronota output is text with the same meaning.
  CHECK(detect_claim_format("0 1 2 3 5.0 1.0 0.0 1.0\n") == Claim_format::text);
  CHECK(read_claimed_vertices("0 1 2 3 5.0 1.0 0.0 1.0\n", "v", Claim_format::voronota, 4).vertices.size() == 1);

  const std::string json = "{\"format\": \"apollonius3d-vertices\", \"version\": 1, \"sites\": 5,\n"
                           " \"vertices\": [\n  {\"sites\": [0, 1, 2, 3], \"x\": 1.5, \"y\": -2e-3, \"z\": 0, \"r\": \"-inf\"}\n ],\n"
                           " \"hidden_sites\": [], \"sites_without_vertex\": [4]}\n";
  CHECK(detect_claim_format(json) == Claim_format::json);
  const Claimed_vertex_list j = read_claimed_vertices(json, "j", std::nullopt, 5);
  REQUIRE(j.vertices.size() == 1);
  CHECK(j.vertices[0].line == 3);
  CHECK(j.vertices[0].point == std::array<double, 4>{1.5, -2e-3, 0, -INFINITY});

  CHECK(read_claimed_vertices("", "empty", std::nullopt, 5).vertices.empty());
  CHECK(read_claimed_vertices("{\"vertices\": []}", "empty", std::nullopt, 5).vertices.empty());
}

TEST_CASE("malformed claims: Input_error with the line and the reason") {
  struct Case {
    const char* what;
    std::string content;
    std::optional<Claim_format> format;
    std::size_t line;
    const char* reason;
  };
  const std::vector<Case> cases = {
      {"too few fields", "0 1 2 3 1 2 3 4\n0 1 2 3 4 5\n", {}, 2, "found 6 fields"},
      {"a word", "0 1 2 3 1 2 3 4\n0 1 x 3 1 2 3 4\n", {}, 2, "not a site index: 'x'"},
      {"negative index", "0 1 -2 3 1 2 3 4\n", {}, 1, "not a site index"},
      {"NaN", "0 1 2 3 1 nan 3 4\n", {}, 1, "not a finite number"},
      {"repeated site", "\n\n0 1 1 3 1 2 3 4\n", {}, 3, "listed twice"},
      {"out of range", "0 1 2 9 1 2 3 4\n", {}, 1, "out of range"},
      {"binary", std::string("0 1 2 3 1 2 3 4\n0 1\x01", 20), {}, 2, "binary data"},
      {"voronota field count", "0 1 2 3 1 2 3 4 5\n", Claim_format::voronota, 1, "found 9 fields"},
      {"voronota link", "0 1 2 3 1.0 2.0 3.0 4.0 0 -2 1 1\n", {}, 1, "not a vertex link"},
      {"voronota with 5 sites", "0 1 2 3 4 1.0 2.0 3.0 4.0\n", Claim_format::voronota, 1, "found 9 fields"},
      {"json syntax", "{\"vertices\": [\n{\"sites\": [0, 1, 2, 3],\n \"x\": 1, \"y\": 2 \"z\": 3}]}", {}, 3, "syntax error"},
      {"json missing r", "{\"vertices\": [\n{\"sites\": [0, 1, 2, 3], \"x\": 1, \"y\": 2, \"z\": 3}]}", {}, 2, "without \"r\""},
      {"json string coordinate", "{\"vertices\": [{\"sites\": [0, 1, 2, 3],\n\"x\": \"1\", \"y\": 2, \"z\": 3, \"r\": 1}]}", {}, 2, "must be a number"},
      {"json site count", "{\"sites\": 7,\n\"vertices\": []}", {}, 1, "for 7 sites"},
      {"json without vertices", "{\"sites\": 5}", {}, 1, "no \"vertices\""},
      {"json three sites", "{\"vertices\": [{\"sites\": [0, 1, 2], \"x\": 1, \"y\": 2, \"z\": 3, \"r\": 1}]}", {}, 1, "4 or more"},
      {"json duplicate key", "{\"vertices\": [],\n\"vertices\": []}", {}, 2, "duplicate key"},
      {"json trailing text", "{\"vertices\": []}\nx", {}, 2, "expected end of input"},
      {"json nested too deep", std::string(70, '[') + std::string(70, ']'), Claim_format::json, 1, "deeper than 64"},
  };
  for (const Case& c : cases) {
    INFO(std::string(c.what));
    try {
      read_claimed_vertices(c.content, "claims.txt", c.format, 5);
      FAIL("no Input_error");
    } catch (const Input_error& e) {
      INFO(std::string(e.what()));
      CHECK(e.file() == "claims.txt");
      CHECK(e.line() == c.line);
      CHECK(e.reason().find(c.reason) != std::string::npos);
    }
  }
}

TEST_CASE("planted defects in our own output: each found with the right verdict") {
  std::size_t wrong_roots = 0;
  for (const Certified_input& input : planted_inputs()) {
    CAPTURE(input.name);
    const Diagram& d = input.diagram;
    REQUIRE(d.vertices.size() >= 8);
    const std::optional<std::size_t> generic = generic_vertex(d);
    REQUIRE(generic);
    const std::size_t k = *generic;
    const Diagram_vertex& vertex = d.vertices[k];
    CAPTURE(k);

    {
      INFO("unchanged: every claim confirmed");
      const Judged j = judge(input, joined(input.lines));
      CHECK(j.counts.confirmed == d.vertices.size());
      CHECK(j.strict_counts.discrepancies == 0);
    }
    {
      INFO("a dropped vertex is missing");
      std::vector<std::string> lines = input.lines;
      lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(k));
      const Judged j = judge(input, joined(lines));
      CHECK(j.certification.missing == std::vector<std::size_t>{k});
      CHECK(j.counts.confirmed == d.vertices.size() - 1);
      CHECK(j.counts.discrepancies == 1);
    }
    {
      INFO("a duplicated vertex");
      std::vector<std::string> lines = input.lines;
      lines.push_back(lines[k]);
      const Judged j = judge(input, joined(lines));
      check_verdicts(j, {{lines.size() - 1, Verdict::duplicate}});
      CHECK(j.certification.claims.back().earlier_claim == k);
      CHECK(j.certification.claims.back().vertex == k);
      CHECK(j.counts.missing == 0);
      CHECK(j.counts.discrepancies == 1);
    }
    {
      INFO("a vertex with one wrong site is not a vertex, and the true one is missing");
      std::vector<Site_index> wrong = vertex.tie_set;
      for (Site_index s = 0; s < input.sites.size(); ++s) {
        wrong.back() = s;
        if (!std::binary_search(vertex.tie_set.begin(), vertex.tie_set.end(), s) && !in_some_tie_set(d, sorted(wrong))) break;
      }
      REQUIRE_FALSE(in_some_tie_set(d, sorted(wrong)));
      std::vector<std::string> lines = input.lines;
      lines[k] = claim_line(wrong, vertex.rounded);
      const Judged j = judge(input, joined(lines));
      check_verdicts(j, {{k, Verdict::not_a_vertex}});
      CHECK(j.certification.missing == std::vector<std::size_t>{k});
      CHECK(j.counts.discrepancies == 2);
    }
    {
      INFO("coordinates perturbed by 1e-6 relative to the scale are off");
      const double scale = input_scale(input.sites);
      std::array<double, 4> moved = vertex.rounded;
      moved[0] += 1e-6 * std::max(scale, std::fabs(moved[0]));
      std::vector<std::string> lines = input.lines;
      lines[k] = claim_line(vertex.tie_set, moved);
      const Judged j = judge(input, joined(lines));
      check_verdicts(j, {{k, Verdict::coordinates_off}});
      const Claim_judgement& off = j.certification.claims[k];
      CHECK(off.vertex == k);
      CHECK(off.error.relative > 0.9e-6);
      CHECK(off.error.relative < 1.1e-6);
      CHECK(off.error.absolute > 0);
      CHECK(j.counts.missing == 0);
    }
    {
      INFO("a spurious far point of 4 sites is not a vertex: a named site is strictly closer");
      // Of the quadruples of the first 12 sites that no tie set holds, the valid root farthest out.
      std::optional<Vertex> farthest;
      double farthest_size = -1;
      const Site_index m = static_cast<Site_index>(std::min<std::size_t>(12, input.sites.size()));
      for (Site_index a = 0; a < m; ++a)
        for (Site_index b = a + 1; b < m; ++b)
          for (Site_index c = b + 1; c < m; ++c)
            for (Site_index e = c + 1; e < m; ++e) {
              if (in_some_tie_set(d, {a, b, c, e})) continue;
              for (const Vertex& p : vertices_of(make_quadruple({a, b, c, e}, input.sites)).vertices) {
                const std::array<double, 4> r = rounded_coordinates(p);
                const double size = std::max({std::fabs(r[0]), std::fabs(r[1]), std::fabs(r[2])});
                if (size > farthest_size) farthest = p, farthest_size = size;
              }
            }
      REQUIRE(farthest);
      std::vector<std::string> lines = input.lines;
      const auto& s = farthest->sites();
      lines.push_back(claim_line({s.begin(), s.end()}, rounded_coordinates(*farthest)));
      const Judged j = judge(input, joined(lines));
      check_verdicts(j, {{lines.size() - 1, Verdict::not_a_vertex}});
      const Claim_judgement& spurious = j.certification.claims.back();
      CHECK(spurious.reason == Not_a_vertex_reason::closer_site);
      CHECK(spurious.point == rounded_coordinates(*farthest));
      CHECK(vertex_conflict(*farthest, input.sites[spurious.closer_site]) == Sign::NEGATIVE);
      CHECK(j.counts.missing == 0);
    }
    if (const auto other = other_root_of_a_vertex(d)) {
      INFO("a claim at the other root of a vertex's quadruple is a wrong root");
      const auto& [v, p] = *other;
      CAPTURE(v);
      std::vector<std::string> lines = input.lines;
      lines[v] = claim_line(d.vertices[v].tie_set, rounded_coordinates(p));
      const Judged j = judge(input, joined(lines));
      check_verdicts(j, {{v, Verdict::wrong_root}});
      const Claim_judgement& wrong = j.certification.claims[v];
      CHECK(wrong.vertex == v);
      CHECK(wrong.point == rounded_coordinates(p));
      CHECK(vertex_conflict(p, input.sites[wrong.closer_site]) == Sign::NEGATIVE);
      CHECK(j.certification.missing == std::vector<std::size_t>{v});
      ++wrong_roots;
    }
  }
  MESSAGE(wrong_roots << " wrong roots planted");
  CHECK(wrong_roots >= 3);
}

TEST_CASE("Voronota-style arbitrary quadruples of a degenerate vertex are surplus, errors only with --strict") {
  std::size_t degenerate_inputs = 0;
  for (const Site_family family : {Site_family::lattice, Site_family::cospherical}) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      CAPTURE(name_of(family));
      CAPTURE(seed);
      const Certified_input input = certified_input(name_of(family), generate_sites(family, 20, seed));
      const auto degenerate = std::find_if(input.diagram.vertices.begin(), input.diagram.vertices.end(),
                                           [](const Diagram_vertex& v) { return v.tie_set.size() >= 5; });
      if (degenerate == input.diagram.vertices.end()) continue;
      ++degenerate_inputs;
      const std::size_t k = static_cast<std::size_t>(degenerate - input.diagram.vertices.begin());
      const std::vector<Site_index>& tie = degenerate->tie_set;
      // Four arbitrary quadruples of the tie set (coplanar or cocircular ones included) replace the line.
      std::vector<std::string> lines = input.lines;
      lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(k));
      const std::vector<std::vector<Site_index>> quadruples = {{tie[0], tie[1], tie[2], tie[3]},
                                                               {tie[1], tie[2], tie[3], tie[4]},
                                                               {tie[0], tie[2], tie[3], tie[4]},
                                                               {tie[4], tie[0], tie[3], tie[1]}};
      for (const auto& q : quadruples) lines.push_back(claim_line(q, degenerate->rounded));
      const Judged j = judge(input, joined(lines));
      const std::size_t first = lines.size() - quadruples.size();
      check_verdicts(j, {{first + 1, Verdict::surplus}, {first + 2, Verdict::surplus}, {first + 3, Verdict::surplus}});
      CHECK(j.certification.claims[first].vertex == k);
      CHECK(j.certification.claims[first + 3].earlier_claim == first);
      CHECK(j.counts.surplus == 3);
      CHECK(j.counts.missing == 0);
      CHECK(j.counts.discrepancies == 0);
      CHECK(j.strict_counts.discrepancies == 3);

      // The same quadruple twice is a duplicate, not a surplus.
      lines.push_back(lines[first]);
      const Judged twice = judge(input, joined(lines));
      CHECK(twice.certification.claims.back().verdict == Verdict::duplicate);
      CHECK(twice.counts.discrepancies == 1);
    }
  }
  CHECK(degenerate_inputs >= 3);
}

TEST_CASE("not a vertex: hidden site, rank-deficient, no valid root, not equidistant") {
  SUBCASE("a hidden claimed site") {
    const Certified_input input = certified_input("hidden", {{1, 1, 1, 1}, {1, -1, -1, 1}, {-1, 1, -1, 1}, {-1, -1, 1, 1},
                                                              {1.25, 1, 1, 0.5}});
    REQUIRE(input.diagram.hidden.size() == 1);
    const Judged j = judge(input, "1 2 3 4 0 0 0 0.7320508075688773\n");
    const Claim_judgement& c = j.certification.claims[0];
    CHECK(c.verdict == Verdict::not_a_vertex);
    CHECK(c.reason == Not_a_vertex_reason::hidden_site);
    REQUIRE(c.hidden);
    CHECK(c.hidden->site == 4);
    CHECK(c.hidden->hidden_by == 0);
    CHECK(j.certification.missing == std::vector<std::size_t>{0});
  }
  SUBCASE("collinear sites: rank-deficient") {
    const Certified_input input = certified_input("collinear", {{0, 0, 0, 1}, {1, 0, 0, 1}, {2, 0, 0, 1}, {3, 0, 0, 1},
                                                                {0, 5, 0, 1}, {0, 0, 5, 1}, {4, 4, 4, 1}});
    const Judged j = judge(input, "0 1 2 3 1.5 0 0 0.5\n");
    CHECK(j.certification.claims[0].verdict == Verdict::not_a_vertex);
    CHECK(j.certification.claims[0].reason == Not_a_vertex_reason::rank_deficient);
  }
  SUBCASE("a fifth site not at the same distance") {
    const Certified_input input = certified_input("tetrahedron", {{1, 1, 1, 1}, {1, -1, -1, 1}, {-1, 1, -1, 1}, {-1, -1, 1, 1},
                                                                  {10, 10, 10, 1}});
    const Judged j = judge(input, "0 1 2 3 4 0 0 0 0.7320508075688773\n");
    CHECK(j.certification.claims[0].verdict == Verdict::not_a_vertex);
    CHECK(j.certification.claims[0].reason == Not_a_vertex_reason::not_equidistant);
  }
  SUBCASE("a quadruple without a valid root") {
    bool found = false;
    for (std::uint64_t seed = 1; seed <= 20 && !found; ++seed) {
      const std::vector<Site> sites = generate_sites(Site_family::mixed_sign, 12, seed);
      const Certified_input input = certified_input("mixed-sign", sites);
      std::vector<bool> hidden(sites.size(), false);
      for (const Hidden_site& h : input.diagram.hidden) hidden[h.site] = true;
      for (Site_index a = 0; a < 9 && !found; ++a) {
        if (hidden[a] || hidden[a + 1] || hidden[a + 2] || hidden[a + 3]) continue;
        const Quadruple_vertices roots = vertices_of(make_quadruple({a, a + 1, a + 2, a + 3}, sites));
        if (roots.rank_deficient || roots.equidistant_curve || !roots.vertices.empty()) continue;
        CAPTURE(seed);
        CAPTURE(a);
        const Judged j = judge(input, claim_line({a, a + 1, a + 2, a + 3}, {0, 0, 0, 1}));
        CHECK(j.certification.claims[0].verdict == Verdict::not_a_vertex);
        CHECK(j.certification.claims[0].reason == Not_a_vertex_reason::no_valid_root);
        found = true;
      }
    }
    CHECK(found);
  }
}

TEST_CASE("any claimed quadruple: represented exactly when a certified tie set holds it") {
  for (const Site_family family : {Site_family::uniform, Site_family::mixed_sign, Site_family::lattice}) {
    const Certified_input input = certified_input(name_of(family), generate_sites(family, 14, 11));
    CAPTURE(input.name);
    std::vector<std::string> lines;
    std::vector<std::vector<Site_index>> quadruples;
    for (Site_index a = 0; a < 10; ++a)
      for (Site_index b = a + 1; b < 10; ++b)
        for (Site_index c = b + 1; c < 10; ++c)
          for (Site_index e = c + 1; e < 10; ++e) {
            quadruples.push_back({a, b, c, e});
            lines.push_back(claim_line(quadruples.back(), {1, 2, 3, 4}));
          }
    const Judged j = judge(input, joined(lines));
    for (std::size_t i = 0; i < quadruples.size(); ++i) {
      CAPTURE(lines[i]);
      const bool held = in_some_tie_set(input.diagram, quadruples[i]);
      CHECK((j.certification.claims[i].verdict != Verdict::not_a_vertex) == held);
    }
  }
}

TEST_CASE("property: certify finds no discrepancy in our own output, text or JSON, on every generator family") {
  std::size_t inputs = 0, vertices = 0;
  for (const std::string& name : site_family_names()) {
    const Site_family family = site_family_from_name(name);
    const bool expensive = family == Site_family::scaled_up || family == Site_family::scaled_down ||
                           family == Site_family::lattice_noise || family == Site_family::wide_range;
    // The octree costs ~50 times more on the families whose predicates all reach the exact stage, or
    // whose sites are 2^900 times apart.
    const std::uint64_t seeds = expensive ? 4 : 24;
    for (std::uint64_t seed = 1; seed <= seeds; ++seed) {
      const std::size_t n = 5 + (seed * 7919) % 16;  // 5 to 20 sites
      CAPTURE(name);
      CAPTURE(seed);
      CAPTURE(n);
      const Certified_input input = certified_input(name, generate_sites(family, n, seed));
      const Judged text = judge(input, joined(input.lines));
      CHECK(text.claims.format == Claim_format::text);
      CHECK(text.counts.confirmed == input.diagram.vertices.size());
      CHECK(text.strict_counts.discrepancies == 0);
      std::ostringstream json;
      write_vertices_json(json, input.diagram, nullptr);
      const Judged from_json = judge(input, json.str());
      CHECK(from_json.claims.format == Claim_format::json);
      CHECK(from_json.counts.confirmed == input.diagram.vertices.size());
      CHECK(from_json.strict_counts.discrepancies == 0);
      CHECK(from_json.counts.largest_error.absolute == 0);
      ++inputs;
      vertices += input.diagram.vertices.size();
    }
  }
  MESSAGE(inputs << " inputs, " << vertices << " vertices, all confirmed");
  CHECK(inputs == (site_family_names().size() - 4) * 24 + 4 * 4);
}

namespace {

bool voronota_available() { return std::system("command -v voronota > /dev/null 2>&1") == 0; }

// `voronota calculate-vertices [--link] < balls`.
std::string run_voronota(const std::string& balls, bool link) {
  const auto [code, output] = shell("voronota calculate-vertices" + std::string(link ? " --link" : "") + " < '" + balls + "'");
  REQUIRE(code == 0);
  return output;
}

}  // namespace

TEST_CASE("Voronota on pept: every claim confirmed, with and without --link; on ANO3_3CONNECT 4 missing") {
  if (!voronota_available()) {
    MESSAGE("voronota is not on PATH: skipped (scripts/install-deps.sh installs it)");
    return;
  }
  const Certified_input pept = certified_input("pept", read_sites(kPept, {}).sites);
  REQUIRE(pept.diagram.vertices.size() == 550);
  for (const bool link : {false, true}) {
    CAPTURE(link);
    const Judged j = judge(pept, run_voronota(kPept, link));
    CHECK(j.claims.format == (link ? Claim_format::voronota : Claim_format::text));
    CHECK(j.counts.confirmed == 550);
    CHECK(j.strict_counts.discrepancies == 0);
    MESSAGE("pept: largest difference from the correctly rounded values " << j.counts.largest_error.absolute);
    CHECK(j.counts.largest_error.absolute < 1e-9);
  }

  Scratch scratch;
  const Certified_input ano3 =
      certified_input("ANO3_3CONNECT", read_sites(std::string(APOLLONIUS_TEST_DATA) + "/vdrc/ANO3_3CONNECT.txt", {}).sites);
  std::string balls;
  for (const Site& s : ano3.sites)
    balls += round_trip(s.x) + " " + round_trip(s.y) + " " + round_trip(s.z) + " " + round_trip(s.w) + "\n";
  const Judged j = judge(ano3, run_voronota(scratch.write("ano3.balls", balls), false));
  CHECK(ano3.diagram.vertices.size() == 8);
  CHECK(j.counts.claims == 4);
  CHECK(j.counts.confirmed == 4);
  CHECK(j.counts.missing == 4);
  CHECK(j.counts.discrepancies == 4);
}

TEST_CASE("certify on the command line: exit codes, summary, --report written atomically") {
  Scratch scratch;
  const Certified_input pept = certified_input("pept", read_sites(kPept, {}).sites);
  const std::string good = scratch.write("good.txt", joined(pept.lines));
  std::vector<std::string> dropped_lines = pept.lines;
  dropped_lines.erase(dropped_lines.begin() + 7);
  const std::string dropped = scratch.write("dropped.txt", joined(dropped_lines));
  const std::string report = scratch.path("report.json");

  SUBCASE("our own output: exit 0, and a report that parses") {
    const Cli_result r = run({"certify", kPept, good, "--report", report, "--threads", "2"});
    CHECK(r.code == EXIT_OK);
    CHECK(r.out.empty());
    CHECK(r.err.find("confirmed 550") != std::string::npos);
    CHECK(r.err.find("no discrepancies") != std::string::npos);
    const nlohmann::json json = parse_json(scratch.read("report.json"), "report").value;
    REQUIRE(json.contains("counts"));
    CHECK(json["format"] == "apollonius3d-certify-report");
    CHECK(json["counts"]["confirmed"] == 550);
    CHECK(json["counts"]["discrepancies"] == 0);
    CHECK(json["claims"].size() == 550);
    CHECK(json["claims"][3]["verdict"] == "confirmed");
    CHECK(json["missing"].empty());
    CHECK(scratch.file_count() == 3);  // good.txt, dropped.txt, report.json: no temporary left
  }
  SUBCASE("a dropped vertex: exit 1, named in the summary and the report") {
    const Cli_result r = run({"certify", kPept, dropped, "--report", report});
    CHECK(r.code == EXIT_DISCREPANCIES);
    CHECK(r.err.find("missing 1") != std::string::npos);
    CHECK(r.err.find("missing: vertex 7 ") != std::string::npos);
    const nlohmann::json json = parse_json(scratch.read("report.json"), "report").value;
    REQUIRE(json["missing"].size() == 1);
    CHECK(json["missing"][0]["index"] == 7);
    CHECK(json["counts"]["discrepancies"] == 1);
  }
  SUBCASE("--coord-tol and --strict change the verdicts") {
    std::vector<std::string> lines = pept.lines;
    std::array<double, 4> moved = pept.diagram.vertices[3].rounded;
    moved[2] += 1e-6 * input_scale(pept.sites);
    lines[3] = claim_line(pept.diagram.vertices[3].tie_set, moved);
    const std::string off = scratch.write("off.txt", joined(lines));
    const Cli_result strict_default = run({"certify", kPept, off});
    CHECK(strict_default.code == EXIT_DISCREPANCIES);
    CHECK(strict_default.err.find("coordinates off 1") != std::string::npos);
    CHECK(strict_default.err.find("off.txt:4: coordinates off") != std::string::npos);
    CHECK(run({"certify", kPept, off, "--coord-tol", "1e-5"}).code == EXIT_OK);

    const std::string lattice = scratch.write("lattice.balls", "0 0 0 1\n1 0 0 1\n0 1 0 1\n0 0 1 1\n1 1 0 1\n1 0 1 1\n0 1 1 1\n1 1 1 1\n");
    const std::string surplus =
        scratch.write("surplus.txt", "0 1 2 3 0.5 0.5 0.5 -0.1339745962155614\n4 5 6 7 0.5 0.5 0.5 -0.1339745962155614\n");
    CHECK(run({"certify", lattice, surplus}).code == EXIT_OK);
    CHECK(run({"certify", lattice, surplus, "--strict"}).code == EXIT_DISCREPANCIES);
  }
  SUBCASE("a bad claim file: FILE:LINE, exit 2, and the old report is left as it was") {
    scratch.write("report.json", "old");
    std::vector<std::string> lines = pept.lines;
    lines[4] = "0 1 2 3 4 5 6";
    const std::string bad = scratch.write("bad.txt", joined(lines));
    const Cli_result r = run({"certify", kPept, bad, "--report", report});
    CHECK(r.code == EXIT_BAD_INPUT);
    CHECK(r.err.find("bad.txt:5: ") != std::string::npos);
    CHECK(scratch.read("report.json") == "old");
    CHECK(scratch.file_count() == 4);  // no temporary left

    const Cli_result missing = run({"certify", kPept, scratch.path("none.txt"), "--report", scratch.path("new.json")});
    CHECK(missing.code == EXIT_BAD_INPUT);
    CHECK(missing.err.find("none.txt") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(scratch.path("new.json")));
  }
  SUBCASE("usage errors exit 2 with one line saying what is wrong and a hint to --help") {
    for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
             {"certify"}, {"certify", kPept}, {"certify", kPept, good, "extra"}, {"certify", kPept, good, "--format", "xml"},
             {"certify", kPept, good, "--coord-tol", "-1"}, {"certify", kPept, good, "--coord-tol", "nan"},
             {"certify", kPept, good, "--bogus"}, {"certify", "-", "-"}, {"certify", kPept, good, "--report"}}) {
      const Cli_result r = run(args);
      CHECK(r.code == EXIT_BAD_INPUT);
      CHECK(r.err.rfind("apollonius3d certify: ", 0) == 0);
      CHECK(r.err.find("\nRun 'apollonius3d certify --help' for the options.\n") != std::string::npos);
      CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 2);
    }
    CHECK(run({"certify", kPept, good, "--report", scratch.path("no/dir/report.json")}).code == EXIT_BAD_INPUT);
  }
  SUBCASE("the binary reads CLAIM from stdin and exits 1 on discrepancies") {
    const auto [code, output] = shell(std::string(APOLLONIUS_BINARY) + " certify '" + kPept + "' - --format text < '" +
                                      dropped + "' 2> /dev/null");
    CHECK(code == 1);
    CHECK(output.empty());
    CHECK(shell(std::string(APOLLONIUS_BINARY) + " certify '" + kPept + "' '" + good + "' 2> /dev/null").first == 0);
  }
}
