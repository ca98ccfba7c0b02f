#include "octree/deep_clusters.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>

namespace apollonius {
namespace {

// The 21 low bits of x spread to every third bit.
std::uint64_t spread_bits(std::uint64_t x) {
  x &= 0x1fffff;
  x = (x | x << 32) & 0x1f00000000ffffull;
  x = (x | x << 16) & 0x1f0000ff0000ffull;
  x = (x | x << 8) & 0x100f00f00f00f00full;
  x = (x | x << 4) & 0x10c30c30c30c30c3ull;
  x = (x | x << 2) & 0x1249249249249249ull;
  return x;
}

// Half of the centre's coordinate on an axis: no extent of halves overflows (sites near +-1.7e308).
double half_coordinate(const Site& s, int axis) { return 0.5 * centre_coordinate(s, axis); }

}  // namespace

std::size_t deep_pairs(const std::vector<Site>& sites, const std::vector<Site_index>& active, std::size_t enough) {
  if (active.size() < 2) return 0;
  std::array<double, 3> lo{}, hi{};
  for (int a = 0; a < 3; ++a) lo[a] = hi[a] = half_coordinate(sites[active[0]], a);
  for (Site_index s : active)
    for (int a = 0; a < 3; ++a) {
      const double x = half_coordinate(sites[s], a);
      lo[a] = std::min(lo[a], x), hi[a] = std::max(hi[a], x);
    }
  double half_extent = 0;
  for (int a = 0; a < 3; ++a) half_extent = std::max(half_extent, hi[a] - lo[a]);
  if (!(half_extent > 0) || !std::isfinite(half_extent)) return 0;

  std::vector<std::pair<std::uint64_t, Site_index>> order;
  order.reserve(active.size());
  for (Site_index s : active) {
    std::uint64_t code = 0;
    for (int a = 0; a < 3; ++a) {
      const double cell = std::floor((half_coordinate(sites[s], a) - lo[a]) / half_extent * 0x1p21);
      code |= spread_bits(static_cast<std::uint64_t>(std::clamp(cell, 0.0, 0x1p21 - 1))) << a;
    }
    order.emplace_back(code, s);
  }
  std::sort(order.begin(), order.end());
  const double deep = std::ldexp(half_extent, -kDeepBinades);
  std::size_t count = 0;
  for (std::size_t k = 1; k < order.size() && count < enough; ++k) {
    const Site& p = sites[order[k - 1].second];
    const Site& q = sites[order[k].second];
    double half_distance = 0;
    for (int a = 0; a < 3; ++a)
      half_distance = std::max(half_distance, std::fabs(half_coordinate(p, a) - half_coordinate(q, a)));
    if (half_distance < deep) ++count;
  }
  return count;
}

}  // namespace apollonius
