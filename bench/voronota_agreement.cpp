// Compares the exact diagram of a balls file with Voronota's `calculate-vertices` output for it: how many
// vertices each has, how many match (same sites; for a tie set of 5 or more, any 4 of them), and the
// largest coordinate difference. Usage: voronota_agreement BALLS VORONOTA_OUTPUT
#include <algorithm>
#include <cstdio>
#include <fstream>

#include "claimed_vertices.h"
#include "io/input_error.h"
#include "io/read_sites.h"
#include "octree_diagram.h"

int main(int argc, char** argv) {
  using namespace apollonius;
  if (argc != 3) {
    std::fprintf(stderr, "usage: voronota_agreement BALLS VORONOTA_OUTPUT\n");
    return 2;
  }
  try {
    const Diagram diagram = octree_diagram(read_sites(argv[1], {}).sites);
    std::ifstream in(argv[2]);
    if (!in) throw Input_error(argv[2], 0, "cannot open");
    const std::vector<Claimed_vertex> claims = read_claimed_vertices(in, argv[2]);
    const Vertex_list_matching m = match_claims(diagram, claims);
    double worst = 0;
    for (const auto& match : m.matches) worst = std::max(worst, match.max_abs_error);
    std::printf("%s: exact %zu, voronota %zu, matched %zu, voronota only %zu, exact only %zu, max |difference| %.3g\n",
                argv[1], diagram.vertices.size(), claims.size(), m.matches.size(), m.unmatched_claims.size(),
                m.vertices_without_claim.size(), worst);
    return m.unmatched_claims.empty() && m.vertices_without_claim.empty() ? 0 : 1;
  } catch (const Input_error& e) {
    std::fprintf(stderr, "voronota_agreement: %s\n", e.what());
    return 2;
  }
}
