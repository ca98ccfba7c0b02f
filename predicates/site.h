// A site of the diagram: a ball centre and an additive weight, each exactly the double given.
#pragma once

#include <cstdint>

namespace apollonius {

struct Site {
  double x, y, z, w;
  friend bool operator==(const Site& a, const Site& b) {
    return a.x == b.x && a.y == b.y && a.z == b.z && a.w == b.w;
  }
};

// Position of a site in the input, 0-based; every output names sites by it.
using Site_index = std::uint32_t;

}  // namespace apollonius
