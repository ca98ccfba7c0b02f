// certify of topology: claimed tie sets (the GPU codes' form, `diagram --format topology`) and Voronota's
// `--link` links, read and judged through the command line. Our own topology certifies clean; planted
// missing, spurious, duplicate and partial sets and planted wrong and missing links are caught and named;
// Voronota's own links are judged; malformed claims exit 2 with FILE:LINE.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "certify/claimed_topology.h"
#include "certify/claimed_vertices.h"
#include "io/input_error.h"
#include "io/json_input.h"
#include "io/read_sites.h"
#include "octree/octree_diagram.h"
#include "reference/brute_force_edges.h"
#include "support/cli_helpers.h"

using namespace apollonius;
using namespace apollonius::testing;

namespace {

const std::string kData = APOLLONIUS_TEST_DATA;
const std::string kPept = kData + "/pept.balls";

std::string read_path(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  REQUIRE(in);
  std::stringstream content;
  content << in.rdbuf();
  return content.str();
}

// The balls text of a vdrc set (a count line, then 'id x y z r'), the numbers copied unchanged.
std::string vdrc_balls(const Scratch& scratch, const std::string& set) {
  std::istringstream in(read_path(kData + "/vdrc/" + set + ".txt"));
  std::string line, balls;
  std::getline(in, line);
  for (std::string id, x, y, z, r; in >> id >> x >> y >> z >> r;) balls += x + " " + y + " " + z + " " + r + "\n";
  return scratch.write(set + ".balls", balls);
}

std::string generated(const Scratch& scratch, const std::string& family, int n, int seed) {
  const std::string path = scratch.path(family + "-" + std::to_string(seed) + ".balls");
  REQUIRE(run({"generate", family, "--n", std::to_string(n), "--seed", std::to_string(seed), "-o", path}).code == EXIT_OK);
  return path;
}

// Our own topology of an input, parsed.
nlohmann::json own_topology(const std::string& input) {
  const Cli_result r = run({"diagram", input, "--format", "topology"});
  REQUIRE(r.code == EXIT_OK);
  return parse_json(r.out, "topology").value;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& line : lines) text += line + "\n";
  return text;
}

std::vector<std::string> fields_of(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> fields;
  for (std::string field; in >> field;) fields.push_back(field);
  return fields;
}

// A Voronota --link line with its link in slot `slot` (0-based) replaced.
std::string with_link(const std::string& line, std::size_t slot, long long link) {
  std::vector<std::string> fields = fields_of(line);
  REQUIRE(fields.size() == 12);
  fields[8 + slot] = std::to_string(link);
  std::string text;
  for (const std::string& f : fields) text += (text.empty() ? "" : " ") + f;
  return text;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("our own topology certifies clean: vdrc sets and generated families") {
  Scratch scratch;
  std::vector<std::string> inputs;
  for (const char* set : {"ANO1_0CONNECT", "ANO3_3CONNECT", "Vis_II_5", "Vis_III_5", "Vis_I_10", "Vis_V_20", "Vis_VII_20"})
    inputs.push_back(vdrc_balls(scratch, set));
  inputs.push_back(kPept);
  for (const char* family : {"uniform", "mixed-sign", "nested", "lattice", "cospherical", "tangent"})
    for (const int seed : {1, 2, 3}) inputs.push_back(generated(scratch, family, 25, seed));
  std::size_t sets = 0;
  for (const std::string& input : inputs) {
    CAPTURE(input);
    const Cli_result diagram = run({"diagram", input, "--format", "topology", "-o", scratch.path("own.json")});
    REQUIRE(diagram.code == EXIT_OK);
    const Cli_result r = run({"certify", input, scratch.path("own.json"), "--strict", "--report", scratch.path("report.json")});
    INFO(r.err);
    CHECK(r.code == EXIT_OK);
    CHECK(contains(r.err, "no discrepancies"));
    const nlohmann::json report = parse_json(scratch.read("report.json"), "report").value;
    CHECK(report["claim_format"] == "topology");
    CHECK(report["counts"]["discrepancies"] == 0);
    for (const char* category : {"bisectors", "trisectors", "quadrisectors"}) {
      const nlohmann::json& counts = report["topology"][category]["counts"];
      CHECK(counts["confirmed"] == counts["exact"]);
      CHECK(counts["claimed"] == counts["exact"]);
      sets += counts["exact"].get<std::size_t>();
    }
  }
  MESSAGE(inputs.size() << " inputs, " << sets << " sets confirmed");
  CHECK(sets > 5000);
}

TEST_CASE("planted topology defects: a missing trisector, a spurious one, a duplicate, a partial tie set") {
  Scratch scratch;
  const std::string input = generated(scratch, "uniform", 30, 4);
  const nlohmann::json own = own_topology(input);
  REQUIRE(own["trisectors"].size() > 10);

  SUBCASE("a trisector removed is missing") {
    nlohmann::json claim = own;
    const nlohmann::json removed = claim["trisectors"][5];
    claim["trisectors"].erase(5);
    const std::string path = scratch.write("claim.json", claim.dump(1));
    const Cli_result r = run({"certify", input, path, "--report", scratch.path("report.json")});
    INFO(r.err);
    CHECK(r.code == EXIT_DISCREPANCIES);
    CHECK(contains(r.err, "trisectors: " + std::to_string(own["trisectors"].size() - 1) + " claimed"));
    CHECK(contains(r.err, "missing 1\n"));
    std::string sites;
    for (const auto& s : removed) sites += " " + std::to_string(s.get<int>());
    CHECK(contains(r.err, "missing: trisectors" + sites + "\n"));
    const nlohmann::json report = parse_json(scratch.read("report.json"), "report").value;
    CHECK(report["topology"]["trisectors"]["missing"] == nlohmann::json::array({removed}));
    CHECK(report["topology"]["bisectors"]["counts"]["discrepancies"] == 0);
    CHECK(report["counts"]["discrepancies"] == 1);
  }
  SUBCASE("a triple that is no edge is spurious, named with its line") {
    nlohmann::json claim = own;
    std::vector<int> spurious;
    for (int a = 0; a < 30 && spurious.empty(); ++a)
      for (int b = a + 1; b < 30 && spurious.empty(); ++b)
        for (int c = b + 1; c < 30 && spurious.empty(); ++c)
          if (std::find(own["trisectors"].begin(), own["trisectors"].end(), nlohmann::json{a, b, c}) == own["trisectors"].end())
            spurious = {c, a, b};  // any order
    claim["trisectors"].push_back(spurious);
    const std::string path = scratch.write("claim.json", claim.dump(1));
    const Cli_result r = run({"certify", input, path});
    INFO(r.err);
    CHECK(r.code == EXIT_DISCREPANCIES);
    CHECK(contains(r.err, "spurious 1, missing 0\n"));
    CHECK(contains(r.err, "trisectors " + std::to_string(spurious[1]) + " " + std::to_string(spurious[2]) + " " +
                              std::to_string(spurious[0]) + ": spurious"));
  }
  SUBCASE("a repeated quadrisector is a duplicate") {
    nlohmann::json claim = own;
    claim["quadrisectors"].push_back(own["quadrisectors"][0]);
    const Cli_result r = run({"certify", input, scratch.write("claim.json", claim.dump(1))});
    CHECK(r.code == EXIT_DISCREPANCIES);
    CHECK(contains(r.err, "duplicate 1"));
  }
  SUBCASE("a category left out is not judged") {
    nlohmann::json claim = own;
    claim.erase("quadrisectors");
    const Cli_result r = run({"certify", input, scratch.write("claim.json", claim.dump(1))});
    CHECK(r.code == EXIT_OK);
    CHECK(contains(r.err, "quadrisectors: not claimed, not judged"));
  }
  SUBCASE("a degenerate vertex named by 4 of its sites is partial: allowed, a discrepancy with --strict") {
    const std::string lattice = scratch.write("lattice.balls", "0 0 0 1\n1 0 0 1\n0 1 0 1\n0 0 1 1\n1 1 0 1\n1 0 1 1\n0 1 1 1\n1 1 1 1\n");
    nlohmann::json claim = own_topology(lattice);
    nlohmann::json& quadrisectors = claim["quadrisectors"];
    const auto degenerate = std::find_if(quadrisectors.begin(), quadrisectors.end(), [](const nlohmann::json& q) { return q.size() > 4; });
    REQUIRE(degenerate != quadrisectors.end());
    while (degenerate->size() > 4) degenerate->erase(degenerate->size() - 1);
    const std::string path = scratch.write("partial.json", claim.dump(1));
    const Cli_result r = run({"certify", lattice, path});
    INFO(r.err);
    CHECK(r.code == EXIT_OK);
    CHECK(contains(r.err, "partial 1"));
    const Cli_result strict = run({"certify", lattice, path, "--strict"});
    CHECK(strict.code == EXIT_DISCREPANCIES);
    CHECK(contains(strict.err, ": partial of the tie set "));
  }
}

TEST_CASE("Voronota's links on pept: 2 missing as recorded; planted wrong and missing links caught and named") {
  Scratch scratch;
  // Recorded: `voronota calculate-vertices --link < tests/data/pept.balls` (tests/data/README.md).
  const std::string recorded = kData + "/voronota/pept.link.txt";
  const std::vector<std::string> lines = lines_of(read_path(recorded));
  REQUIRE(lines.size() == 550);

  const Claimed_vertex_list list = read_claimed_vertices(joined(lines), "pept", std::nullopt, 107);
  CHECK(list.format == Claim_format::voronota);
  for (const Claimed_vertex& claim : list.vertices) REQUIRE(claim.links);

  SUBCASE("as Voronota wrote them: two missing links, both ways along the edge of 83 85 87") {
    const Cli_result r = run({"certify", kPept, recorded, "--report", scratch.path("report.json")});
    INFO(r.err);
    CHECK(r.code == EXIT_DISCREPANCIES);
    CHECK(contains(r.err, "confirmed 550, surplus 0, duplicate 0, coordinates off 0, wrong root 0, not a vertex 0, missing 0\n"));
    CHECK(contains(r.err, "links 2200: right 2198, wrong 0, missing 2, not judged 0 "));
    CHECK(contains(r.err, "pept.link.txt:492: link 4 (edge of sites 83 85 87): missing: -1; the edge leaves vertex 491 for vertex 492 "));
    CHECK(contains(r.err, "pept.link.txt:493: link 4 (edge of sites 83 85 87): missing: -1; the edge leaves vertex 492 for vertex 491 "));
    const nlohmann::json report = parse_json(scratch.read("report.json"), "report").value;
    CHECK(report["links"]["counts"]["right"] == 2198);
    CHECK(report["counts"]["discrepancies"] == 2);
    CHECK(report["claims"][0]["link_verdicts"].size() == 4);
  }
  // The first claim with a link to a vertex in slot 2, and the other claims.
  std::size_t planted = 0;
  while (fields_of(lines[planted])[10] == "-1") ++planted;
  const long long target = std::stoll(fields_of(lines[planted])[10]);
  SUBCASE("a link to another line is wrong, named with both lines") {
    std::vector<std::string> edited = lines;
    edited[planted] = with_link(lines[planted], 2, (target + 1) % 550);
    const Cli_result r = run({"certify", kPept, scratch.write("wrong.txt", joined(edited)), "--report", scratch.path("report.json")});
    INFO(r.err);
    CHECK(r.code == EXIT_DISCREPANCIES);
    CHECK(contains(r.err, "wrong 1, missing 2"));
    CHECK(contains(r.err, "wrong.txt:" + std::to_string(planted + 1) + ": link 3 (edge of sites "));
    CHECK(contains(r.err, "): wrong: line " + std::to_string((target + 1) % 550 + 1) + ", vertex "));
    CHECK(contains(r.err, "claimed on line " + std::to_string(target + 1) + "\n"));
    const nlohmann::json report = parse_json(scratch.read("report.json"), "report").value;
    REQUIRE(report["links"]["discrepancies"].size() == 3);
    const nlohmann::json& wrong = report["links"]["discrepancies"][0];  // before lines 492 and 493
    CHECK(wrong["verdict"] == "wrong");
    CHECK(wrong["line"] == planted + 1);
    CHECK(wrong["expected_line"] == target + 1);
    CHECK(report["counts"]["discrepancies"] == 3);
  }
  SUBCASE("-1 where the edge ends at a vertex is a missing link") {
    std::vector<std::string> edited = lines;
    edited[planted] = with_link(lines[planted], 2, -1);
    const Cli_result r = run({"certify", kPept, scratch.write("missing.txt", joined(edited))});
    INFO(r.err);
    CHECK(r.code == EXIT_DISCREPANCIES);
    CHECK(contains(r.err, "wrong 0, missing 3"));
    CHECK(contains(r.err, "missing.txt:" + std::to_string(planted + 1) + ": link 3 (edge of sites "));
    CHECK(contains(r.err, "): missing: -1; the edge leaves vertex "));
  }
  SUBCASE("a link where the edge goes to infinity is wrong") {
    std::size_t infinite = 0;
    std::size_t slot = 0;
    for (; infinite < lines.size(); ++infinite) {
      const std::vector<std::string> f = fields_of(lines[infinite]);
      const auto minus = std::find(f.begin() + 8, f.end(), "-1");
      if (minus != f.end()) {
        slot = static_cast<std::size_t>(minus - f.begin() - 8);
        break;
      }
    }
    REQUIRE(infinite < lines.size());
    std::vector<std::string> edited = lines;
    edited[infinite] = with_link(lines[infinite], slot, 0);
    const Cli_result r = run({"certify", kPept, scratch.write("infinite.txt", joined(edited))});
    INFO(r.err);
    CHECK(r.code == EXIT_DISCREPANCIES);
    CHECK(contains(r.err, "wrong 1, missing 2"));
    CHECK(contains(r.err, " for infinity\n"));
  }
  SUBCASE("links are permuted with the sites") {
    // Sites written in reverse order, with their links: the same claim, still right.
    std::vector<std::string> edited = lines;
    const std::vector<std::string> f = fields_of(lines[planted]);
    edited[planted] = f[3] + " " + f[2] + " " + f[1] + " " + f[0] + " " + f[4] + " " + f[5] + " " + f[6] + " " + f[7] + " " +
                      f[11] + " " + f[10] + " " + f[9] + " " + f[8];
    CHECK(contains(run({"certify", kPept, scratch.write("reversed.txt", joined(edited))}).err, "right 2198, wrong 0, missing 2,"));
    const Claimed_vertex_list reversed = read_claimed_vertices(joined(edited), "r", std::nullopt, 107);
    CHECK(reversed.vertices[planted].sites == list.vertices[planted].sites);
    CHECK(reversed.vertices[planted].links == list.vertices[planted].links);
  }
}

TEST_CASE("the two links Voronota leaves out on pept: the brute-force edge reference has their edge") {
  // brute_force_edges shares no code with build_topology: every arc of every triple tested at a witness.
  const std::vector<Site> sites = read_sites(kPept, {}).sites;
  const Diagram diagram = octree_diagram(sites);
  REQUIRE(diagram.vertices.size() == 550);
  CHECK(diagram.vertices[491].tie_set == std::vector<Site_index>{83, 85, 87, 98});
  CHECK(diagram.vertices[492].tie_set == std::vector<Site_index>{83, 85, 87, 102});
  const std::vector<Diagram_edge> edges = brute_force_edges(sites, diagram);
  const auto edge = std::find_if(edges.begin(), edges.end(), [](const Diagram_edge& e) {
    return e.tie_set == std::vector<Site_index>{83, 85, 87} && e.start && e.end &&
           std::min(*e.start, *e.end) == 491 && std::max(*e.start, *e.end) == 492;
  });
  CHECK(edge != edges.end());
}

TEST_CASE("Voronota's links on ANO3_3CONNECT: its 4 vertices linked right, the other component missing") {
  Scratch scratch;
  const std::string input = vdrc_balls(scratch, "ANO3_3CONNECT");
  // Recorded: `voronota calculate-vertices --link` on the balls of tests/data/vdrc/ANO3_3CONNECT.txt.
  const std::string claim = kData + "/voronota/ANO3_3CONNECT.link.txt";
  if (shell("command -v voronota > /dev/null 2>&1").first == 0) {
    const auto [code, output] = shell("voronota calculate-vertices --link < '" + input + "'");
    REQUIRE(code == 0);
    CHECK(output == read_path(claim));  // the recording is what this Voronota prints
  } else {
    MESSAGE("voronota is not on PATH: the recorded output alone is judged");
  }
  const Cli_result r = run({"certify", input, claim, "--report", scratch.path("report.json")});
  INFO(r.err);
  CHECK(r.code == EXIT_DISCREPANCIES);
  CHECK(contains(r.err, "confirmed 4, surplus 0, duplicate 0, coordinates off 0, wrong root 0, not a vertex 0, missing 4\n"));
  // The two roots of each missing quadruple are joined to each other (three edges each), never to
  // Voronota's vertices: every one of its links is right.
  CHECK(contains(r.err, "links 16: right 16, wrong 0, missing 0, not judged 0 "));
  const nlohmann::json report = parse_json(scratch.read("report.json"), "report").value;
  CHECK(report["counts"]["discrepancies"] == 4);
  CHECK(report["links"]["discrepancies"].empty());
}

TEST_CASE("malformed claims: out-of-range links and bad topology JSON exit 2 with FILE:LINE") {
  Scratch scratch;
  struct Case {
    const char* what;
    std::string content;
    std::size_t line;
    const char* reason;
  };
  const std::string v = " 1.0 2.0 3.0 4.0 ";
  const std::vector<Case> cases = {
      {"link past the list", "0 1 2 3" + v + "1 -1 -1 -1\n0 1 2 4" + v + "0 -1 2 -1\n", 2, "vertex link 2 out of range (the list has 2 vertices)"},
      {"link below -1", "0 1 2 3" + v + "-1 -1 -1 -2\n", 1, "not a vertex link"},
      {"topology not an object", "[{\"bisectors\": []}]", 1, "expected a JSON object, found an array"},
      {"category not an array", "{\"bisectors\": [],\n\"trisectors\": {}}", 2, "\"trisectors\" must be an array"},
      {"set not an array", "{\"trisectors\": [\n[0, 1, 2],\n3]}", 3, "a trisector must be an array"},
      {"index not an integer", "{\"trisectors\": [\n[0, 1,\n2.5]]}", 3, "not a site index: 2.5"},
      {"negative index", "{\"bisectors\": [[0, -1]]}", 1, "not a site index: -1"},
      {"index out of range", "{\"quadrisectors\": [\n[0, 1, 2, 3],\n[0, 1, 2, 9]]}", 3, "site index 9 out of range"},
      {"repeated index", "{\"trisectors\": [[0, 1, 1]]}", 1, "site index 1 listed twice"},
      {"bisector of 3", "{\"bisectors\": [[0, 1],\n[0, 1, 2]]}", 2, "a bisector has 2 sites, found 3"},
      {"trisector of 2", "{\"trisectors\": [[0, 1]]}", 1, "a trisector has at least 3 sites, found 2"},
      {"quadrisector of 3", "{\"quadrisectors\": [\n\n[0, 1, 2]]}", 3, "a quadrisector has at least 4 sites, found 3"},
      {"syntax", "{\"bisectors\": [[0, 1],\n[0 2]]}", 2, "syntax error"},
  };
  const std::string input = scratch.write("five.balls", "0 0 0 1\n3 0 0 1\n0 3 0 1\n0 0 3 1\n3 3 3 1\n");
  for (const Case& c : cases) {
    INFO(std::string(c.what));
    const std::string claim = scratch.write("claim.txt", c.content);
    const std::vector<std::string> format =
        std::string(c.what) == "topology not an object" ? std::vector<std::string>{"--format", "topology"} : std::vector<std::string>{};
    std::vector<std::string> args = {"certify", input, claim, "--report", scratch.path("report.json")};
    args.insert(args.end(), format.begin(), format.end());
    const Cli_result r = run(args);
    INFO(r.err);
    CHECK(r.code == EXIT_BAD_INPUT);
    CHECK(contains(r.err, "claim.txt:" + std::to_string(c.line) + ": " + c.reason));
    CHECK_FALSE(std::filesystem::exists(scratch.path("report.json")));
  }
  // Detection: a JSON object with a topology member is a topology claim; otherwise a vertex list.
  CHECK(detect_claim_format("{\"trisectors\": []}") == Claim_format::topology);
  CHECK(detect_claim_format("\xEF\xBB\xBF {\"quadrisectors\": []}") == Claim_format::topology);
  CHECK(detect_claim_format("{\"vertices\": []}") == Claim_format::json);
  CHECK(detect_claim_format("{\"trisectors\": [}") == Claim_format::json);  // malformed: the JSON reader names the line
  CHECK_THROWS_AS(read_claimed_topology("{\"faces\": []}", "t", 5), Input_error);
}

TEST_CASE("property: mutated claims are read or refused with Input_error, never anything else") {
  // Byte flips, deletions and insertions in a Voronota --link list and a topology claim; whatever is read
  // keeps its invariants (sites sorted, distinct, in range; links -1 or within the list).
  Scratch scratch;
  const std::string link = read_path(kData + "/voronota/ANO3_3CONNECT.link.txt");
  const std::string topology = own_topology(vdrc_balls(scratch, "ANO3_3CONNECT")).dump(1);
  std::size_t read = 0, refused = 0;
  for (std::uint64_t seed = 1; seed <= 3000; ++seed) {
    CAPTURE(seed);
    std::mt19937_64 random(seed);
    std::string content = seed % 2 == 0 ? link : topology;
    const char alphabet[] = "0123456789 -.,[]{}\n\"eE+xinf";
    for (int edit = 0; edit < 1 + static_cast<int>(random() % 4); ++edit) {
      const std::size_t at = random() % content.size();
      const char c = alphabet[random() % (sizeof alphabet - 1)];
      switch (random() % 3) {
        case 0: content[at] = c; break;
        case 1: content.erase(at, 1); break;
        default: content.insert(at, 1, c); break;
      }
    }
    try {
      if (detect_claim_format(content) == Claim_format::topology) {
        const Claimed_topology t = read_claimed_topology(content, "mutated", 9);
        for (std::size_t c = 0; c < 3; ++c)
          for (const Claimed_set& set : t.categories[c].sets) {
            REQUIRE(set.sites.size() >= c + 2);
            REQUIRE(std::adjacent_find(set.sites.begin(), set.sites.end(), std::greater_equal<>()) == set.sites.end());
            REQUIRE(set.sites.back() < 9);
          }
      } else {
        const Claimed_vertex_list list = read_claimed_vertices(content, "mutated", std::nullopt, 9);
        for (const Claimed_vertex& claim : list.vertices) {
          REQUIRE(std::adjacent_find(claim.sites.begin(), claim.sites.end(), std::greater_equal<>()) == claim.sites.end());
          REQUIRE(claim.sites.back() < 9);
          if (claim.links)
            for (const long long l : *claim.links) REQUIRE((l >= -1 && l < static_cast<long long>(list.vertices.size())));
        }
      }
      ++read;
    } catch (const Input_error& e) {
      REQUIRE(e.file() == "mutated");
      REQUIRE(e.line() <= static_cast<std::size_t>(std::count(content.begin(), content.end(), '\n')) + 1);
      ++refused;
    }
  }
  MESSAGE(read << " mutated claims read, " << refused << " refused");
  CHECK(read > 100);
  CHECK(refused > 100);
}
