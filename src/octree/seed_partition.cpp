#include "octree/seed_partition.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace apollonius {
namespace {

// At least this many level-0 cubes per active site (and fewer than 8 times as many): fewer cubes start
// with more candidates each, and the refinement makes up for them at less cost than propagation over more
// (docs/benchmarks.md, "A quarter of a seed cube per site").
constexpr double kCubesPerSite = 0.25;
// Lattice indices stay below 2^50 in magnitude, so that k 2^l s is exact and sums of indices do not
// overflow; the cube side stays above 2^-40 times the extent of the sites.
constexpr double kLargestIndex = 0x1p50;
constexpr double kFinestRelativeSide = 0x1p-40;
// The grid is offset from the multiples of s by kOffsetFraction s, an odd multiple of 2^-10 away from the
// simple fractions: a lattice input (integer or dyadic centres) would otherwise put its bisector planes
// and vertices on the faces of boxes of the first levels, where vertex_in_box has only its exact stage
// to decide. Bounds stay exact while |k| 2^l 2^10 < 2^53, so the offset is used below kLargestOffsetIndex,
// and below the tenth level of refinement the grid holds no more bits than it did without the offset.
constexpr double kOffsetFraction = 379.0 / 1024;
constexpr double kLargestOffsetIndex = 0x1p40;

// Floor and ceiling division by 2 of possibly negative integers.
std::int64_t floor_half(std::int64_t k) { return k >= 0 ? k / 2 : -((-k + 1) / 2); }
std::int64_t ceil_half(std::int64_t k) { return -floor_half(-k); }

// The side s = 2^e of the level-0 cubes: halved from the first power of two covering the extent until
// there are at least kCubesPerSite cubes per site.
double cube_side(const std::array<double, 3>& lo, const std::array<double, 3>& hi, std::size_t site_count) {
  const double extent = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  double largest = 0;
  for (int a = 0; a < 3; ++a) largest = std::max({largest, std::fabs(lo[a]), std::fabs(hi[a])});
  int exponent = 0;
  std::frexp(extent, &exponent);
  double side = std::ldexp(1.0, exponent);
  const auto cubes = [&](double s) {
    double count = 1;
    for (int a = 0; a < 3; ++a) count *= std::floor(hi[a] / s) - std::ceil(lo[a] / s) + 3;
    return count;
  };
  const double target = kCubesPerSite * static_cast<double>(site_count);
  while (cubes(side) < target && side / 2 > extent * kFinestRelativeSide && largest / (side / 2) < kLargestIndex)
    side /= 2;
  return side;
}

}  // namespace

Seed_partition::Seed_partition(const std::vector<Site>& sites, const std::vector<Site_index>& active,
                               double far_field_scale) {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  std::array<double, 3> lo{kInfinity, kInfinity, kInfinity}, hi{-kInfinity, -kInfinity, -kInfinity};
  for (Site_index i : active) {
    const double c[3] = {sites[i].x, sites[i].y, sites[i].z};
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], c[a]), hi[a] = std::max(hi[a], c[a]);
  }
  const double side = cube_side(lo, hi, active.size());
  build_levels(lo, hi, side, far_field_scale);
  // The offset needs ten bits below s on top of the largest index of the first build, which the second
  // exceeds by a cube of each level at most.
  double largest_index = 0;
  for (int a = 0; a < 3; ++a)
    largest_index = std::max({largest_index, std::fabs(root_box_.lo[a]) / side, std::fabs(root_box_.hi[a]) / side});
  if (largest_index < kLargestOffsetIndex) {
    offset_ = kOffsetFraction * side;
    build_levels(lo, hi, side, far_field_scale);
  }

  level_offset_.push_back(0);
  for (const Level& l : levels_) {
    std::size_t count = 1;
    for (int a = 0; a < 3; ++a) count *= static_cast<std::size_t>(l.hi[a] - l.lo[a]);
    level_offset_.push_back(level_offset_.back() + count);
  }
}

void Seed_partition::build_levels(const std::array<double, 3>& lo, const std::array<double, 3>& hi, double side,
                                  double far_field_scale) {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  levels_.clear();
  unit_.clear();
  // Level 0: every centre strictly inside, bounds even for level 1.
  Level g;
  for (int a = 0; a < 3; ++a) {
    g.lo[a] = 2 * floor_half(static_cast<std::int64_t>(std::ceil(lo[a] / side)) - 1);
    g.hi[a] = 2 * ceil_half(static_cast<std::int64_t>(std::floor(hi[a] / side)) + 1);
    // Without the offset the bounds are strict already (ceil(lo / s) - 1 < lo / s); with it, one more cube
    // of level 1 at most.
    while (!(bound(side, g.lo[a]) < lo[a])) g.lo[a] -= 2;
    while (!(hi[a] < bound(side, g.hi[a]))) g.hi[a] += 2;
  }
  levels_.push_back(g);
  unit_.push_back(side);
  Axis_box grid_box;  // G
  for (int a = 0; a < 3; ++a) {
    grid_box.lo[a] = bound(side, g.lo[a]);
    grid_box.hi[a] = bound(side, g.hi[a]);
    origin_[a] = grid_box.lo[a] + (grid_box.hi[a] - grid_box.lo[a]) / 2;
  }
  double half_extent = 0;
  for (int a = 0; a < 3; ++a) half_extent = std::max(half_extent, grid_box.hi[a] - origin_[a]);
  // far_field.h decides beyond R whatever the weights (lifted_triangulation.h), so R depends on the
  // centres only.
  const double needed = 2 * far_field_scale * half_extent;

  // Shells: level l + 1 has cubes twice as large, reaches at least one of them beyond level l, and is
  // aligned to the cubes of level l + 2.
  for (;;) {
    const Level& inner = levels_.back();
    const double unit = unit_.back();
    double radius = kInfinity;
    for (int a = 0; a < 3; ++a) {
      root_box_.lo[a] = bound(unit, inner.lo[a]);
      root_box_.hi[a] = bound(unit, inner.hi[a]);
      radius = std::min({radius, origin_[a] - root_box_.lo[a], root_box_.hi[a] - origin_[a]});
    }
    if (!std::isfinite(radius) || !std::isfinite(2 * unit))
      throw std::overflow_error("the far field of this input exceeds the double range");
    if (radius >= needed) {
      root_radius_ = radius;
      break;
    }
    Level outer;
    for (int a = 0; a < 3; ++a) {
      outer.lo[a] = 2 * floor_half(inner.lo[a] / 2 - 1);
      outer.hi[a] = 2 * ceil_half(inner.hi[a] / 2 + 1);
    }
    levels_.push_back(outer);
    unit_.push_back(2 * unit);
  }
}

bool Seed_partition::in_range(int level, const Index3& k) const {
  const Level& l = levels_[level];
  for (int a = 0; a < 3; ++a)
    if (k[a] < l.lo[a] || k[a] >= l.hi[a]) return false;
  return true;
}

bool Seed_partition::in_hole(int level, const Index3& k) const {
  if (level == 0) return false;
  const Level& inner = levels_[level - 1];
  for (int a = 0; a < 3; ++a)
    if (k[a] < inner.lo[a] / 2 || k[a] >= inner.hi[a] / 2) return false;
  return true;
}

std::size_t Seed_partition::id_of(int level, const Index3& k) const {
  const Level& l = levels_[level];
  const std::size_t n0 = static_cast<std::size_t>(l.hi[0] - l.lo[0]), n1 = static_cast<std::size_t>(l.hi[1] - l.lo[1]);
  return level_offset_[level] + static_cast<std::size_t>(k[0] - l.lo[0]) +
         n0 * (static_cast<std::size_t>(k[1] - l.lo[1]) + n1 * static_cast<std::size_t>(k[2] - l.lo[2]));
}

Seed_partition::Index3 Seed_partition::index_of(std::size_t id, int& level) const {
  level = static_cast<int>(std::upper_bound(level_offset_.begin(), level_offset_.end(), id) - level_offset_.begin()) - 1;
  const Level& l = levels_[level];
  std::size_t local = id - level_offset_[level];
  const std::size_t n0 = static_cast<std::size_t>(l.hi[0] - l.lo[0]), n1 = static_cast<std::size_t>(l.hi[1] - l.lo[1]);
  Index3 k;
  k[0] = l.lo[0] + static_cast<std::int64_t>(local % n0);
  local /= n0;
  k[1] = l.lo[1] + static_cast<std::int64_t>(local % n1);
  k[2] = l.lo[2] + static_cast<std::int64_t>(local / n1);
  return k;
}

bool Seed_partition::is_box(std::size_t id) const {
  int level = 0;
  const Index3 k = index_of(id, level);
  return !in_hole(level, k);
}

Axis_box Seed_partition::box(std::size_t id) const {
  int level = 0;
  const Index3 k = index_of(id, level);
  Axis_box b;
  for (int a = 0; a < 3; ++a) {
    b.lo[a] = bound(unit_[level], k[a]);
    b.hi[a] = bound(unit_[level], k[a] + 1);
  }
  return b;
}

void Seed_partition::append_face_neighbours(std::size_t id, std::vector<std::size_t>& out) const {
  int level = 0;
  const Index3 k = index_of(id, level);
  for (int a = 0; a < 3; ++a) {
    for (int step : {-1, 1}) {
      Index3 n = k;
      n[a] += step;
      if (in_range(level, n) && !in_hole(level, n)) {
        out.push_back(id_of(level, n));
      } else if (in_range(level, n)) {
        // The face lies on the outer boundary of level - 1: four cubes of half the side meet it.
        const int b = (a + 1) % 3, c = (a + 2) % 3;
        Index3 fine;
        fine[a] = step > 0 ? 2 * n[a] : 2 * n[a] + 1;
        for (int db = 0; db < 2; ++db)
          for (int dc = 0; dc < 2; ++dc) {
            fine[b] = 2 * k[b] + db;
            fine[c] = 2 * k[c] + dc;
            out.push_back(id_of(level - 1, fine));
          }
      } else if (level + 1 < static_cast<int>(levels_.size())) {
        // The face lies on the outer boundary of this level: one cube of twice the side lies beyond it.
        Index3 coarse;
        for (int d = 0; d < 3; ++d) coarse[d] = floor_half(n[d]);
        out.push_back(id_of(level + 1, coarse));
      }
    }
  }
}

std::size_t Seed_partition::home(const Site& s) const {
  const double c[3] = {s.x, s.y, s.z};
  Index3 k;
  for (int a = 0; a < 3; ++a) {
    // (c - offset) / unit is rounded (and a negative one that tiny underflows to -0, whose floor names
    // the cube above c); the bounds are exact and increasing in k, so comparing with them repairs it.
    k[a] = static_cast<std::int64_t>(std::floor((c[a] - offset_) / unit_[0]));
    while (bound(unit_[0], k[a]) > c[a]) --k[a];
    while (!(c[a] < bound(unit_[0], k[a] + 1))) ++k[a];
  }
  return id_of(0, k);
}

bool Seed_partition::touches_root_boundary(std::size_t id) const {
  int level = 0;
  const Index3 k = index_of(id, level);
  if (level + 1 != static_cast<int>(levels_.size())) return false;
  const Level& l = levels_[level];
  for (int a = 0; a < 3; ++a)
    if (k[a] == l.lo[a] || k[a] + 1 == l.hi[a]) return true;
  return false;
}

}  // namespace apollonius
