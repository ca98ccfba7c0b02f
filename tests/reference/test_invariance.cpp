// Exact invariance of the diagram on random inputs: permuting the sites, translating by integers, scaling
// by 2^k and adding a constant to every weight give the same diagram, transformed exactly.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>

#include "reference/brute_force_diagram.h"
#include "support/diagram_checks.h"
#include "reference/site_generators.h"

using namespace apollonius;
using namespace apollonius::testing;

namespace {

// The vertex of `d` with the given tie set and the exact point `expected` (after the inverse transform).
void check_same_diagram(const Diagram& original, const Diagram& transformed,
                        const std::vector<Site_index>& original_index_of,
                        const std::function<std::array<Root_number<Exact>, 4>(const Vertex&)>& untransformed_point) {
  REQUIRE(transformed.vertices.size() == original.vertices.size());
  for (const Diagram_vertex& t : transformed.vertices) {
    std::vector<Site_index> tie;
    for (Site_index s : t.tie_set) tie.push_back(original_index_of[s]);
    std::sort(tie.begin(), tie.end());
    const auto p = untransformed_point(t.vertex);
    const auto same = std::find_if(original.vertices.begin(), original.vertices.end(), [&](const Diagram_vertex& o) {
      if (o.tie_set != tie) return false;
      const auto q = exact_point(o.vertex);
      for (int j = 0; j < 4; ++j)
        if (!exactly_equal(p[j], q[j])) return false;
      return true;
    });
    CHECK(same != original.vertices.end());
  }
  REQUIRE(transformed.hidden.size() == original.hidden.size());
}

std::vector<Site_index> identity(std::size_t n) {
  std::vector<Site_index> v(n);
  std::iota(v.begin(), v.end(), Site_index{0});
  return v;
}

const Site_family kFamilies[] = {Site_family::uniform, Site_family::mixed_sign, Site_family::coplanar,
                                 Site_family::cospherical, Site_family::nested, Site_family::lattice};

}  // namespace

TEST_CASE("permuting the sites permutes the tie sets and nothing else") {
  for (Site_family family : kFamilies)
    for (std::uint64_t seed = 1; seed <= 25; ++seed) {
      const std::string family_name = name_of(family);
      CAPTURE(family_name);
      CAPTURE(seed);
      const std::vector<Site> sites = generate_sites(family, 6 + seed % 4, seed);
      const Diagram original = brute_force_diagram(sites);
      // Reverse, then rotate: every site changes position, so every vertex changes its origin site.
      std::vector<Site_index> original_index_of = identity(sites.size());
      std::reverse(original_index_of.begin(), original_index_of.end());
      std::rotate(original_index_of.begin(), original_index_of.begin() + 1, original_index_of.end());
      std::vector<Site> permuted;
      for (Site_index i : original_index_of) permuted.push_back(sites[i]);
      const Diagram d = brute_force_diagram(permuted);
      validate_diagram(d, permuted);
      check_same_diagram(original, d, original_index_of, [](const Vertex& v) { return exact_point(v); });
      // Correct rounding is a function of the exact value: the printed numbers are identical.
      std::vector<std::array<double, 4>> a, b;
      for (const auto& v : original.vertices) a.push_back(v.rounded);
      for (const auto& v : d.vertices) b.push_back(v.rounded);
      std::sort(a.begin(), a.end());
      std::sort(b.begin(), b.end());
      CHECK(a == b);
    }
}

TEST_CASE("translating by integers, scaling by 2^k, shifting every weight") {
  for (Site_family family : kFamilies)
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
      const std::string family_name = name_of(family);
      CAPTURE(family_name);
      CAPTURE(seed);
      const std::vector<Site> sites = generate_sites(family, 6 + seed % 4, seed);
      const Diagram original = brute_force_diagram(sites);
      const auto same_indices = identity(sites.size());

      SUBCASE("translation") {
        const double t[3] = {1000.0 + static_cast<double>(seed), -77.0, 3.0 * static_cast<double>(seed)};
        std::vector<Site> moved = sites;
        for (Site& s : moved) s = {s.x + t[0], s.y + t[1], s.z + t[2], s.w};  // exact: small dyadics
        const Diagram d = brute_force_diagram(moved);
        validate_diagram(d, moved);
        check_same_diagram(original, d, same_indices, [&](const Vertex& v) {
          auto p = exact_point(v);
          for (int j = 0; j < 3; ++j) p[j] = plus(p[j], -t[j]);
          return p;
        });
      }
      SUBCASE("scaling") {
        for (int k : {-40, -1, 3, 200}) {
          CAPTURE(k);
          std::vector<Site> scaled = sites;
          for (Site& s : scaled) s = scaled_by_power_of_two(s, k);
          const Diagram d = brute_force_diagram(scaled);
          validate_diagram(d, scaled);
          REQUIRE(d.vertices.size() == original.vertices.size());
          for (std::size_t i = 0; i < d.vertices.size(); ++i) {
            CHECK(d.vertices[i].tie_set == original.vertices[i].tie_set);
            for (int j = 0; j < 4; ++j) CHECK(d.vertices[i].rounded[j] == std::ldexp(original.vertices[i].rounded[j], k));
          }
        }
      }
      SUBCASE("adding a constant to every weight") {
        const double c = 0.375 * static_cast<double>(seed % 5) - 0.5;
        std::vector<Site> shifted = sites;
        for (Site& s : shifted) s.w += c;
        const Diagram d = brute_force_diagram(shifted);
        validate_diagram(d, shifted);
        check_same_diagram(original, d, same_indices, [&](const Vertex& v) {
          auto p = exact_point(v);
          p[3] = plus(p[3], c);
          return p;
        });
      }
    }
}
