// Agreement with Voronota (Debian package voronota, a declared dependency) where it is right: on a generic
// protein it must give the same quadruples, with coordinates within 1e-9.
#include <doctest/doctest.h>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "brute_force_diagram.h"
#include "claimed_vertices.h"
#include "diagram_checks.h"
#include "io/read_sites.h"

using namespace apollonius;
using namespace apollonius::testing;

namespace {

// Output of `voronota calculate-vertices < balls_file`.
std::string run_voronota(const std::string& balls_file) {
  const std::string command = "voronota calculate-vertices < '" + balls_file + "'";
  FILE* pipe = popen(command.c_str(), "r");
  REQUIRE(pipe != nullptr);
  std::string output;
  char buffer[4096];
  for (std::size_t n; (n = fread(buffer, 1, sizeof buffer, pipe)) > 0;) output.append(buffer, n);
  REQUIRE(pclose(pipe) == 0);
  return output;
}

}  // namespace

TEST_CASE("pept: the same quadruples as voronota calculate-vertices, coordinates within 1e-9") {
  const std::string balls = std::string(APOLLONIUS_TEST_DATA) + "/pept.balls";
  const std::vector<Site> sites = read_sites(balls, {}).sites;
  REQUIRE(sites.size() == 107);
  const Diagram d = brute_force_diagram(sites);
  validate_diagram(d, sites);

  std::istringstream voronota_output(run_voronota(balls));
  const std::vector<Claimed_vertex> claims = read_claimed_vertices(voronota_output, "voronota");
  const Vertex_list_matching m = match_claims(d, claims);
  CHECK(m.unmatched_claims.empty());
  CHECK(m.vertices_without_claim.empty());
  CHECK(claims.size() == d.vertices.size());
  double worst = 0;
  for (const auto& match : m.matches) worst = std::max(worst, match.max_abs_error);
  MESSAGE("pept: " << d.vertices.size() << " vertices, voronota " << claims.size() << ", max |difference| " << worst);
  CHECK(worst < 1e-9);
  for (const Diagram_vertex& v : d.vertices) CHECK(v.tie_set.size() == 4);  // generic: no surplus quadruples
}

TEST_CASE("vdrc ANO3_3CONNECT: Voronota reports only some of the 8 vertices, all of them real") {
  const std::string file = std::string(APOLLONIUS_TEST_DATA) + "/vdrc/ANO3_3CONNECT.txt";
  const std::vector<Site> sites = read_sites(file, {}).sites;
  const Diagram d = brute_force_diagram(sites);
  REQUIRE(d.vertices.size() == 8);
  // Voronota reads balls text: write the sites as 'x y z r'.
  const std::string balls = "ano3.balls";
  {
    std::ofstream out(balls);
    out.precision(17);
    for (const Site& s : sites) out << s.x << ' ' << s.y << ' ' << s.z << ' ' << s.w << '\n';
  }
  std::istringstream voronota_output(run_voronota(balls));
  const std::vector<Claimed_vertex> claims = read_claimed_vertices(voronota_output, "voronota");
  const Vertex_list_matching m = match_claims(d, claims);
  MESSAGE("ANO3_3CONNECT: exact " << d.vertices.size() << ", voronota " << claims.size() << ", missed by voronota "
                                  << m.vertices_without_claim.size());
  CHECK(m.unmatched_claims.empty());
  CHECK(m.vertices_without_claim.size() == d.vertices.size() - claims.size());
  CHECK(claims.size() < d.vertices.size());
  std::remove(balls.c_str());
}
