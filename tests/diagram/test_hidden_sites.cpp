// classify_hidden_sites (site_set.h) against every pair tested exactly: the same hidden sites, each with
// the preferred hiding site (an identical earlier site, else the smallest index that contains it).
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <random>

#include "diagram/site_set.h"
#include "predicates/is_hidden.h"
#include "predicates/kernels.h"
#include "reference/site_generators.h"

using namespace apollonius;

namespace {

// The reference: all n^2 ordered pairs, with no search structure.
std::vector<Hidden_site> every_pair(const std::vector<Site>& sites) {
  std::vector<Hidden_site> hidden;
  for (Site_index i = 0; i < sites.size(); ++i) {
    std::optional<Hidden_site> found;
    for (Site_index j = 0; j < sites.size(); ++j) {
      if (j == i || !is_hidden(sites[i], i, sites[j], j)) continue;
      const bool duplicate = sites[i] == sites[j];
      if (!found || (duplicate && !found->duplicate) || (duplicate == found->duplicate && j < found->hidden_by))
        found = Hidden_site{i, j, duplicate};
    }
    if (found) hidden.push_back(*found);
  }
  return hidden;
}

void check_against_every_pair(const std::vector<Site>& sites) {
  const std::vector<Hidden_site> expected = every_pair(sites);
  for (const int threads : {1, 2}) {
    CAPTURE(threads);
    const std::vector<Hidden_site> got = classify_hidden_sites<Certified_kernel>(sites, nullptr, threads);
    REQUIRE(got.size() == expected.size());
    for (std::size_t k = 0; k < got.size(); ++k) {
      CAPTURE(k);
      CHECK(got[k].site == expected[k].site);
      CHECK(got[k].hidden_by == expected[k].hidden_by);
      CHECK(got[k].duplicate == expected[k].duplicate);
    }
  }
}

// Balls nested around a few centres, with duplicates, internal tangencies (integer data, so that
// |c_i - c_j| = w_j - w_i holds exactly for Pythagorean offsets) and one ball far heavier than the rest.
std::vector<Site> nested_cluster(std::mt19937_64& random) {
  std::uniform_int_distribution<int> count(2, 150), coordinate(-6, 6), weight(0, 6), choice(0, 9);
  std::vector<Site> sites;
  const int n = count(random);
  for (int k = 0; k < n; ++k) {
    const int c = choice(random);
    if (c == 0 && !sites.empty()) {
      sites.push_back(sites[std::uniform_int_distribution<std::size_t>(0, sites.size() - 1)(random)]);
    } else if (c == 1 && !sites.empty()) {  // tangent inside: offset (3, 4, 0), weight 5 less
      const Site s = sites[std::uniform_int_distribution<std::size_t>(0, sites.size() - 1)(random)];
      sites.push_back({s.x + 3, s.y + 4, s.z, s.w - 5});
    } else if (c == 2) {
      sites.push_back({0.5 * coordinate(random), 0, 0, 1000.0 * weight(random)});
    } else {
      sites.push_back({1.0 * coordinate(random), 1.0 * coordinate(random), 1.0 * coordinate(random), 0.5 * weight(random) - 1});
    }
  }
  return sites;
}

}  // namespace

TEST_CASE("hidden sites equal every pair's test on the generated families") {
  int inputs = 0;
  for (const Site_family_description& family : kSiteFamilies)
    for (std::uint64_t seed = 1; seed <= 40; ++seed) {
      const std::size_t n = 2 + seed * 7 % 180;
      CAPTURE(family.name);
      CAPTURE(seed);
      CAPTURE(n);
      check_against_every_pair(generate_sites(family.family, n, seed));
      ++inputs;
    }
  CHECK(inputs >= 40 * 20);
}

TEST_CASE("hidden sites equal every pair's test on nested clusters, duplicates and internal tangencies") {
  std::mt19937_64 random(20261128);
  std::size_t hidden = 0, duplicates = 0;
  for (int trial = 0; trial < 1500; ++trial) {
    const std::vector<Site> sites = nested_cluster(random);
    CAPTURE(trial);
    check_against_every_pair(sites);
    for (const Hidden_site& h : classify_hidden_sites<Certified_kernel>(sites)) ++hidden, duplicates += h.duplicate;
  }
  CHECK(hidden > 10000);
  CHECK(duplicates > 1000);
}

TEST_CASE("hidden sites in parallel: several chunks of sites, the same verdicts") {
  // Nested clusters side by side, about 3,000 sites: the parallel classification's chunks are 1,024 sites.
  std::mt19937_64 random(20261130);
  std::vector<Site> sites;
  for (int cluster = 0; sites.size() < 3000; ++cluster) {
    std::vector<Site> more = nested_cluster(random);
    for (Site& s : more) s.x += 40.0 * cluster;
    sites.insert(sites.end(), more.begin(), more.end());
  }
  check_against_every_pair(sites);
  CHECK(classify_hidden_sites<Certified_kernel>(sites).size() > 1000);
}

TEST_CASE("hidden sites: extremes of the double range, a dozen identical balls, one ball holding all") {
  const double big = std::numeric_limits<double>::max(), tiny = std::numeric_limits<double>::denorm_min();
  // Centres at both ends of the range: the tree's extents overflow.
  check_against_every_pair({{-big, 0, 0, 1}, {big, 0, 0, 1}, {0, -big, 0, big}, {0, 0, 0, 1}, {tiny, tiny, tiny, 0},
                            {0, 0, big, -big}, {big, big, big, big}, {-big, -big, -big, 0}, {0, 0, 0, 0}, {tiny, 0, 0, 0}});
  std::vector<Site> same(13, Site{1, 2, 3, 4});
  check_against_every_pair(same);
  CHECK(classify_hidden_sites<Certified_kernel>(same).size() == 12);
  std::vector<Site> inside;
  for (int k = 0; k < 400; ++k) inside.push_back({std::cos(k) * 10, std::sin(k) * 10, 0.001 * k, 0.5});
  inside.push_back({0, 0, 0, 1e6});
  check_against_every_pair(inside);
  CHECK(classify_hidden_sites<Certified_kernel>(inside).size() == 400);
}
