// apollonius3d centroidal: the final sites and the history written atomically, a run that converges, and
// bad parameters (masses not summing to 1, a negative mass, the wrong number of masses, a domain that does
// not contain the sites, a degenerate domain or tolerance): FILE:LINE: reason or a usage line, exit 2, and
// no output file, not even the history.
#include <doctest/doctest.h>

#include <filesystem>
#include <sstream>

#include "io/read_sites.h"
#include "support/cli_helpers.h"

using namespace apollonius;
using namespace apollonius::testing;
namespace fs = std::filesystem;

namespace {

const std::string kSites = "# four sites\n0.2 0.2 0.2 0\n0.8 0.3 0.2 0\n0.3 0.7 0.4 0\n0.5 0.5 0.8 0\n";
const std::string kMasses = "0.25\n0.25\n# a comment\n0.3\n0.2\n";

}  // namespace

TEST_CASE("centroidal writes the final sites and one history row per iteration, atomically") {
  Scratch scratch;
  const std::string example = std::string(APOLLONIUS_EXAMPLES) + "/centroidal6/";
  const std::string sites = scratch.write("sites.txt", kSites), masses = scratch.write("masses.txt", kMasses);
  const std::string out = scratch.path("out.txt"), history = scratch.path("history.csv");
  const Cli_result r = run({"centroidal", example + "sites.txt", "--domain", "0", "0", "0", "1", "1", "1", "--masses",
                            example + "masses.txt", "--tolerance", "1e-4", "-o", out, "--history", history});
  CHECK(r.code == EXIT_OK);
  CHECK(r.out.empty());
  const Site_input final_sites = read_sites(out, {});
  REQUIRE(final_sites.sites.size() == 6);
  CHECK(scratch.read("out.txt").find("# apollonius3d centroidal: converged") == 0);
  std::istringstream rows(scratch.read("history.csv"));
  std::string line;
  std::getline(rows, line);
  CHECK(line.rfind("iteration,E4,max_relative_mass_error,largest_site_move,seconds", 0) == 0);
  int count = 0;
  while (std::getline(rows, line)) CHECK(line.rfind(std::to_string(++count) + ",", 0) == 0);
  CHECK(count >= 1);
  CHECK(scratch.file_count() == 4);  // the inputs and the two outputs, no temporary left
}

TEST_CASE("centroidal: not converged within --max-iterations is exit 1, with the state reached written") {
  Scratch scratch;
  const std::string sites = scratch.write("sites.txt", kSites), masses = scratch.write("masses.txt", kMasses);
  const Cli_result r = run({"centroidal", sites, "--domain", "0", "0", "0", "1", "1", "1", "--masses", masses,
                            "--tolerance", "1e-9", "--max-iterations", "1"});
  CHECK(r.code == EXIT_DISCREPANCIES);
  CHECK(r.out.find("not converged") != std::string::npos);
  CHECK(r.err.find("not converged within 1 iterations") != std::string::npos);
}

TEST_CASE("centroidal: bad parameters give FILE:LINE: reason, exit 2, and no output file") {
  Scratch scratch;
  const std::string sites = scratch.write("sites.txt", kSites);
  struct Case {
    std::string what;
    std::string masses;  // the content of masses.txt
    std::vector<std::string> domain;
    std::string expected_message;
  };
  const std::vector<std::string> unit = {"0", "0", "0", "1", "1", "1"};
  const std::vector<Case> cases = {
      {"masses not summing to 1", "0.25\n0.25\n0.3\n0.3\n", unit, "masses.txt: the masses sum to 1.1"},
      {"a negative mass", "0.25\n0.25\n0.7\n-0.2\n", unit, "masses.txt:4: a mass must be positive, not -0.2"},
      {"a zero mass", "0.5\n0\n0.3\n0.2\n", unit, "masses.txt:2: a mass must be positive, not 0"},
      {"too few masses", "0.5\n0.5\n", unit, "masses.txt: 2 masses for 4 sites"},
      {"too many masses", "0.2\n0.2\n0.2\n0.2\n0.2\n", unit, "masses.txt:5: more masses than the 4 sites"},
      {"a mass that is no number", "0.25\n0.25\nabc\n0.25\n", unit, "masses.txt:3:"},
      {"two masses on a line", "0.25 0.25\n0.25\n0.25\n", unit, "masses.txt:1: expected 1 field"},
      {"a domain that does not contain the sites", kMasses, {"0", "0", "0", "0.6", "1", "1"},
       "sites.txt:3: site 1: the site (0.8"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.what);
    const std::string masses = scratch.write("masses.txt", c.masses);
    const std::string out = scratch.path("out.txt"), history = scratch.path("history.csv");
    std::vector<std::string> args = {"centroidal", sites, "--masses", masses, "-o", out, "--history", history, "--domain"};
    args.insert(args.end(), c.domain.begin(), c.domain.end());
    const Cli_result r = run(args);
    CHECK(r.code == EXIT_BAD_INPUT);
    CAPTURE(r.err);
    CHECK(r.err.find(c.expected_message) != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK_FALSE(fs::exists(out));
    CHECK_FALSE(fs::exists(history));
    CHECK(scratch.file_count() == 2);  // sites.txt and masses.txt: no temporary left
  }
}

TEST_CASE("centroidal: usage errors name the option, exit 2, no output") {
  Scratch scratch;
  const std::string sites = scratch.write("sites.txt", kSites);
  const std::string out = scratch.path("out.txt");
  for (const auto& [args, message] : std::vector<std::pair<std::vector<std::string>, std::string>>{
           {{"centroidal", sites, "-o", out}, "--domain is required"},
           {{"centroidal", sites, "-o", out, "--domain", "0", "0", "0", "1", "1"}, "--domain"},
           {{"centroidal", sites, "-o", out, "--domain", "0", "0", "0", "1", "0", "1"}, "X0 < X1, Y0 < Y1 and Z0 < Z1"},
           {{"centroidal", sites, "-o", out, "--domain", "0", "0", "0", "1", "1", "nan"}, "needs a finite number"},
           {{"centroidal", sites, "-o", out, "--domain", "0", "0", "0", "1", "1", "1", "--tolerance", "0"},
            "--tolerance: must lie in [1e-10, 0.5]"},
           {{"centroidal", sites, "-o", out, "--domain", "0", "0", "0", "1", "1", "1", "--median-tolerance", "0"},
            "--median-tolerance: must lie in [1e-10, 0.5]"},
           {{"centroidal", sites, "-o", out, "--domain", "0", "0", "0", "1", "1", "1", "--max-iterations", "0"},
            "--max-iterations"}}) {
    std::string command_line;
    for (const std::string& a : args) command_line += a + ' ';
    CAPTURE(command_line);
    const Cli_result r = run(args);
    CHECK(r.code == EXIT_BAD_INPUT);
    CHECK(r.err.find(message) != std::string::npos);
    CHECK_FALSE(fs::exists(out));
  }
}

TEST_CASE("the binary: exit 2 and no output for masses that do not sum to 1") {
  Scratch scratch;
  const std::string sites = scratch.write("sites.txt", kSites);
  const std::string masses = scratch.write("masses.txt", "0.1\n0.1\n0.1\n0.1\n");
  const std::string out = scratch.path("out.txt");
  const auto [code, output] = shell(std::string(APOLLONIUS_BINARY) + " centroidal " + sites +
                                    " --domain 0 0 0 1 1 1 --masses " + masses + " -o " + out + " 2>&1");
  CHECK(code == 2);
  CHECK(output.find("the masses sum to 0.4") != std::string::npos);
  CHECK_FALSE(fs::exists(out));
}
