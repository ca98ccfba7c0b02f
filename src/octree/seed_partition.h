// The seed boxes of the octree (paper section 5.2.1: "initially, we partition the bounding box into a set
// of cubes"), extended to a root box R far larger than the sites:
//  - level 0 is the box G of the site centres, cut into cubes of side s = 2^e (a quarter to two cubes per site);
//  - level l >= 1 is a shell of cubes of side 2^l s around level l - 1, one or two cubes thick;
//  - the outer boundary of the last level L is R.
// Every bound is k 2^l s + offset for an integer k, an exact double (the offset is a fixed fraction of s
// with ten bits, or 0: seed_partition.cpp), so that adjacent boxes share their bounds exactly and every
// box of the octree below them is a dyadic box of that grid as well.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "predicates/axis_box.h"
#include "predicates/site.h"

namespace apollonius {

// Invariants: the boxes tile R; every active site centre lies strictly inside G; level l - 1 is aligned to
// the cubes of level l, so each face of a level-l cube on the inner boundary of its shell meets exactly
// four cubes of level l - 1.
class Seed_partition {
 public:
  // R contains the ball about G's centre of radius 2 * far_field_scale * h (h: G's largest half-extent).
  // Throws std::overflow_error when R exceeds the double range.
  Seed_partition(const std::vector<Site>& sites, const std::vector<Site_index>& active, double far_field_scale);

  // Box identifiers are dense in [0, id_count()); identifiers of the cubes of a shell's hole are unused.
  std::size_t id_count() const { return level_offset_.back(); }
  bool is_box(std::size_t id) const;
  Axis_box box(std::size_t id) const;

  // The boxes sharing a piece of face of positive area with box `id`, appended to out.
  void append_face_neighbours(std::size_t id, std::vector<std::size_t>& out) const;

  // A box of level 0 whose closed box contains the site centre.
  std::size_t home(const Site& s) const;

  // Whether the box lies on the boundary of R.
  bool touches_root_boundary(std::size_t id) const;

  const Axis_box& root_box() const { return root_box_; }
  // Every bound is k 2^l s + grid_offset() for an integer k.
  double grid_offset() const { return offset_; }
  // The centre of G and the radius of the ball about it that R contains.
  const std::array<double, 3>& origin() const { return origin_; }
  double root_radius() const { return root_radius_; }

 private:
  using Index3 = std::array<std::int64_t, 3>;
  struct Level {
    Index3 lo, hi;  // cube index range [lo, hi) per axis, in units of 2^l s
  };

  // Levels, root box, origin and radius for the current offset_.
  void build_levels(const std::array<double, 3>& lo, const std::array<double, 3>& hi, double side,
                    double far_field_scale);
  double bound(double unit, std::int64_t k) const { return static_cast<double>(k) * unit + offset_; }
  std::size_t id_of(int level, const Index3& k) const;
  Index3 index_of(std::size_t id, int& level) const;
  bool in_range(int level, const Index3& k) const;
  bool in_hole(int level, const Index3& k) const;

  std::vector<Level> levels_;
  std::vector<double> unit_;                // 2^l s
  std::vector<std::size_t> level_offset_;  // first identifier of each level, and the total at the end
  Axis_box root_box_;
  std::array<double, 3> origin_;
  double root_radius_ = 0;
  double offset_ = 0;
};

}  // namespace apollonius
