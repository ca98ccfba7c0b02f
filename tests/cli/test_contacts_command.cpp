// apollonius3d contacts: Voronota's text layout ('i i sas' before 'i j area', ascending), JSON with every
// error estimate, the volumes file, a hidden ball left out, and bad parameters or input: a usage line or
// FILE:LINE: reason, exit 2, and no output file.
#include <doctest/doctest.h>

#include <cmath>
#include <sstream>

#include <nlohmann/json.hpp>

#include "support/cli_helpers.h"

using namespace apollonius;
using namespace apollonius::testing;

namespace {

// Balls 0 and 1 touch within the probe, ball 2 is far away, ball 3 lies inside ball 0.
const std::string kBalls = "0 0 0 1\n2 0 0 1\n20 0 0 1.5\n0.2 0 0 0.5\n";

}  // namespace

TEST_CASE("contacts writes Voronota's layout, the volumes and the JSON with errors") {
  Scratch scratch;
  const std::string balls = scratch.write("balls.txt", kBalls);
  const std::string out = scratch.path("contacts.txt"), volumes = scratch.path("volumes.txt");
  const Cli_result r = run({"contacts", balls, "-o", out, "--volumes-output", volumes});
  CHECK(r.code == EXIT_OK);
  std::istringstream lines(scratch.read("contacts.txt"));
  const std::pair<int, int> expected[] = {{0, 0}, {0, 1}, {1, 1}, {2, 2}};
  const double pi = 3.14159265358979323846, R = 2.4;
  for (const auto& [a, b] : expected) {
    int i, j;
    double area;
    REQUIRE(static_cast<bool>(lines >> i >> j >> area));
    CHECK(i == a);
    CHECK(j == b);
    if (a != b) CHECK(std::fabs(area - pi * (R * R - 1)) < 1e-5);  // the disc of the bisector plane
    if (a == 2) CHECK(std::fabs(area - 4 * pi * 2.9 * 2.9) < 1e-5);
  }
  int extra;
  CHECK(!static_cast<bool>(lines >> extra));
  std::istringstream volume_lines(scratch.read("volumes.txt"));
  int site, count = 0;
  double volume;
  while (volume_lines >> site >> volume) CHECK(site == count++);
  CHECK(count == 3);  // not the hidden ball 3

  const Cli_result json = run({"contacts", balls, "--format", "json", "--probe", "0.5", "--tolerance", "1e-8"});
  CHECK(json.code == EXIT_OK);
  const nlohmann::json document = nlohmann::json::parse(json.out);
  CHECK(document["format"] == "apollonius3d-contacts");
  CHECK(document["probe"] == 0.5);
  REQUIRE(document["contacts"].size() == 1);
  CHECK(std::fabs(document["contacts"][0]["area"].get<double>() - pi * (1.5 * 1.5 - 1)) <=
        document["contacts"][0]["error"].get<double>() + 1e-12);
  REQUIRE(document["cells"].size() == 4);
  CHECK(document["cells"][3]["volume"] == 0);
  REQUIRE(document["hidden_sites"].size() == 1);
  CHECK(document["hidden_sites"][0]["site"] == 3);
}

TEST_CASE("contacts: bad parameters and input are exit 2 with no output file") {
  Scratch scratch;
  const std::string balls = scratch.write("balls.txt", kBalls), bad = scratch.write("bad.txt", "0 0 0 1\n1 2 nan 1\n");
  const std::string out = scratch.path("out.txt");
  for (const std::vector<std::string>& arguments :
       {std::vector<std::string>{"contacts", balls, "--probe", "-1", "-o", out},
        {"contacts", balls, "--probe", "inf", "-o", out},
        {"contacts", balls, "--tolerance", "0", "-o", out},
        {"contacts", balls, "--format", "pdb", "-o", out},
        {"contacts", bad, "-o", out}}) {
    const Cli_result r = run(arguments);
    CHECK(r.code == EXIT_BAD_INPUT);
    CHECK(!r.err.empty());
    CHECK(scratch.file_count() == 2);
  }
  CHECK(run({"contacts", bad}).err.find("bad.txt:2:") != std::string::npos);
}

TEST_CASE("regression: contacts_hang_for_balls_2e-16_apart, exit 2 naming the balls, not a hang or exit 3") {
  Scratch scratch;
  const std::string input = std::string(APOLLONIUS_TEST_DATA) + "/regression/contacts_hang_for_balls_2e-16_apart.balls";
  const std::string out = scratch.path("out.txt");
  for (const char* probe : {"0", "0.5", "1.4"}) {
    CAPTURE(probe);
    const Cli_result r = run({"contacts", input, "--probe", probe, "-o", out});
    CHECK(r.code == EXIT_BAD_INPUT);
    CHECK(r.err.find("contacts_hang_for_balls_2e-16_apart.balls:5:") != std::string::npos);
    CHECK(r.err.find("balls 0 and 1 lie within 1e-4") != std::string::npos);
    CHECK(scratch.file_count() == 0);
  }
}
