// Site_tree (site_tree.h): its nearest sites against a scan of every site with the same floating formula,
// sorted by (d, index), on every generator family, at points inside, beside and far outside the sites, for
// every k; and the tree's invariant (each node's box and heaviest weight bound its sites).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "diagram/site_tree.h"
#include "reference/site_generators.h"

using namespace apollonius;

namespace {

double floating_d(const std::array<double, 3>& x, const Site& s) {
  const double dx = x[0] - s.x, dy = x[1] - s.y, dz = x[2] - s.z;
  const double d = std::sqrt(dx * dx + dy * dy + dz * dz) - s.w;
  return std::isnan(d) ? std::numeric_limits<double>::infinity() : d;
}

// The k sites of least d at x among `subset`, by a plain sort.
std::vector<Site_index> scanned_nearest(const std::vector<Site>& sites, const std::vector<Site_index>& subset,
                                        const std::array<double, 3>& x, std::size_t k) {
  std::vector<std::pair<double, Site_index>> all;
  for (Site_index s : subset) all.emplace_back(floating_d(x, sites[s]), s);
  std::sort(all.begin(), all.end());
  std::vector<Site_index> nearest;
  for (std::size_t i = 0; i < std::min(k, all.size()); ++i) nearest.push_back(all[i].second);
  return nearest;
}

}  // namespace

TEST_CASE("Site_tree's nearest sites equal a scan of every site, on every family") {
  std::size_t queries = 0;
  for (const std::string& name : site_family_names()) {
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
      const std::size_t n = seed % 3 == 0 ? 9 : 40 * seed;
      const std::vector<Site> sites = generate_sites(site_family_from_name(name), n, seed);
      std::mt19937_64 random(seed);
      // A subset, as the octree passes only the sites that are not hidden.
      std::vector<Site_index> subset;
      for (Site_index s = 0; s < sites.size(); ++s)
        if (random() % 4 != 0) subset.push_back(s);
      const Site_tree tree(sites, subset);
      std::array<double, 3> lo{}, hi{};
      for (int a = 0; a < 3; ++a) lo[a] = std::numeric_limits<double>::infinity(), hi[a] = -lo[a];
      for (const Site& s : sites)
        for (int a = 0; a < 3; ++a) {
          lo[a] = std::min(lo[a], centre_coordinate(s, a)), hi[a] = std::max(hi[a], centre_coordinate(s, a));
        }
      for (int q = 0; q < 60; ++q) {
        std::array<double, 3> x{};
        for (int a = 0; a < 3; ++a) {
          const double t = std::uniform_real_distribution<double>(-0.5, 1.5)(random);
          x[a] = q % 10 == 0 ? (q % 20 == 0 ? 1e6 : -1e3) * (hi[a] - lo[a] + 1)  // far outside
                 : q % 7 == 0 && !sites.empty() ? centre_coordinate(sites[q % sites.size()], a)  // at a centre
                                                 : lo[a] / 2 + hi[a] / 2 + t * (hi[a] / 2 - lo[a] / 2);
          if (!std::isfinite(x[a])) x[a] = lo[a];
        }
        for (std::size_t k = 1; k <= Site_tree::kMostNearest; ++k) {
          std::array<Site_index, Site_tree::kMostNearest> found{};
          const std::size_t count = tree.nearest(x, k, found.data());
          const std::vector<Site_index> expected = scanned_nearest(sites, subset, x, k);
          INFO("family ", name, ", seed ", seed, ", query ", q, ", k ", k);
          REQUIRE(count == expected.size());
          CHECK(std::equal(expected.begin(), expected.end(), found.begin()));
          ++queries;
        }
      }
    }
  }
  CHECK(queries > 40000);
}

TEST_CASE("Site_tree: no sites, fewer sites than asked, and its nodes bound their sites") {
  const std::vector<Site> sites = generate_sites(Site_family::uniform, 500, 3);
  Site_index none[Site_tree::kMostNearest];
  CHECK(Site_tree(sites, {}).nearest({0, 0, 0}, 4, none) == 0);
  const Site_tree three(sites, {7, 3, 11});
  Site_index found[Site_tree::kMostNearest];
  CHECK(three.nearest({0, 0, 0}, 8, found) == 3);
  CHECK(three.nearest({0, 0, 0}, 0, found) == 0);

  std::vector<Site_index> all(sites.size());
  for (Site_index s = 0; s < sites.size(); ++s) all[s] = s;
  const Site_tree tree(sites, all);
  std::vector<Site_index> order = tree.order();
  std::sort(order.begin(), order.end());
  CHECK(order == all);  // a permutation of the subset
  for (std::size_t k = 0; k < tree.nodes().size(); ++k) {
    const Site_tree::Node& node = tree.nodes()[k];
    REQUIRE(node.begin < node.end);
    for (std::size_t m = node.begin; m < node.end; ++m) {
      const Site& s = sites[tree.order()[m]];
      for (int a = 0; a < 3; ++a) {
        const double c = centre_coordinate(s, a);
        CHECK((node.lo[a] <= c && c <= node.hi[a]));
      }
      CHECK(s.w <= node.heaviest);
    }
    if (node.right != 0) {
      CHECK(tree.nodes()[k + 1].begin == node.begin);
      CHECK(tree.nodes()[k + 1].end == tree.nodes()[node.right].begin);
      CHECK(tree.nodes()[node.right].end == node.end);
    }
  }
}
