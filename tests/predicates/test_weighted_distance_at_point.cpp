// compare_weighted_distances and side_of_grown_ball against 2000-bit MPFR evaluations of the square roots
// (an independent computation: it takes the roots, the predicates never do), on random doubles, on exact
// ties built from Pythagorean quadruples, and on near-ties one ulp away. Seeds are printed on failure.
#include <doctest/doctest.h>

#include <boost/multiprecision/mpfr.hpp>

#include <cmath>
#include <random>

#include "predicates/weighted_distance_at_point.h"

using namespace apollonius;

namespace {

using Big = boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<2000>>;

// sign(d_s(p) - d_t(p)), the roots taken at 2000 bits: certain unless the value is below 2^-1900 of the
// inputs' scale, which the tests below avoid but for exact ties (built so that A, B, W are exact squares).
Sign reference_compare(const std::array<double, 3>& p, const Site& s, const Site& t) {
  const auto distance = [&](const Site& x) {
    const Big dx = Big(p[0]) - Big(x.x), dy = Big(p[1]) - Big(x.y), dz = Big(p[2]) - Big(x.z);
    return sqrt(dx * dx + dy * dy + dz * dz) - Big(x.w);
  };
  const Big d = distance(s) - distance(t);
  if (abs(d) < Big("1e-500")) return Sign::ZERO;
  return d > 0 ? Sign::POSITIVE : Sign::NEGATIVE;
}

Sign reference_side(const std::array<double, 3>& p, const Site& s, double r) {
  const Big radius = Big(s.w) + Big(r);
  if (radius < 0) return Sign::POSITIVE;
  const Big dx = Big(p[0]) - Big(s.x), dy = Big(p[1]) - Big(s.y), dz = Big(p[2]) - Big(s.z);
  const Big d = sqrt(dx * dx + dy * dy + dz * dz) - radius;
  if (abs(d) < Big("1e-500")) return Sign::ZERO;
  return d > 0 ? Sign::POSITIVE : Sign::NEGATIVE;
}

}  // namespace

TEST_CASE("compare_weighted_distances: random points and sites, against MPFR") {
  for (int seed = 1; seed <= 20000; ++seed) {
    CAPTURE(seed);
    std::mt19937_64 random(static_cast<std::uint64_t>(seed));
    std::uniform_real_distribution<double> coordinate(-10, 10), weight(-3, 3);
    const std::array<double, 3> p{coordinate(random), coordinate(random), coordinate(random)};
    const Site s{coordinate(random), coordinate(random), coordinate(random), weight(random)};
    const Site t{coordinate(random), coordinate(random), coordinate(random), seed % 3 == 0 ? s.w : weight(random)};
    CHECK(compare_weighted_distances(p, s, t) == reference_compare(p, s, t));
    CHECK(compare_weighted_distances(p, t, s) == -reference_compare(p, s, t));
  }
}

TEST_CASE("compare_weighted_distances: exact ties and one-ulp neighbours") {
  // Integer distances from the origin: (1, 2, 2) -> 3, (2, 3, 6) -> 7, (1, 4, 8) -> 9, (4, 4, 7) -> 9.
  const std::array<std::array<double, 4>, 4> quadruples{{{1, 2, 2, 3}, {2, 3, 6, 7}, {1, 4, 8, 9}, {4, 4, 7, 9}}};
  int ties = 0;
  for (int scale_step = -3; scale_step <= 3; ++scale_step) {
    const double scale = std::ldexp(1.0, 7 * scale_step);
    for (const auto& a : quadruples)
      for (const auto& b : quadruples)
        for (double shift : {-2.0, 0.0, 1.5}) {
          CAPTURE(scale);
          // d_s(0) = a[3] - w_s and d_t(0) = b[3] - w_t, equal when w_t = w_s + b[3] - a[3].
          const Site s{scale * a[0], scale * a[1], scale * a[2], scale * shift};
          const Site t{-scale * b[1], scale * b[2], -scale * b[0], scale * (shift + b[3] - a[3])};
          const std::array<double, 3> origin{0, 0, 0};
          CHECK(compare_weighted_distances(origin, s, t) == Sign::ZERO);
          ++ties;
          for (double direction : {-1.0, 1.0}) {
            Site nudged = t;
            nudged.w = std::nextafter(t.w, direction * INFINITY);
            CHECK(compare_weighted_distances(origin, s, nudged) == reference_compare(origin, s, nudged));
            CHECK(compare_weighted_distances(origin, s, nudged) == (direction > 0 ? Sign::POSITIVE : Sign::NEGATIVE));
            std::array<double, 3> moved = origin;
            moved[0] = direction * std::ldexp(1.0, -1000);
            CHECK(compare_weighted_distances(moved, s, t) == reference_compare(moved, s, t));
          }
        }
  }
  CHECK(ties == 7 * 16 * 3);
  // A site against itself, and the same centre with other weights.
  const Site s{1, 2, 3, 0.5}, lighter{1, 2, 3, 0.25};
  const std::array<double, 3> p{4, 5, 6};
  CHECK(compare_weighted_distances(p, s, s) == Sign::ZERO);
  CHECK(compare_weighted_distances(p, s, lighter) == Sign::NEGATIVE);
}

TEST_CASE("side_of_grown_ball: on, inside, outside, negative radius") {
  const Site s{1, 1, 1, 3};
  const std::array<double, 3> on{1 + 3, 1 + 4, 1}, centre{1, 1, 1};
  CHECK(side_of_grown_ball(on, s, 2.0) == Sign::ZERO);  // |(3, 4, 0)| = 5 = 3 + 2
  CHECK(side_of_grown_ball(on, s, std::nextafter(2.0, 3.0)) == Sign::NEGATIVE);
  CHECK(side_of_grown_ball(on, s, std::nextafter(2.0, 1.0)) == Sign::POSITIVE);
  CHECK(side_of_grown_ball(centre, s, -4.0) == Sign::POSITIVE);  // radius -1: no ball
  CHECK(side_of_grown_ball(centre, s, -3.0) == Sign::ZERO);      // radius 0: the centre only
  for (int seed = 1; seed <= 20000; ++seed) {
    CAPTURE(seed);
    std::mt19937_64 random(static_cast<std::uint64_t>(seed));
    std::uniform_real_distribution<double> coordinate(-5, 5), weight(-2, 4);
    const std::array<double, 3> p{coordinate(random), coordinate(random), coordinate(random)};
    const Site t{coordinate(random), coordinate(random), coordinate(random), weight(random)};
    const double r = weight(random);
    CHECK(side_of_grown_ball(p, t, r) == reference_side(p, t, r));
  }
}
