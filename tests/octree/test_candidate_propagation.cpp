// propagate_candidates (octree/candidate_propagation.h) keeps every site that owns a point of a seed box.
// Checked independently: sample points of every box (corners, centres, random dyadic points, the active
// centres, and the vertices of the brute-force diagram) get their owners, the active sites of least
// d(x) = |x - p| - w, by an exact comparison written here; every owner of a point must be a candidate of
// every closed seed box that contains the point.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "octree/candidate_propagation.h"
#include "octree/seed_partition.h"
#include "predicates/number_types.h"
#include "predicates/root_sign.h"
#include "predicates/rounding_guard.h"
#include "reference/brute_force_diagram.h"
#include "reference/site_generators.h"
#include "support/octree_input.h"

using namespace apollonius;
using namespace apollonius::testing;

namespace {

using Point = std::array<double, 3>;

int sign_of(const Exact& x) { return x.sign(); }

// sign(l + k sqrt(d)) for d >= 0: when the two terms have opposite signs, squaring both keeps the order
// of their magnitudes.
int sign_of_sum(const Exact& l, const Exact& k, const Exact& d) {
  const int sl = sign_of(l), sr = sign_of(d) == 0 ? 0 : sign_of(k);
  if (sr == 0) return sl;
  if (sl == 0 || sl == sr) return sr;
  return sl * sign_of(l * l - k * k * d);
}

// sign(sqrt(A) - sqrt(B) - c) for A, B >= 0. For c >= 0 both sqrt(A) and sqrt(B) + c are >= 0, so the
// sign is that of A - (sqrt(B) + c)^2 = (A - B - c^2) - 2c sqrt(B). For c < 0 both sqrt(A) - c and
// sqrt(B) are >= 0, so it is that of (sqrt(A) - c)^2 - B = (A + c^2 - B) - 2c sqrt(A).
int sign_of_root_difference(const Exact& A, const Exact& B, const Exact& c) {
  if (sign_of(c) >= 0) return sign_of_sum(A - B - c * c, Exact(-2) * c, B);
  return sign_of_sum(A + c * c - B, Exact(-2) * c, A);
}

Exact squared_distance(const Point& x, const Site& s) {
  const Exact dx = Exact(x[0]) - Exact(s.x), dy = Exact(x[1]) - Exact(s.y), dz = Exact(x[2]) - Exact(s.z);
  return dx * dx + dy * dy + dz * dz;
}

// sign(d_i(x) - d_j(x)) with d(x) = |x - p| - w: sign(sqrt(A) - sqrt(B) - (w_i - w_j)).
int compare_distances(const Point& x, const Site& i, const Site& j) {
  return sign_of_root_difference(squared_distance(x, i), squared_distance(x, j), Exact(i.w) - Exact(j.w));
}

// The owners of x: the active sites of least d(x), ascending. Intervals only rule out sites certainly
// farther than another one (lower bound above the least upper bound); the rest are compared exactly.
std::vector<Site_index> owners(const Point& x, const std::vector<Site>& sites, const std::vector<Site_index>& active) {
  std::vector<Interval> d(active.size());
  double least_upper = std::numeric_limits<double>::infinity();
  {
    Rounding_guard guard;
    for (std::size_t k = 0; k < active.size(); ++k) {
      const Site& s = sites[active[k]];
      const Interval dx = Interval(x[0]) - s.x, dy = Interval(x[1]) - s.y, dz = Interval(x[2]) - s.z;
      d[k] = CGAL::sqrt(dx * dx + dy * dy + dz * dz) - s.w;
      if (d[k].sup() < least_upper) least_upper = d[k].sup();
    }
  }
  std::vector<Site_index> tied;  // the least so far, all at the same distance
  for (std::size_t k = 0; k < active.size(); ++k) {
    if (d[k].inf() > least_upper) continue;  // false for NaN bounds: such a site is compared exactly
    const Site_index s = active[k];
    const int sign = tied.empty() ? -1 : compare_distances(x, sites[s], sites[tied.front()]);
    if (sign < 0) tied.assign(1, s);
    if (sign == 0) tied.push_back(s);
  }
  return tied;
}

bool contains(const Axis_box& b, const Point& x) {
  for (int a = 0; a < 3; ++a)
    if (!(b.lo[a] <= x[a] && x[a] <= b.hi[a])) return false;
  return true;
}

// Whether the closed box contains the exact centre of v. A correctly rounded coordinate below lo (above
// hi) proves the exact one is below (above) too, since rounding is monotone; the rest is decided exactly.
bool contains(const Axis_box& b, const Diagram_vertex& v) {
  for (int a = 0; a < 3; ++a)
    if (v.rounded[a] < b.lo[a] || v.rounded[a] > b.hi[a]) return false;
  const std::array<Root_number<Exact>, 4> p = exact_point(v.vertex);
  for (int a = 0; a < 3; ++a) {
    const Root_number<Exact> lo{Exact(b.lo[a]), Exact(0), Exact(0), Exact(1)};
    const Root_number<Exact> hi{Exact(b.hi[a]), Exact(0), Exact(0), Exact(1)};
    if (compare(p[a], lo) == Sign::NEGATIVE || compare(p[a], hi) == Sign::POSITIVE) return false;
  }
  return true;
}

struct Totals {
  std::size_t inputs = 0, skipped = 0, boxes = 0, points = 0, vertices = 0, vertices_beyond_root = 0, checks = 0,
              tied_checks = 0, candidates = 0;
};

// Every owner of `owned` is a candidate of every seed box that contains the point. Returns how many do.
template <class Contains>
std::size_t check_owners_are_candidates(const std::vector<Site_index>& owned, Contains&& contains_point,
                                        const std::vector<std::size_t>& ids, const std::vector<Axis_box>& boxes,
                                        const std::vector<std::vector<Site_index>>& candidates, Totals& totals) {
  std::size_t containing = 0;
  for (std::size_t k = 0; k < ids.size(); ++k) {
    if (!contains_point(boxes[k])) continue;
    const std::size_t id = ids[k];
    ++containing;
    const std::vector<Site_index>& list = candidates[id];
    for (Site_index s : owned) {
      INFO("owner ", s, " of the point, box ", id);
      CHECK(std::binary_search(list.begin(), list.end(), s));
    }
    ++totals.checks;
    if (owned.size() > 1) ++totals.tied_checks;
  }
  return containing;
}

void check_input(Site_family family, std::size_t n, std::uint64_t seed, Totals& totals) {
  const Octree_input in = octree_input(generate_sites(family, n, seed));
  if (in.active.size() < 4) {  // octree_diagram stops before the partition
    ++totals.skipped;
    return;
  }
  const Seed_partition partition(in.sites, in.active, kOctreeFarFieldScale);
  const std::vector<std::vector<Site_index>> candidates =
      propagate_candidates(in.sites, in.active, partition, Certified_kernel::filter_slack);
  REQUIRE(candidates.size() == partition.id_count());

  std::vector<std::size_t> ids;  // the seed boxes
  std::vector<Axis_box> boxes;   // theirs
  for (std::size_t id = 0; id < partition.id_count(); ++id) {
    CAPTURE(id);
    const std::vector<Site_index>& list = candidates[id];
    if (!partition.is_box(id)) {
      CHECK(list.empty());
      continue;
    }
    ids.push_back(id);
    boxes.push_back(partition.box(id));
    const auto not_ascending = [](Site_index p, Site_index q) { return p >= q; };
    CHECK(std::adjacent_find(list.begin(), list.end(), not_ascending) == list.end());
    for (Site_index s : list) CHECK(std::binary_search(in.active.begin(), in.active.end(), s));
    totals.candidates += list.size();
  }

  // The sample points: every corner and centre of a box, three random dyadic points in each, the active
  // centres. Each distinct point once.
  std::mt19937_64 random(seed * 0x9e3779b97f4a7c15ull + n);
  std::vector<Point> points;
  for (const Axis_box& b : boxes) {
    for (int corner = 0; corner < 8; ++corner)
      points.push_back({(corner & 1) != 0 ? b.hi[0] : b.lo[0], (corner & 2) != 0 ? b.hi[1] : b.lo[1],
                        (corner & 4) != 0 ? b.hi[2] : b.lo[2]});
    Point centre;
    for (int a = 0; a < 3; ++a) centre[a] = b.lo[a] + (b.hi[a] - b.lo[a]) / 2;
    points.push_back(centre);
    for (int k = 0; k < 3; ++k) {
      Point x;
      for (int a = 0; a < 3; ++a)  // lo + (hi - lo) j / 2^20, j in [0, 2^20]
        x[a] = b.lo[a] + (b.hi[a] - b.lo[a]) * std::ldexp(static_cast<double>(random() % ((1u << 20) + 1)), -20);
      CHECK(contains(b, x));
      points.push_back(x);
    }
  }
  for (Site_index s : in.active) points.push_back({in.sites[s].x, in.sites[s].y, in.sites[s].z});
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());

  for (const Point& x : points) {
    INFO("point (", x[0], ", ", x[1], ", ", x[2], ")");
    const std::vector<Site_index> owned = owners(x, in.sites, in.active);
    REQUIRE(!owned.empty());
    const std::size_t containing = check_owners_are_candidates(
        owned, [&](const Axis_box& b) { return contains(b, x); }, ids, boxes, candidates, totals);
    CHECK(containing >= 1);  // the boxes cover the root box, which holds every sample point
  }
  totals.points += points.size();

  // The vertices of the diagram: points owned by four sites or more, the hardest to keep.
  const Diagram reference = brute_force_diagram(in.sites);
  for (const Diagram_vertex& v : reference.vertices) {
    INFO("vertex of ", v.tie_set.size(), " sites, at about (", v.rounded[0], ", ", v.rounded[1], ", ", v.rounded[2],
         ")");
    const std::size_t containing = check_owners_are_candidates(
        v.tie_set, [&](const Axis_box& b) { return contains(b, v); }, ids, boxes, candidates, totals);
    // Beyond the root box no seed box holds a vertex: far_field.h finds those.
    if (containing == 0) ++totals.vertices_beyond_root;
  }
  totals.vertices += reference.vertices.size();
  ++totals.inputs;
  totals.boxes += ids.size();
}

}  // namespace

TEST_CASE("the exact comparison of weighted distances decides ties and near-ties") {
  const Point origin{0, 0, 0};
  struct Case {
    Site i, j;
    int expected;  // sign(d_i - d_j) at the origin
  };
  const double sqrt2_rounded = 1.4142135623730951;  // above sqrt(2) by about 4.4e-17
  const Case cases[] = {
      {{3, 4, 0, 1}, {0, 0, 5, 1}, 0},                     // 5 - 1 both
      {{1, 1, 0, 0}, {0, 1, 1, 0}, 0},                     // sqrt(2) both
      {{3, 4, 0, 2}, {0, 0, 1, -2}, 0},                    // 5 - 2 = 1 + 2, c = w_i - w_j > 0
      {{0, 0, 1, -2}, {3, 4, 0, 2}, 0},                    // the same, c < 0
      {{0, 0, 0, 1}, {1, 0, 0, 2}, 0},                     // at a centre: -1 both
      {{3, 4, 0, 2}, {0, 0, 1, -2 + 0x1p-50}, 1},          // j nearer by 2^-50
      {{0, 0, 1, -2 + 0x1p-50}, {3, 4, 0, 2}, -1},
      {{1, 1, 0, 0}, {0, 0, 0, -sqrt2_rounded}, -1},       // sqrt(2) against the double nearest to it
      {{0, 0, 0, -sqrt2_rounded}, {1, 1, 0, 0}, 1},
      {{2, 2, 0, 0}, {1, 1, 0, -sqrt2_rounded}, -1},       // 2 sqrt(2) against sqrt(2) + that double
      {{1, 1, 0, 0}, {0, 0, 0, -1.4142135623730949}, 1},   // the double below sqrt(2)
  };
  for (const Case& c : cases) {
    INFO("sites (", c.i.x, ", ", c.i.y, ", ", c.i.z, ", ", c.i.w, ") and (", c.j.x, ", ", c.j.y, ", ", c.j.z, ", ",
         c.j.w, ")");
    CHECK(compare_distances(origin, c.i, c.j) == c.expected);
    CHECK(compare_distances(origin, c.j, c.i) == -c.expected);
  }
  // Owners: every tied site, and no other.
  const std::vector<Site> sites = {{3, 4, 0, 1}, {0, 0, 5, 1}, {0, 0, 6, 1.5}, {0, 3, 4, 1}, {1, 1, 0, -sqrt2_rounded}};
  CHECK(owners(origin, sites, {0, 1, 2, 3}) == std::vector<Site_index>{0, 1, 3});
  CHECK(owners(origin, sites, {0, 1, 2, 3, 4}) == std::vector<Site_index>{4});
}

TEST_CASE("every owner of a sample point is a candidate of every seed box containing it") {
  Totals totals;
  for (const Site_family_description& family : kSiteFamilies) {
    for (std::size_t n : {5, 12, 25}) {
      for (std::uint64_t seed : {1, 2}) {
        INFO("family ", std::string(family.name), ", n = ", n, ", seed ", seed);
        check_input(family.family, n, seed, totals);
      }
    }
  }
  MESSAGE(totals.inputs, " inputs, ", totals.boxes, " seed boxes with ", totals.candidates, " candidates, ",
          totals.points, " sample points and ", totals.vertices, " vertices (", totals.vertices_beyond_root,
          " beyond the root box): ", totals.checks, " (point, box) pairs checked, ", totals.tied_checks,
          " of them at points with several owners; ", totals.skipped, " inputs with fewer than 4 active sites");
  CHECK(totals.inputs + totals.skipped == std::size(kSiteFamilies) * 3 * 2);
  CHECK(totals.inputs >= std::size(kSiteFamilies) * 3 * 2 - 6);
  CHECK(totals.vertices > totals.vertices_beyond_root);
  CHECK(totals.tied_checks > 0);
}
