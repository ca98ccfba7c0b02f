// An exact validator for a Diagram, run after every computation in the tests: every vertex against every
// active site, and every invariant of diagram.h.
#pragma once

#include <doctest/doctest.h>

#include <algorithm>
#include <set>

#include "predicates/compare_vertices.h"
#include "diagram/diagram.h"
#include "support/exact_checks.h"
#include "predicates/vertex_conflict.h"

namespace apollonius::testing {

inline void validate_diagram(const Diagram& d, const std::vector<Site>& sites) {
  std::vector<bool> hidden(sites.size(), false);
  for (const Hidden_site& h : d.hidden) hidden[h.site] = true;
  for (std::size_t i = 0; i < d.vertices.size(); ++i) {
    const Diagram_vertex& v = d.vertices[i];
    INFO("vertex " << i);
    REQUIRE(v.tie_set.size() >= 4);
    REQUIRE(std::is_sorted(v.tie_set.begin(), v.tie_set.end()));
    for (Site_index s : v.vertex.sites()) REQUIRE(std::binary_search(v.tie_set.begin(), v.tie_set.end(), s));
    // Every active site: tied exactly when in the tie set, otherwise strictly farther.
    for (Site_index s = 0; s < sites.size(); ++s) {
      if (hidden[s]) continue;
      const bool tied = std::binary_search(v.tie_set.begin(), v.tie_set.end(), s);
      CHECK(vertex_conflict(v.vertex, sites[s]) == (tied ? Sign::ZERO : Sign::POSITIVE));
    }
    // Printed values are the correct roundings of the exact point.
    CHECK(exactly_rounded_point(v.vertex) == v.rounded);
    if (i > 0) {
      const Diagram_vertex& u = d.vertices[i - 1];
      const bool ordered = u.tie_set < v.tie_set ||
                           (u.tie_set == v.tie_set && (u.rounded < v.rounded || (u.rounded == v.rounded &&
                                                        compare_vertices(u.vertex, v.vertex) == Sign::NEGATIVE)));
      CHECK(ordered);
    }
  }
  std::set<Site_index> with_vertex;
  for (const Diagram_vertex& v : d.vertices) with_vertex.insert(v.tie_set.begin(), v.tie_set.end());
  for (Site_index s : d.sites_without_vertex) {
    CHECK_FALSE(hidden[s]);
    CHECK(with_vertex.count(s) == 0);
  }
  std::size_t active = 0;
  for (Site_index s = 0; s < sites.size(); ++s) active += hidden[s] ? 0 : 1;
  CHECK(with_vertex.size() + d.sites_without_vertex.size() == active);
}

}  // namespace apollonius::testing
