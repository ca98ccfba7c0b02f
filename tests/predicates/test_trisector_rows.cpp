// The rows' Gram determinant (trisector_rows.h) against the trisector's own classification (trisector.h):
// negative for every ellipse and point, positive for every hyperbola, zero for every parabola, on random and
// degenerate triples of every site family.
#include <doctest/doctest.h>

#include <random>

#include "predicates/is_hidden.h"
#include "predicates/rounding_guard.h"
#include "predicates/trisector_predicates.h"
#include "predicates/trisector_rows.h"
#include "reference/site_generators.h"

using namespace apollonius;

TEST_CASE("trisector rows: the Gram determinant's sign gives ellipse, hyperbola or parabola") {
  const std::uint64_t seed = std::random_device{}();
  CAPTURE(seed);
  std::size_t kinds[5] = {0, 0, 0, 0, 0};
  for (const Site_family_description& family : kSiteFamilies) {
    for (std::uint64_t k = 0; k < 3; ++k) {
      const std::uint64_t family_seed = seed + k;
      CAPTURE(family.name);
      CAPTURE(family_seed);
      const std::vector<Site> s = generate_sites(family.family, 12, family_seed);
      const auto visible = [&](Site_index i, Site_index j) { return !is_hidden(s[i], i, s[j], j) && !is_hidden(s[j], j, s[i], i); };
      for (Site_index a = 0; a < s.size(); ++a)
        for (Site_index b = a + 1; b < s.size(); ++b)
          for (Site_index c = b + 1; c < s.size(); ++c) {
            if (!visible(a, b) || !visible(a, c) || !visible(b, c)) continue;
            CAPTURE(a);
            CAPTURE(b);
            CAPTURE(c);
            const Trisector t({a, b, c}, {s[a], s[b], s[c]});
            const Trisector_kind kind = classify_trisector(t).first;
            ++kinds[static_cast<int>(kind)];
            const Sign exact = certain_sign(rows_gram_determinant(power_gap<Rational>(s[a], s[b]), power_gap<Rational>(s[a], s[c]),
                                                                  power_gap<Rational>(s[b], s[c])));
            // Any order of the sites gives the same value.
            CHECK(certain_sign(rows_gram_determinant(power_gap<Rational>(s[c], s[b]), power_gap<Rational>(s[c], s[a]),
                                                     power_gap<Rational>(s[b], s[a]))) == exact);
            if (kind == Trisector_kind::ellipse || kind == Trisector_kind::point) CHECK(exact == Sign::NEGATIVE);
            if (kind == Trisector_kind::hyperbola) CHECK(exact == Sign::POSITIVE);
            if (kind == Trisector_kind::parabola) CHECK(exact == Sign::ZERO);
            // The interval filter (vertex_free.cpp) only ever claims what is exact.
            Rounding_guard guard;
            const Interval filtered = rows_gram_determinant(power_gap<Interval>(s[a], s[b]), power_gap<Interval>(s[a], s[c]),
                                                            power_gap<Interval>(s[b], s[c]));
            if (filtered.inf() > 0) CHECK(exact == Sign::POSITIVE);
            if (filtered.sup() < 0) CHECK(exact == Sign::NEGATIVE);
          }
    }
  }
  MESSAGE("empty " << kinds[0] << ", point " << kinds[1] << ", ellipse " << kinds[2] << ", hyperbola " << kinds[3]
                   << ", parabola " << kinds[4]);
  CHECK(kinds[static_cast<int>(Trisector_kind::ellipse)] > 0);
  CHECK(kinds[static_cast<int>(Trisector_kind::hyperbola)] > 0);
}
