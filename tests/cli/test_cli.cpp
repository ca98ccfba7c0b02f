// The command line: outputs, stdin, --stats, and every kind of bad input (message with file:line and
// reason, exit code 2, no output file); generate's sites read back exactly as the tests generate them.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>

#include "reference/brute_force_diagram.h"
#include "cli/command.h"
#include "support/cli_helpers.h"
#include "io/read_sites.h"
#include "io/write_sites.h"
#include "io/write_vertices.h"
#include "reference/site_generators.h"

using namespace apollonius;
using namespace apollonius::testing;
namespace fs = std::filesystem;

namespace {

std::string read_file(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  std::stringstream content;
  content << file.rdbuf();
  return content.str();
}

// Equal as bit patterns: -0 and 0 differ, unlike with Site's operator==.
bool same_bits(const std::vector<Site>& a, const std::vector<Site>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(Site)) == 0);
}

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

TEST_CASE("usage errors: one line saying what is wrong, a hint to --help, exit 2") {
  struct Case {
    std::vector<std::string> args;
    std::string command;  // "apollonius3d" or "apollonius3d COMMAND"
    std::string message;
  };
  for (const Case& c : std::vector<Case>{
           {{}, "apollonius3d", "A subcommand is required"},
           {{"frobnicate"}, "apollonius3d", "frobnicate"},
           {{"vertices"}, "apollonius3d vertices", "INPUT is required"},
           {{"vertices", "a", "--format", "xml"}, "apollonius3d vertices", "--format"},
           {{"vertices", "a", "--algorithm", "magic"}, "apollonius3d vertices", "--algorithm"},
           {{"vertices", "a", "--bogus"}, "apollonius3d vertices", "--bogus"},
           {{"vertices", "a", "--thread", "2"}, "apollonius3d vertices", "--thread"},
           {{"vertices", "a", "-o"}, "apollonius3d vertices", "-o"},
           {{"vertices", "a", "--threads", "abc"}, "apollonius3d vertices", "--threads: needs an integer from 1 to 1024, not 'abc'"},
           {{"vertices", "a", "--threads", "0"}, "apollonius3d vertices", "--threads: needs an integer from 1 to 1024, not '0'"},
           {{"vertices", "a", "--threads", "2.5"}, "apollonius3d vertices", "--threads: needs an integer"},
           {{"vertices", "a", "--box", "0", "0", "0", "1", "1"}, "apollonius3d vertices", "--box"},
           {{"vertices", "a", "--box", "0", "0", "0", "1", "1", "inf"}, "apollonius3d vertices", "needs a finite number, not 'inf'"},
           {{"vertices", "a", "--box", "0", "0", "0", "1", "-1", "1"}, "apollonius3d vertices", "X0 <= X1"},
           {{"vertices", "a", "--arith", "float", "--algorithm", "brute"}, "apollonius3d vertices", "octree only"}}) {
    std::string command_line;
    for (const std::string& a : c.args) command_line += a + ' ';
    CAPTURE(command_line);
    const Cli_result r = run(c.args);
    CHECK(r.code == EXIT_BAD_INPUT);
    CHECK(r.out.empty());
    CHECK(r.err.rfind(c.command + ": ", 0) == 0);
    CHECK(r.err.find(c.message) != std::string::npos);
    CHECK(r.err.find("\nRun '" + c.command + " --help' for the options.\n") != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 2);
  }
}

TEST_CASE("--help, per command, and --version") {
  const Cli_result help = run({"--help"});
  CHECK(help.code == EXIT_OK);
  for (const char* command : {"vertices", "certify", "crosscheck", "generate"}) {
    CAPTURE(command);
    CHECK(help.out.find(command) != std::string::npos);
    const Cli_result own = run({command, "--help"});
    CHECK(own.code == EXIT_OK);
    CHECK(own.err.empty());
    CHECK(own.out.find(std::string("Usage: apollonius3d ") + command) != std::string::npos);
    CHECK(own.out.find("Exit codes:") != std::string::npos);
  }
  CHECK(run({"vertices", "--help"}).out.find("--threads") != std::string::npos);
  CHECK(run({"vertices", "--help"}).out.find("--coord-tol") == std::string::npos);  // certify's, not vertices'
  const Cli_result version = run({"--version"});
  CHECK(version.code == EXIT_OK);
  CHECK(version.out == std::string("apollonius3d ") + APOLLONIUS3D_VERSION + "\n");
}

TEST_CASE("-o - writes to standard output, and no file named '-'") {
  Scratch scratch;
  const std::string input = scratch.write("tetra.balls", kTetrahedron);
  const auto [code, output] = shell("cd '" + scratch.dir.string() + "' && " + APOLLONIUS_BINARY + " vertices tetra.balls -o -");
  CHECK(code == 0);
  CHECK(output == "0 1 2 3 0 0 0 0.7320508075688773\n");
  CHECK_FALSE(fs::exists(scratch.path("-")));
}

TEST_CASE("more threads than the machine has: the same output, and no warning from TBB") {
  Scratch scratch;
  const std::string input = scratch.path("lattice.balls");
  REQUIRE(run({"generate", "uniform", "--n", "300", "--seed", "4", "-o", input}).code == EXIT_OK);
  const auto [code, output] = shell(std::string(APOLLONIUS_BINARY) + " vertices '" + input + "' --threads 64 2>&1");
  CHECK(code == 0);
  CHECK(output.find("TBB") == std::string::npos);
  CHECK(output == run({"vertices", input}).out);
  // mesh made its own arena of the count asked for, and TBB warned (caught on 2026-11-30).
  const std::string tetra = scratch.write("tetra.balls", kTetrahedron), ply = scratch.path("tetra.ply");
  const auto [mesh_code, mesh_output] = shell(std::string(APOLLONIUS_BINARY) + " mesh '" + tetra + "' -o '" + ply + "' --threads 64 2>&1");
  CHECK(mesh_code == 0);
  CHECK(mesh_output.find("TBB") == std::string::npos);
  CHECK(fs::exists(ply));
}

TEST_CASE("a UTF-8 byte-order mark at the start of a text input is skipped") {
  Scratch scratch;
  const std::string with_mark = scratch.write("bom.balls", "\xEF\xBB\xBF" + kTetrahedron);
  const Cli_result r = run({"vertices", with_mark});
  CHECK(r.code == EXIT_OK);
  CHECK(r.out == "0 1 2 3 0 0 0 0.7320508075688773\n");
  const std::string vdrc = scratch.write("bom.txt", "\xEF\xBB\xBF" "4\n1 1 1 1 1\n2 1 -1 -1 1\n3 -1 1 -1 1\n4 -1 -1 1 1\n");
  CHECK(run({"vertices", vdrc}).out == r.out);
  // Elsewhere it is no number: refused with the line.
  const std::string inside = scratch.write("inside.balls", kTetrahedron + "\xEF\xBB\xBF" "1 2 3 4\n");
  const Cli_result bad = run({"vertices", inside});
  CHECK(bad.code == EXIT_BAD_INPUT);
  CHECK(bad.err.find("inside.balls:5:") != std::string::npos);
}

TEST_CASE("an unwritable output path is an error, not a crash") {
  Scratch scratch;
  const std::string input = scratch.write("tetra.balls", kTetrahedron);
  const Cli_result r = run({"vertices", input, "-o", scratch.path("no/such/dir/out.txt")});
  CHECK(r.code == EXIT_BAD_INPUT);
  CHECK(r.err.find("out.txt") != std::string::npos);
}

TEST_CASE("generate writes exactly the sites of generate_sites, which read back bit for bit") {
  for (const std::string& name : site_family_names()) {
    for (const std::uint64_t seed : {std::uint64_t{0}, std::uint64_t{1}, std::uint64_t{42}, ~std::uint64_t{0}}) {
      for (const std::size_t n : {1, 7, 40}) {
        CAPTURE(name);
        CAPTURE(seed);
        CAPTURE(n);
        const Cli_result r = run({"generate", name, "--n", std::to_string(n), "--seed", std::to_string(seed)});
        REQUIRE(r.code == EXIT_OK);
        const std::string header = "# apollonius3d generate " + name + " --n " + std::to_string(n) + " --seed " +
                                   std::to_string(seed) + "\n";
        CHECK(r.out.compare(0, header.size(), header) == 0);
        const Site_input input = read_sites_from_text(r.out, "generated", {});
        CHECK(input.format == Input_format::balls);
        CHECK(same_bits(input.sites, generate_sites(site_family_from_name(name), n, seed)));
      }
    }
  }
}

TEST_CASE("vertices of a generated file are the vertices of the generated sites") {
  Scratch scratch;
  for (const char* name : {"lattice-noise", "scaled-down", "mixed-sign"}) {
    CAPTURE(name);
    const std::string file = scratch.path(std::string(name) + ".balls");
    REQUIRE(run({"generate", name, "--n", "9", "--seed", "5", "-o", file}).code == EXIT_OK);
    std::ostringstream expected;
    write_vertices_text(expected, brute_force_diagram(generate_sites(site_family_from_name(name), 9, 5)));
    CHECK(!expected.str().empty());
    // auto, the default, takes the lifted triangulation for these 9 sites (at most 256 active ones).
    for (const std::string algorithm : {"brute", "octree", "lifted", "auto"}) {
      CAPTURE(algorithm);
      const Cli_result r = run({"vertices", file, "--algorithm", algorithm, "--stats"});
      REQUIRE(r.code == EXIT_OK);
      CHECK(r.out == expected.str());
      CHECK((r.err.find("lifted fallback") != std::string::npos) == (algorithm == "lifted" || algorithm == "auto"));
      CHECK((r.err.find("lifted_reason small_input") != std::string::npos) == (algorithm == "auto"));
      CHECK((r.err.find("lifted_reason box_budget") != std::string::npos) == (algorithm == "lifted"));
    }
    const Cli_result by_default = run({"vertices", file, "--stats"});
    CHECK(by_default.out == expected.str());
    CHECK(by_default.err.find("lifted_reason small_input") != std::string::npos);
  }
}

// One ball far from a cluster once sent the propagation past its budget of seed candidates; its nearest
// witnesses keep them few now, and the octree answers as the lifted triangulation does.
TEST_CASE("vertices: a ball 1e6 away from a cluster stays in the octree, with the lifted triangulation's answer") {
  Scratch scratch;
  std::vector<Site> sites = generate_sites(Site_family::uniform, 1000, 3);
  sites.push_back({1e6, 0, 0, 1});
  const std::string file = scratch.path("ball_1e6_away.balls");
  {
    std::ofstream out(file);
    write_sites_text(out, sites, "uniform 1000 and a ball 1e6 away");
  }
  const Cli_result lifted = run({"vertices", file, "--algorithm", "lifted"});
  REQUIRE(lifted.code == EXIT_OK);
  for (const std::string algorithm : {"auto", "octree"}) {
    CAPTURE(algorithm);
    const Cli_result r = run({"vertices", file, "--algorithm", algorithm, "--stats"});
    REQUIRE(r.code == EXIT_OK);
    CHECK(r.out == lifted.out);
    CHECK(r.err.find("lifted_reason") == std::string::npos);
    CHECK(r.err.find("\nboxes 0\n") == std::string::npos);
  }
}

TEST_CASE("generate --list describes every family; bad arguments exit 2 and write nothing") {
  const Cli_result list = run({"generate", "--list"});
  CHECK(list.code == EXIT_OK);
  for (const Site_family_description& d : kSiteFamilies) {
    CAPTURE(d.name);
    CHECK(list.out.find(d.name) != std::string::npos);
    CHECK(list.out.find(d.summary) != std::string::npos);
  }

  Scratch scratch;
  const std::string out = scratch.path("sites.balls");
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"generate"},
           {"generate", "bogus", "--n", "5", "--seed", "1", "-o", out},
           {"generate", "uniform", "--n", "0", "--seed", "1", "-o", out},
           {"generate", "uniform", "--n", "1000001", "--seed", "1", "-o", out},
           {"generate", "uniform", "--n", "5x", "--seed", "1", "-o", out},
           {"generate", "uniform", "--n", "-5", "--seed", "1", "-o", out},
           {"generate", "uniform", "--n", "5", "--seed", "-1", "-o", out},
           {"generate", "uniform", "--n", "5", "--seed", "18446744073709551616", "-o", out},
           {"generate", "uniform", "--seed", "1", "-o", out},
           {"generate", "uniform", "--n", "5", "-o", out},
           {"generate", "uniform", "lattice", "--n", "5", "--seed", "1", "-o", out},
           {"generate", "--list", "uniform"},
           {"generate", "uniform", "--n", "5", "--seed", "1", "-o", scratch.path("no/such/dir/sites.balls")}}) {
    std::string command_line;
    for (const std::string& a : args) command_line += a + ' ';
    CAPTURE(command_line);
    const Cli_result r = run(args);
    CHECK(r.code == EXIT_BAD_INPUT);
    CHECK(r.out.empty());
    CHECK(r.err.find("apollonius3d") == 0);
    CHECK(std::distance(fs::directory_iterator(scratch.dir), fs::directory_iterator()) == 0);
  }
}

TEST_CASE("generate -o writes the same text as to standard output") {
  Scratch scratch;
  const std::string out = scratch.path("sites.balls");
  const Cli_result to_stdout = run({"generate", "cospherical", "--n", "12", "--seed", "3"});
  CHECK(run({"generate", "cospherical", "--n", "12", "--seed", "3", "-o", out}).code == EXIT_OK);
  CHECK(read_file(out) == to_stdout.out);
}

TEST_CASE("diagram: the whole diagram as JSON or topology, the same for every thread count") {
  Scratch scratch;
  // ANO1_0CONNECT: four vertices, a cell with no vertex, a closed edge that is a hole in a face.
  const std::string input = std::string(APOLLONIUS_TEST_DATA) + "/vdrc/ANO1_0CONNECT.txt";
  const Cli_result json = run({"diagram", input});
  REQUIRE(json.code == EXIT_OK);
  CHECK(json.out.find("\"format\": \"apollonius3d-diagram\"") != std::string::npos);
  CHECK(json.out.find("{\"id\":0,\"sites\":[0,1,2],\"ends\":[],\"curve\":\"ellipse\"}") != std::string::npos);
  CHECK(json.out.find("{\"site\":2,\"faces\":[1,6],\"bounded\":true}") != std::string::npos);
  CHECK(run({"diagram", input, "--threads", "2"}).out == json.out);

  const Cli_result topology = run({"diagram", input, "--format", "topology"});
  REQUIRE(topology.code == EXIT_OK);
  CHECK(topology.out.find("\"quadrisectors\"") != std::string::npos);
  CHECK(topology.out.find("[0,1,2]") != std::string::npos);

  const Cli_result stats = run({"diagram", input, "--stats"});
  CHECK(stats.err.find("nested_pairs") != std::string::npos);

  // Random balls: every thread count gives the same bytes.
  const std::string random = scratch.path("uniform.balls");
  REQUIRE(run({"generate", "uniform", "--n", "300", "--seed", "7", "-o", random}).code == EXIT_OK);
  const std::string one = run({"diagram", random, "--threads", "1"}).out;
  CHECK(one.find("\"faces\"") != std::string::npos);
  CHECK(run({"diagram", random, "--threads", "2"}).out == one);
  CHECK(run({"diagram", random, "--threads", "3"}).out == one);
  CHECK(run({"diagram", random, "--stats"}).err.find("lifted fallback") == std::string::npos);

  // Balls tangent to one circle: the octree passes its box budget, and --stats says so; the diagram is the
  // same for every thread count.
  const std::string tangent = scratch.path("circle-tangent.balls");
  REQUIRE(run({"generate", "circle-tangent", "--n", "200", "--seed", "2", "-o", tangent}).code == EXIT_OK);
  const Cli_result fallback = run({"diagram", tangent, "--stats"});
  REQUIRE(fallback.code == EXIT_OK);
  CHECK(fallback.err.find("lifted fallback\nlifted_reason box_budget") != std::string::npos);
  CHECK(run({"diagram", tangent, "--threads", "2"}).out == run({"diagram", tangent}).out);

  // Bad input: file:line and reason, exit 2, no output file.
  const std::string bad = scratch.write("bad.balls", "0 0 0 1\n1 2 x 1\n");
  const std::string out = scratch.path("bad.json");
  const Cli_result failed = run({"diagram", bad, "-o", out});
  CHECK(failed.code == EXIT_BAD_INPUT);
  CHECK(failed.err.find("bad.balls:2:") != std::string::npos);
  CHECK_FALSE(fs::exists(out));
  CHECK(run({"diagram", input, "--format", "xml"}).code == EXIT_BAD_INPUT);
}

TEST_CASE("a command's results are freed when it returns, unless the process ends right after") {
  struct Counted {
    int* destroyed;
    explicit Counted(int* d) : destroyed(d) {}
    Counted(Counted&& other) noexcept : destroyed(std::exchange(other.destroyed, nullptr)) {}
    ~Counted() {
      if (destroyed != nullptr) ++*destroyed;
    }
  };
  int destroyed = 0;
  REQUIRE_FALSE(process_ends_after_command());  // a test runs commands in turn
  release_or_keep_until_exit(Counted(&destroyed));
  CHECK(destroyed == 1);
  set_process_ends_after_command(true);  // as main sets it
  release_or_keep_until_exit(Counted(&destroyed));
  set_process_ends_after_command(false);
  CHECK(destroyed == 1);  // kept, and still reachable (no leak report under ASan)
}
