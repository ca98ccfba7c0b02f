// A closed axis-aligned box whose corners are doubles (exact dyadic rationals): the cubes of the octree.
#pragma once

#include <array>

namespace apollonius {

struct Axis_box {
  std::array<double, 3> lo, hi;  // lo[a] < hi[a]
};

}  // namespace apollonius
