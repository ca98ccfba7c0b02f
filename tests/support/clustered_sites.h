// Sites over many binades for the filter stages' tests (wide_interval.h, mpfr_interval.h).
#pragma once

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "predicates/site.h"

namespace apollonius::testing {

// Sites in clusters of their own scales, as in `generate wide-range`: a site at 2^e, and sites a hair from
// it (2^(e - h), h up to 900) or at scales of their own. Weights stay below the spread, so that most
// quadruples have vertices.
inline std::vector<Site> clustered_sites(std::mt19937_64& random, int count) {
  std::uniform_int_distribution<int> exponent(-700, 700), hair(20, 900), small(-4, 4), choice(0, 2);
  std::vector<Site> sites;
  const auto at_scale = [&](double scale) {
    return Site{scale * small(random), scale * small(random), scale * small(random),
                scale * std::abs(small(random)) / 8};
  };
  while (static_cast<int>(sites.size()) < count) {
    if (sites.empty() || choice(random) == 0) {
      sites.push_back(at_scale(std::ldexp(1.0, exponent(random))));
      continue;
    }
    const Site& near = sites[std::uniform_int_distribution<std::size_t>(0, sites.size() - 1)(random)];
    const double scale =
        std::max({std::fabs(near.x), std::fabs(near.y), std::fabs(near.z), std::fabs(near.w), 0x1p-700});
    const Site offset = at_scale(std::ldexp(scale, -hair(random)));
    sites.push_back({near.x + offset.x, near.y + offset.y, near.z + offset.z, near.w + offset.w});
  }
  return sites;
}

}  // namespace apollonius::testing
