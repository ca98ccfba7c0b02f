// exact_quadruple_line (from point-interval minors where they are exact) equals quadruple_line<Exact> on
// every quadruple of every family: the grid families take the interval path, the others fall back.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <string>

#include "predicates/exact_quadruple_line.h"
#include "reference/site_generators.h"

using namespace apollonius;

namespace {

bool same_line(const Quadruple_line<Exact>& x, const Quadruple_line<Exact>& y) {
  if (x.pivot != y.pivot || x.n != y.n) return false;
  if (x.pivot < 0) return true;  // rank deficient: nothing else is formed
  return x.Q == y.Q && x.A == y.A && x.B == y.B && x.C == y.C && x.discriminant == y.discriminant;
}

// Whether the minors are all doubles: the interval path's case.
bool is_double(const Exact& x) {
  const double d = CGAL::to_double(x);
  return std::isfinite(d) && Exact(d) == x;
}
bool minors_are_doubles(const Quadruple_line<Exact>& line) {
  for (int j = 0; j < 4; ++j)
    if (!is_double(line.n[j]) || (line.pivot >= 0 && !is_double(line.Q[j]))) return false;
  return true;
}

}  // namespace

TEST_CASE("exact_quadruple_line equals quadruple_line<Exact> on every family") {
  std::size_t checked = 0, from_doubles = 0, rank_deficient = 0;
  for (const Site_family_description& family : kSiteFamilies) {
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
      const std::vector<Site> sites = generate_sites(family.family, 12, seed);
      std::mt19937_64 random(seed);
      std::vector<std::size_t> order(sites.size());
      std::iota(order.begin(), order.end(), std::size_t{0});
      for (int trial = 0; trial < 40; ++trial) {
        // Four distinct sites; one in ten quadruples repeats one (rank deficient).
        std::shuffle(order.begin(), order.end(), random);
        const std::size_t last = trial % 10 == 0 ? order[0] : order[3];
        const std::array<Site, 4> quadruple = {sites[order[0]], sites[order[1]], sites[order[2]], sites[last]};
        const Quadruple_line<Exact> expected = quadruple_line<Exact>(quadruple);
        const Quadruple_line<Exact> line = exact_quadruple_line(quadruple);
        INFO("family ", std::string(family.name), ", seed ", seed, ", trial ", trial);
        CHECK(same_line(line, expected));
        ++checked;
        from_doubles += minors_are_doubles(expected);
        rank_deficient += expected.pivot < 0;
      }
    }
  }
  MESSAGE(checked, " quadruples, ", from_doubles, " with minors that are doubles, ", rank_deficient, " rank deficient");
  // Both paths, and rank-deficient lines (repeated sites), were exercised.
  CHECK(from_doubles > checked / 4);
  CHECK(from_doubles < checked);
  CHECK(rank_deficient > 0);
}
