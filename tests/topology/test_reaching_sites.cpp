// Reaching_sites (the sites that may be within a reach of a point known within a box) against the exact
// condition at points of the box: every site with d_s(x) <= reach at a sampled x, decided in rationals, is
// found; the answer holds each site once, from the subset, and, for boxes away from most sites, a small part of it.
// Random sites of every generator family and random boxes; a failure prints the family and seed.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "predicates/number_types.h"
#include "predicates/rounding_guard.h"
#include "reference/site_generators.h"
#include "topology/reaching_sites.h"

using namespace apollonius;

namespace {

// d_s(x) <= reach, exactly: |x - c| <= reach + w.
bool reaches(const std::array<double, 3>& x, const Site& s, double reach) {
  const Rational limit = Rational(reach) + Rational(s.w);
  if (limit < 0) return false;
  const Rational dx = Rational(x[0]) - Rational(s.x), dy = Rational(x[1]) - Rational(s.y),
                 dz = Rational(x[2]) - Rational(s.z);
  return dx * dx + dy * dy + dz * dz <= limit * limit;
}

}  // namespace

TEST_CASE("Reaching_sites finds every site within the reach somewhere in the box") {
  std::size_t queries = 0, found = 0, offered = 0, must = 0;
  for (const Site_family_description& f : kSiteFamilies) {
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
      const std::string family = f.name;
      CAPTURE(family);
      CAPTURE(seed);
      const std::vector<Site> sites = generate_sites(f.family, 200, seed);
      std::vector<Site_index> subset;
      std::mt19937_64 random(seed);
      for (Site_index s = 0; s < sites.size(); ++s)
        if (random() % 4 != 0) subset.push_back(s);
      const Reaching_sites reaching(sites, subset);
      std::vector<Site_index> out;
      for (int q = 0; q < 40; ++q) {
        // A box around a site's centre (sometimes a point), and a reach from -2 to 2 times its size.
        const Site& s = sites[random() % sites.size()];
        const double half = std::ldexp(static_cast<double>(random() % 1000) / 1000, -static_cast<int>(random() % 8));
        const std::array<double, 3> centre{s.x, s.y, s.z};
        std::array<Interval, 3> box;
        for (int a = 0; a < 3; ++a)
          box[a] = q % 5 == 0 ? Interval(centre[a]) : Interval(centre[a] - half, centre[a] + half);
        const double reach = (static_cast<double>(random() % 4001) / 1000 - 2) * (half + 1);
        reaching.find(box, reach, out);
        std::sort(out.begin(), out.end());
        ++queries;
        found += out.size();
        offered += subset.size();
        CHECK(std::adjacent_find(out.begin(), out.end()) == out.end());
        for (Site_index t : out) CHECK(std::binary_search(subset.begin(), subset.end(), t));
        // Points of the box: its corners, its centre and random ones.
        for (int p = 0; p < 12; ++p) {
          std::array<double, 3> x;
          for (int a = 0; a < 3; ++a) {
            const double lo = box[a].inf(), hi = box[a].sup();
            x[a] = p < 8 ? ((p >> a) & 1 ? hi : lo) : p == 8 ? centre[a] : lo + (hi - lo) * (static_cast<double>(random() % 1024) / 1024);
            x[a] = std::min(std::max(x[a], lo), hi);
          }
          for (Site_index t : subset) {
            if (!reaches(x, sites[t], reach)) continue;
            ++must;
            CHECK_MESSAGE(std::binary_search(out.begin(), out.end(), t), "site " << t << " reaches a point of the box");
          }
        }
      }
    }
  }
  MESSAGE(queries << " queries: " << found << " sites found of " << offered << " offered; " << must
                  << " point-site pairs within reach checked");
  CHECK(must > 1000);
  CHECK(found * 4 < offered);  // the search leaves most sites out
}

TEST_CASE("Reaching_sites: unbounded boxes, infinite reaches, and an empty subset") {
  const std::vector<Site> sites = generate_sites(Site_family::uniform, 50, 1);
  std::vector<Site_index> all(sites.size());
  for (Site_index s = 0; s < sites.size(); ++s) all[s] = s;
  const Reaching_sites reaching(sites, all);
  std::vector<Site_index> out;
  const double inf = std::numeric_limits<double>::infinity();
  reaching.find({Interval(-inf, inf), Interval(-inf, inf), Interval(-inf, inf)}, 0, out);  // every weight is positive
  std::sort(out.begin(), out.end());
  CHECK(out == all);
  reaching.find({Interval(0), Interval(0), Interval(0)}, inf, out);
  std::sort(out.begin(), out.end());
  CHECK(out == all);
  reaching.find({Interval(1e300), Interval(1e300), Interval(1e300)}, 1, out);
  CHECK(out.empty());
  const Reaching_sites none(sites, {});
  none.find({Interval(0), Interval(0), Interval(0)}, inf, out);
  CHECK(out.empty());
  // The bound of d_s over a box is at least d_s at its corners, and infinite for an unbounded box.
  const std::array<Interval, 3> box{Interval(0, 1), Interval(-1, 2), Interval(3)};
  {
    Rounding_guard guard;
    const double bound = weighted_distance_upper_bound(box, sites[0]);
    for (double x : {0.0, 1.0})
      for (double y : {-1.0, 2.0}) CHECK(reaches({x, y, 3}, sites[0], bound));
    CHECK(weighted_distance_upper_bound({Interval(-inf, inf), Interval(0), Interval(0)}, sites[0]) == inf);
  }
}
