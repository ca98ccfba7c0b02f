// Every triple of a list of sites, for the trisector tests.
#pragma once

#include <doctest/doctest.h>

#include <array>
#include <cstddef>
#include <vector>

#include "predicates/site.h"

namespace apollonius::testing {

// Calls f on the sites at a < b < c for every such positions, captured for doctest's failure messages.
template <class F>
void for_each_triple(const std::vector<Site>& sites, F f) {
  for (std::size_t a = 0; a < sites.size(); ++a)
    for (std::size_t b = a + 1; b < sites.size(); ++b)
      for (std::size_t c = b + 1; c < sites.size(); ++c) {
        CAPTURE(a);
        CAPTURE(b);
        CAPTURE(c);
        f(std::array<Site, 3>{sites[a], sites[b], sites[c]});
      }
}

}  // namespace apollonius::testing
