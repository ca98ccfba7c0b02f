// A site of the diagram: a ball centre and an additive weight, each exactly the double given.
#pragma once

#include <cmath>
#include <cstdint>

namespace apollonius {

struct Site {
  double x, y, z, w;
  friend bool operator==(const Site& a, const Site& b) {
    return a.x == b.x && a.y == b.y && a.z == b.z && a.w == b.w;
  }
};

// The centre's coordinate on axis 0 (x), 1 (y) or 2 (z).
inline double centre_coordinate(const Site& s, int axis) { return axis == 0 ? s.x : axis == 1 ? s.y : s.z; }

// The site scaled by 2^k: exact unless a value leaves the normal range. The diagram scales with it.
inline Site scaled_by_power_of_two(const Site& s, int k) {
  return {std::ldexp(s.x, k), std::ldexp(s.y, k), std::ldexp(s.z, k), std::ldexp(s.w, k)};
}

// Position of a site in the input, 0-based; every output names sites by it.
using Site_index = std::uint32_t;

}  // namespace apollonius
