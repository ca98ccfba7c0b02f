// enclose_axis_point (predicates/sheet_point.h) against the exact point in Q(sqrt(D^2)): every coordinate of
// the point lies within the enclosure, decided exactly, for pairs of sites of every generator family (scaled
// by 2^300 and 2^-300, subnormal offsets, weights of both signs) and for pairs whose coordinates overflow in
// intervals. And the enclosure is tight where the intervals are: a failure of the narrowing would leave the
// centres' bounding box. Seeds are printed on failure.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "predicates/is_hidden.h"
#include "predicates/sheet_point.h"
#include "reference/site_generators.h"

using namespace apollonius;

namespace {

// Whether the exact coordinate k of the sheet point of a and b lies in [lo, hi].
bool exactly_within(const Site& a, const Site& b, int k, double lo, double hi) {
  const auto point = Axis_point_predicates::point<Rational>(a, b);
  return CGAL::sign(point[k] - Axis_point_predicates::Extension(Rational(lo))) != CGAL::NEGATIVE &&
         CGAL::sign(point[k] - Axis_point_predicates::Extension(Rational(hi))) != CGAL::POSITIVE;
}

}  // namespace

TEST_CASE("the sheet point's enclosure holds the exact point, and is tight where the intervals are") {
  std::size_t pairs = 0, tight = 0;
  for (const std::string& name : site_family_names()) {
    const Site_family family = site_family_from_name(name);
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      const std::vector<Site> sites = generate_sites(family, 24, seed);
      for (std::size_t i = 0; i < sites.size(); ++i)
        for (std::size_t j = i + 1; j < sites.size(); j += 3) {
          const Site &a = sites[i], &b = sites[j];
          // A sheet point needs D > |w_a - w_b|: neither ball inside the other, nor one centre.
          if (is_hidden(a, 0, b, 1) || is_hidden(b, 1, a, 0)) continue;
          CAPTURE(name);
          CAPTURE(seed);
          CAPTURE(i);
          CAPTURE(j);
          const std::array<Interval, 3> box = enclose_axis_point(a, b);
          ++pairs;
          bool narrow = true;
          for (int k = 0; k < 3; ++k) {
            REQUIRE(box[k].inf() <= box[k].sup());
            CHECK(exactly_within(a, b, k, box[k].inf(), box[k].sup()));
            const double extent = std::abs(centre_coordinate(a, k) - centre_coordinate(b, k));
            narrow = narrow && box[k].sup() - box[k].inf() <= 1e-12 * extent + 1e-300;
          }
          tight += narrow;
        }
    }
  }
  CHECK(pairs > 2000);
  // Most pairs: the intervals are tight but where subnormal offsets or 2^-300 scales leave them wide.
  CHECK(tight > pairs * 3 / 4);
}

TEST_CASE("where the intervals overflow, the enclosure is the centres' bounding box") {
  const double huge = std::numeric_limits<double>::max();  // x_b - x_a overflows
  for (const double w : {0.0, 1.0, -3.0}) {
    CAPTURE(w);
    const Site a{-huge, 0, 1, w}, b{huge, 1, 0, 0};  // t = 1/2 + w / (2 D): y a hair above 1/2 unless w = 0
    const std::array<Interval, 3> box = enclose_axis_point(a, b);
    CHECK(box[0].inf() == -huge);
    CHECK(box[0].sup() == huge);
    for (int k = 0; k < 3; ++k) CHECK(exactly_within(a, b, k, box[k].inf(), box[k].sup()));
    CHECK(box[1].sup() - box[1].inf() < 1e-15);
  }
}
