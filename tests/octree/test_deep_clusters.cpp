// deep_clusters.h: which inputs count as deep (the octree would refine through many binades more than the
// sites' spacing needs), which do not, and no overflow at the ends of the double range.
#include <doctest/doctest.h>

#include <cmath>
#include <numeric>
#include <vector>

#include "diagram/site_set.h"
#include "octree/deep_clusters.h"
#include "predicates/kernels.h"
#include "reference/site_generators.h"

using namespace apollonius;

namespace {

std::vector<Site_index> all_of(const std::vector<Site>& sites) {
  std::vector<Site_index> active(sites.size());
  std::iota(active.begin(), active.end(), Site_index{0});
  return active;
}

// The sites the octree works on: no hidden one, so no two with one centre.
std::vector<Site_index> active_of(const std::vector<Site>& sites) {
  return active_sites(sites.size(), classify_hidden_sites<Certified_kernel>(sites));
}

}  // namespace

TEST_CASE("random balls, lattices, near-lattices and scaled inputs are not deep") {
  for (const Site_family family : {Site_family::uniform, Site_family::equal_weights, Site_family::lattice,
                                   Site_family::lattice_noise, Site_family::nested, Site_family::tangent,
                                   Site_family::scaled_up, Site_family::scaled_down, Site_family::coplanar}) {
    for (const std::size_t n : {std::size_t{100}, std::size_t{3000}}) {
      CAPTURE(static_cast<int>(family));
      CAPTURE(n);
      const std::vector<Site> sites = generate_sites(family, n, 11);
      CHECK(deep_pairs(sites, active_of(sites), sites.size()) == 0);
      CHECK_FALSE(has_deep_clusters(sites, active_of(sites)));
    }
  }
}

TEST_CASE("a cluster beside a far ball, and sites from 1e-260 to 1e265, are deep") {
  std::vector<Site> cluster;  // 512 balls 1 apart, an extent of 7, radii 0.5 to 0.875
  for (int x = 0; x < 8; ++x)
    for (int y = 0; y < 8; ++y)
      for (int z = 0; z < 8; ++z) cluster.push_back({double(x), double(y), double(z), 0.5 + (x + y + z) % 4 / 8.0});
  CHECK_FALSE(has_deep_clusters(cluster, all_of(cluster)));
  // Spacing 1: a ball 1e6 away keeps the pairs within 32 binades of the extent, 1e12 not.
  cluster.push_back({1e6, 0, 0, 1});
  CHECK_FALSE(has_deep_clusters(cluster, all_of(cluster)));
  cluster.back() = {0, -1e12, 0, 1};
  CHECK(deep_pairs(cluster, all_of(cluster), cluster.size()) == 511);  // every consecutive pair of the cluster
  cluster.back() = {0, 0, 1.7e308, 1};  // an extent near the largest double: halves, no overflow
  CHECK(has_deep_clusters(cluster, all_of(cluster)));
  const std::vector<Site> wide = generate_sites(Site_family::wide_range, 1000, 13);
  CHECK(has_deep_clusters(wide, all_of(wide)));
  // Only the active sites count: without the far ball the cluster is not deep.
  std::vector<Site_index> without_far = all_of(cluster);
  without_far.pop_back();
  CHECK_FALSE(has_deep_clusters(cluster, without_far));
}

TEST_CASE("fewer than two sites, equal centres and an empty extent are not deep") {
  const std::vector<Site> one = {{1, 2, 3, 1}};
  CHECK(deep_pairs(one, all_of(one), 3) == 0);
  const std::vector<Site> same_centre = {{1, 2, 3, 1}, {1, 2, 3, 2}, {1, 2, 3, 3}};
  CHECK(deep_pairs(same_centre, all_of(same_centre), 3) == 0);
  const std::vector<Site> ends = {{-1.7e308, -1.7e308, -1.7e308, 0}, {1.7e308, 1.7e308, 1.7e308, 0},
                                  {0, 0, 0, 1}, {5e-324, 0, 0, 1}, {0, 5e-324, 0, 1}, {0, 0, 5e-324, 1}};
  CHECK(deep_pairs(ends, all_of(ends), ends.size()) >= 3);  // three pairs a subnormal apart
}
