// The command line: outputs, stdin, --stats, and every kind of bad input (message with file:line and
// reason, exit code 2, no output file).
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli_helpers.h"

using namespace apollonius;
using namespace apollonius::testing;
namespace fs = std::filesystem;

namespace {

const std::string kTetrahedron = "1 1 1 1\n1 -1 -1 1\n-1 1 -1 1\n-1 -1 1 1\n";

}  // namespace

TEST_CASE("vertices writes text to stdout or atomically to -o, and JSON on request") {
  Scratch scratch;
  const std::string input = scratch.write("tetra.balls", kTetrahedron);
  const Cli_result text = run({"vertices", input});
  CHECK(text.code == EXIT_OK);
  CHECK(text.out == "0 1 2 3 0 0 0 0.7320508075688773\n");

  const std::string out = scratch.path("out.txt");
  CHECK(run({"vertices", input, "-o", out}).code == EXIT_OK);
  std::ifstream written(out);
  std::stringstream content;
  content << written.rdbuf();
  CHECK(content.str() == text.out);

  const Cli_result json = run({"vertices", input, "--format", "json", "--stats"});
  CHECK(json.code == EXIT_OK);
  CHECK(json.out.find("\"vertices\"") != std::string::npos);
  CHECK(json.out.find("\"exact_stages\"") != std::string::npos);
  CHECK(json.err.find("vertex_conflict") == std::string::npos);  // 4 sites: no conflict tests at all
  CHECK(json.err.find("vertices_of") != std::string::npos);
}

TEST_CASE("the binary reads stdin with '-' and exits 0") {
  Scratch scratch;
  const std::string input = scratch.write("tetra.balls", kTetrahedron);
  const auto [code, output] = shell(std::string(APOLLONIUS_BINARY) + " vertices - < '" + input + "'");
  CHECK(code == 0);
  CHECK(output == "0 1 2 3 0 0 0 0.7320508075688773\n");
}

TEST_CASE("bad input: file:line and reason, exit code 2, no output file") {
  Scratch scratch;
  struct Case {
    const char* what;
    std::string content;  // empty name: a missing file
    std::string expected_message;
  };
  const std::string nul("1 2 3 4\n\0\x01\x02garbage\n", 20);
  const std::vector<Case> cases = {
      {"NaN", "1 2 3 4\n1 nan 3 4\n", "bad.txt:2:"},
      {"inf", "1 2 3 4\n1 2 inf 4\n", "bad.txt:2:"},
      {"three numbers", "1 2 3 4\n1 2 3\n", "bad.txt:2:"},
      {"words", "1 2 3 4\nhello world foo bar\n", "bad.txt:2:"},
      {"empty file", "", "bad.txt"},
      {"binary garbage", nul, "bad.txt:2:"},
      {"PDB with no atoms", "HEADER    NOTHING HERE\nEND\n", "bad.txt"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.what);
    const std::string input = scratch.write("bad.txt", c.content);
    const std::string out = scratch.path("out.txt");
    const Cli_result r = run({"vertices", input, "-o", out});
    CHECK(r.code == EXIT_BAD_INPUT);
    CHECK(r.err.find(c.expected_message) != std::string::npos);
    CHECK_FALSE(fs::exists(out));
    CHECK(std::distance(fs::directory_iterator(scratch.dir), fs::directory_iterator()) == 1);  // no temporary left
  }
  SUBCASE("a missing file") {
    const Cli_result r = run({"vertices", scratch.path("missing.txt"), "-o", scratch.path("out.txt")});
    CHECK(r.code == EXIT_BAD_INPUT);
    CHECK(r.err.find("missing.txt") != std::string::npos);
    CHECK_FALSE(fs::exists(scratch.path("out.txt")));
  }
  SUBCASE("a PDB file with no atoms, by extension") {
    const std::string input = scratch.write("empty.pdb", "HEADER    NOTHING HERE\nEND\n");
    const Cli_result r = run({"vertices", input, "-o", scratch.path("out.txt")});
    CHECK(r.code == EXIT_BAD_INPUT);
    CHECK(r.err.find("no atoms") != std::string::npos);
  }
}

TEST_CASE("usage errors exit 2 with the usage text") {
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {}, {"frobnicate"}, {"vertices"}, {"vertices", "a", "--format", "xml"}, {"vertices", "a", "--algorithm", "magic"},
           {"vertices", "a", "--bogus"}, {"vertices", "a", "-o"}}) {
    const Cli_result r = run(args);
    CHECK(r.code == EXIT_BAD_INPUT);
    CHECK(r.err.find("usage:") != std::string::npos);
  }
  CHECK(run({"--help"}).code == EXIT_OK);
}

TEST_CASE("an unwritable output path is an error, not a crash") {
  Scratch scratch;
  const std::string input = scratch.write("tetra.balls", kTetrahedron);
  const Cli_result r = run({"vertices", input, "-o", scratch.path("no/such/dir/out.txt")});
  CHECK(r.code == EXIT_BAD_INPUT);
  CHECK(r.err.find("out.txt") != std::string::npos);
}
