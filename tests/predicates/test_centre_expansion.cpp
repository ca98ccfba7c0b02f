// The octree's removal tests (predicates/centre_expansion.h) against exact brute force: whenever
// expansion_dominates says that site j is strictly closer than site i on a box, d_j(x) < d_i(x) must hold
// exactly at the box's corners, its centre and random points of it. Inputs range from ordinary boxes to
// pairs of sites seen from up to 2^900 times their separation, at any overall scale of the double range,
// where the plain differences of distances lose every bit. The tests must also keep removing sites there:
// a filter that never certifies would be sound and useless (the octree then refines without end).
//
// A failure prints the family, the case and its seed; APOLLONIUS_CENTRE_EXPANSION_SEED overrides the base seed.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <string>
#include <utility>

#include "predicates/centre_expansion.h"
#include "predicates/number_types.h"
#include "predicates/root_sign.h"

using namespace apollonius;

namespace {

// The standard engine: the cases need only be reproducible from the printed seed on this toolchain.
class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}
  double unit() { return std::uniform_real_distribution<double>(0, 1)(engine_); }  // in [0, 1)
  double symmetric() { return 2 * unit() - 1; }                                   // in [-1, 1)
  int integer(int low, int high) { return std::uniform_int_distribution<int>(low, high)(engine_); }
  double eighths(double extent) { return std::round(extent * symmetric() * 8) / 8; }  // in [-extent, extent]

 private:
  std::mt19937_64 engine_;
};

// sign(d_i(x) - d_j(x)) exactly: sqrt|x - x_i|^2 - sqrt|x - x_j|^2 + (w_j - w_i).
Sign exact_difference_sign(const std::array<double, 3>& x, const Site& i, const Site& j) {
  const auto squared = [&](const Site& s) {
    const Exact dx = Exact(x[0]) - Exact(s.x), dy = Exact(x[1]) - Exact(s.y), dz = Exact(x[2]) - Exact(s.z);
    return dx * dx + dy * dy + dz * dz;
  };
  return sign_of_two_root_sum(Exact(j.w) - Exact(i.w), Exact(1), squared(i), Exact(-1), squared(j));
}

// A point of the closed box: lo + t (hi - lo), kept inside against rounding.
double inside(double lo, double hi, double t) { return std::min(hi, std::max(lo, lo + t * (hi - lo))); }

struct Outcome {
  bool dominated = false;
  bool sound = true;
};

// Which removal test check_pair runs: the octree's sequence, or test (A) alone.
enum class Removal_test { all, corners };

// Runs the test as the refinement does (or test (A) alone) and, when it removes i, checks d_j < d_i exactly
// at 8 corners, the centre and 24 random points.

Outcome check_pair(const Axis_box& box, const Site& i, const Site& j, Random& random,
                   Removal_test test = Removal_test::all) {
  const Box_frame frame = frame_of(box);
  const Centre_expansion at_i = expand_at_centre(i, frame);
  Witness_expansion at_j = expand_witness(expand_at_centre(j, frame));
  add_corners(at_j, j, frame);
  Candidate_on_box on_box;
  Outcome outcome;
  outcome.dominated = test == Removal_test::all ? expansion_dominates(j, at_j, i, at_i, on_box, frame, 1.0)
                                                : corners_dominate(j, at_j, i, at_i, on_box, frame, 1.0);
  if (!outcome.dominated) return outcome;
  for (int q = 0; q < 8 + 1 + 24; ++q) {
    std::array<double, 3> x;
    for (int a = 0; a < 3; ++a)
      x[a] = q < 8 ? (q >> a & 1 ? box.hi[a] : box.lo[a]) : q == 8 ? frame.centre[a] : inside(box.lo[a], box.hi[a], random.unit());
    if (exact_difference_sign(x, i, j) != Sign::POSITIVE) outcome.sound = false;
  }
  return outcome;
}

std::uint64_t base_seed() {
  if (const char* env = std::getenv("APOLLONIUS_CENTRE_EXPANSION_SEED")) return std::strtoull(env, nullptr, 10);
  return 20261122;
}

Axis_box scaled(const Axis_box& b, int e) {
  Axis_box r;
  for (int a = 0; a < 3; ++a) r.lo[a] = std::ldexp(b.lo[a], e), r.hi[a] = std::ldexp(b.hi[a], e);
  return r;
}

// A cube of side 2^size_exponent (a dyadic box, as the octree's) with its lower corner near `near`.
Axis_box dyadic_cube(const std::array<double, 3>& near, int size_exponent) {
  const double side = std::ldexp(1.0, size_exponent);
  Axis_box box;
  for (int a = 0; a < 3; ++a) {
    box.lo[a] = std::floor(near[a] / side) * side;
    box.hi[a] = box.lo[a] + side;
  }
  return box;
}

}  // namespace

TEST_CASE("removal tests are sound against exact brute force, near and far, at every scale") {
  const std::uint64_t seed0 = base_seed();
  struct Family {
    const char* name;
    int cases;
  };
  for (const Family family : {Family{"ordinary boxes", 4000}, Family{"cluster seen from far away", 4000},
                              Family{"tiny box near both sites", 2000}}) {
    int dominated = 0;
    for (int k = 0; k < family.cases; ++k) {
      const std::uint64_t seed = seed0 + static_cast<std::uint64_t>(k) * 1000003;
      Random random(seed);
      Site i, j;
      Axis_box box;
      const std::string name = family.name;
      if (name == "ordinary boxes") {
        // Sites and boxes of comparable sizes, dyadic coordinates.
        i = {random.eighths(16), random.eighths(16), random.eighths(16), std::round(random.unit() * 24) / 8};
        j = {random.eighths(16), random.eighths(16), random.eighths(16), std::round(random.unit() * 24) / 8};
        box = dyadic_cube({16 * random.symmetric(), 16 * random.symmetric(), 16 * random.symmetric()}, random.integer(-6, 3));
      } else if (name == "cluster seen from far away") {
        // Two sites about 1 apart, the box 2^far away in a random direction and 2^far / 2^(0..8) in size.
        const int far = random.integer(0, 900);
        i = {random.symmetric(), random.symmetric(), random.symmetric(), random.unit()};
        j = {random.symmetric(), random.symmetric(), random.symmetric(), random.unit()};
        const std::array<double, 3> direction = {random.symmetric(), random.symmetric(), random.symmetric()};
        box = dyadic_cube({std::ldexp(direction[0], far), std::ldexp(direction[1], far), std::ldexp(direction[2], far)},
                          far - random.integer(0, 8));
      } else {
        // A box much smaller than the sites' distances to it.
        i = {random.symmetric(), random.symmetric(), random.symmetric(), random.unit()};
        j = {random.symmetric(), random.symmetric(), random.symmetric(), random.unit()};
        box = dyadic_cube({random.symmetric(), random.symmetric(), random.symmetric()}, -random.integer(4, 60));
      }
      // An overall scale that keeps every value a normal double: the tests must not depend on it.
      const int e = random.integer(-60, 60) * (name == "cluster seen from far away" ? 1 : 15);
      const Outcome outcome = check_pair(scaled(box, e), scaled_by_power_of_two(i, e), scaled_by_power_of_two(j, e), random);
      CAPTURE(family.name);
      CAPTURE(k);
      CAPTURE(seed);
      CHECK(outcome.sound);
      dominated += outcome.dominated;
    }
    MESSAGE(std::string(family.name) << ": " << dominated << " of " << family.cases << " removals certified, each checked exactly");
    // Not vacuous: about half the pairs have the witness closer, and many of those are far from the box.
    CHECK(dominated >= family.cases / 10);
  }
}

// The defect these tests had: two sites 1 apart, seen from 10^15 times farther, could not be told apart
// (the rounding error of each distance exceeded their difference), and the octree refined millions of
// boxes (tests/data/regression/octree_boxes_explode_*). Now separated up to 2^900 away, at any scale.
TEST_CASE("a pair seen from up to 2^900 times its separation is separated, at every scale") {
  const Site i{-1, 0, 0, 0}, j{0, 0.25, 0, 0.125};
  for (int far = 4; far <= 900; far += 8)
    for (int e : {-1000, -300, 0, 100}) {
      if (far + e > 1000) continue;
      CAPTURE(far);
      CAPTURE(e);
      // The box on the +x axis, 2^far away and 2^(far - 6) in size: j is closer by about 1 on all of it.
      Axis_box box;
      const double side = std::ldexp(1.0, far - 6);
      for (int a = 0; a < 3; ++a) box.lo[a] = a == 0 ? std::ldexp(1.0, far) : -side / 2, box.hi[a] = box.lo[a] + side;
      Random random(static_cast<std::uint64_t>(far));
      const Outcome outcome = check_pair(scaled(box, e), scaled_by_power_of_two(i, e), scaled_by_power_of_two(j, e), random);
      CHECK(outcome.dominated);
      CHECK(outcome.sound);
    }
}

// Test (A) with a witness no larger than the candidate is exact up to rounding (paper Theorem 8.1): j is
// then closer than i on the whole box as soon as it is closer at the eight corners, and the test must
// remove i whenever the corners show that by more than the rounding margins. (The octree tries it only
// where the first-order bound does not already fail: centre_tests.)
TEST_CASE("a witness no larger than the candidate, closer at the eight corners, removes it") {
  const std::uint64_t seed0 = base_seed();
  int required = 0;
  for (int k = 0; k < 4000; ++k) {
    const std::uint64_t seed = seed0 + static_cast<std::uint64_t>(k) * 7919;
    Random random(seed);
    // Boxes as large as their distance to the sites, where bounding d_i by its tangent plane loses most.
    Site i{random.eighths(4), random.eighths(4), random.eighths(4), std::round(random.unit() * 16) / 8};
    Site j{random.eighths(4), random.eighths(4), random.eighths(4), std::round(random.unit() * 16) / 8};
    if (j.w > i.w) std::swap(i.w, j.w);
    const Axis_box box = dyadic_cube({4 * random.symmetric(), 4 * random.symmetric(), 4 * random.symmetric()},
                                     random.integer(-3, 1));
    // Closer at every corner by far more than any rounding (plain doubles suffice to choose the cases).
    bool closer_at_corners = true;
    for (int q = 0; q < 8; ++q) {
      const double y[3] = {q & 1 ? box.hi[0] : box.lo[0], q & 2 ? box.hi[1] : box.lo[1], q & 4 ? box.hi[2] : box.lo[2]};
      const auto d = [&](const Site& s) { return std::hypot(y[0] - s.x, y[1] - s.y, y[2] - s.z) - s.w; };
      closer_at_corners = closer_at_corners && d(i) - d(j) > 1e-9;
    }
    if (!closer_at_corners) continue;
    ++required;
    const int e = random.integer(-60, 60) * 15;
    const Outcome outcome =
        check_pair(scaled(box, e), scaled_by_power_of_two(i, e), scaled_by_power_of_two(j, e), random, Removal_test::corners);
    CAPTURE(k);
    CAPTURE(seed);
    CHECK(outcome.dominated);
    CHECK(outcome.sound);
  }
  MESSAGE(required << " pairs closer at the corners, each required to be removed");
  CHECK(required >= 500);
}

namespace {

// sign(d_s(c) unit - bound) exactly, for a bound in box units: sign(sqrt(S) - (w + bound / unit)).
Sign sign_of_box_value_minus(const Site& s, const Box_frame& frame, double bound) {
  const Exact dx = Exact(frame.centre[0]) - Exact(s.x), dy = Exact(frame.centre[1]) - Exact(s.y),
              dz = Exact(frame.centre[2]) - Exact(s.z);
  const Exact shifted = Exact(s.w) + times_power_of_two(Exact(bound), frame.exponent);  // unit = 2^-exponent
  return sign_of_root_number(-shifted, Exact(1), dx * dx + dy * dy + dz * dz);
}

// A ball whose sphere passes within a rounding of `near`: its centre 2^far away in a random direction, its
// weight the rounded distance (plus -1, 0 or 1 ulp). Near `near`, d_s is then tiny against |c - x_s| + w_s,
// the plain doubles' error scale: the ball acts there as a plane through `near`.
Site sphere_through(const std::array<double, 3>& near, int far, Random& random) {
  Site s;
  const std::array<double, 3> direction = {random.symmetric(), random.symmetric(), random.symmetric()};
  s.x = near[0] + std::ldexp(direction[0], far);
  s.y = near[1] + std::ldexp(direction[1], far);
  s.z = near[2] + std::ldexp(direction[2], far);
  // The distance without overflow: scaled down first.
  const double scale = std::ldexp(1.0, -far);
  const double distance =
      std::hypot((s.x - near[0]) * scale, (s.y - near[1]) * scale, (s.z - near[2]) * scale) / scale;
  const int nudge = random.integer(-1, 1);
  s.w = nudge < 0 ? std::nextafter(distance, 0.0) : nudge > 0 ? std::nextafter(distance, HUGE_VAL) : distance;
  return s;
}

}  // namespace

// The sharp value (sharp_centre_value.h) where the plain doubles fail: near the sphere of a ball up to 2^1000
// times larger than the box, and for sites beyond the plain tests' range. Checked exactly: d_s(c) lies in
// [value - error, value + error] (or beyond the clamp, on its side), and the error is small against the box.
TEST_CASE("the sharp centre value encloses d_s(c) exactly, near huge spheres and beyond the plain range") {
  const std::uint64_t seed0 = base_seed();
  int tight = 0, clamped = 0;
  const int cases = 4000;
  for (int k = 0; k < cases; ++k) {
    const std::uint64_t seed = seed0 + static_cast<std::uint64_t>(k) * 15485863;
    Random random(seed);
    const std::array<double, 3> near = {random.symmetric(), random.symmetric(), random.symmetric()};
    const Axis_box box = dyadic_cube({near[0] + random.eighths(2), near[1] + random.eighths(2), near[2] + random.eighths(2)},
                                     -random.integer(0, 40));
    // Half the cases a huge sphere through `near`, half a site far beyond the plain range with any weight.
    Site s = sphere_through(near, random.integer(10, 1000), random);
    if (k % 2 == 1) s.w = (random.unit() < 0.5 ? -1 : 1) * std::ldexp(random.unit(), random.integer(-1074, 1023));
    const int e = random.integer(-4, 4) * 10;
    const Box_frame frame = frame_of(scaled(box, e));
    s = scaled_by_power_of_two(s, e);
    if (!std::isfinite(s.x) || !std::isfinite(s.y) || !std::isfinite(s.z) || !std::isfinite(s.w)) continue;
    const Sharp_centre_value sharp = sharp_centre_value(s, frame);
    CAPTURE(k);
    CAPTURE(seed);
    REQUIRE(sharp.known);
    if (sharp.error == 0 && std::fabs(sharp.value) == kSharpValueClamp) {
      ++clamped;
      CHECK(sign_of_box_value_minus(s, frame, sharp.value) != (sharp.value > 0 ? Sign::NEGATIVE : Sign::POSITIVE));
      continue;
    }
    CHECK(sign_of_box_value_minus(s, frame, sharp.value - sharp.error) != Sign::NEGATIVE);
    CHECK(sign_of_box_value_minus(s, frame, sharp.value + sharp.error) != Sign::POSITIVE);
    // A few units in the last place of the value itself, not of |c - x_s| + |w_s|.
    tight += sharp.error <= 0x1p-45 * std::max(std::fabs(sharp.value), 1.0);
  }
  MESSAGE(tight << " tight and " << clamped << " clamped sharp values of " << cases << ", each checked exactly");
  CHECK(tight >= cases / 2);
}

// The octree's defect this fixes (tests/data/regression/octree_boxes_explode_for_huge_sphere_near_cluster_*):
// a ball whose sphere, 2^far times larger than the box, passes near it could neither be removed there
// nor remove a small ball, so the boxes refined one level per binade. Now both, soundly, at every scale.
TEST_CASE("a ball whose sphere is far larger than the box is removed, and removes, near its sphere") {
  const std::uint64_t seed0 = base_seed();
  int removed_huge = 0, removed_small = 0;
  const int cases = 3000;
  for (int k = 0; k < cases; ++k) {
    const std::uint64_t seed = seed0 + static_cast<std::uint64_t>(k) * 104729;
    Random random(seed);
    const std::array<double, 3> near = {random.eighths(4), random.eighths(4), random.eighths(4)};
    const Site huge = sphere_through(near, random.integer(60, 1000), random);
    // A small ball near the sphere, and a box a few box sizes from both.
    const Site small{near[0] + random.eighths(4), near[1] + random.eighths(4), near[2] + random.eighths(4),
                     std::round(random.unit() * 8) / 8};
    const Axis_box box = dyadic_cube({near[0] + random.eighths(16), near[1] + random.eighths(16), near[2] + random.eighths(16)},
                                     -random.integer(0, 3));
    CAPTURE(k);
    CAPTURE(seed);
    const Outcome huge_removed = check_pair(box, huge, small, random);
    const Outcome small_removed = check_pair(box, small, huge, random);
    CHECK(huge_removed.sound);
    CHECK(small_removed.sound);
    CHECK(!(huge_removed.dominated && small_removed.dominated));
    removed_huge += huge_removed.dominated;
    removed_small += small_removed.dominated;
  }
  MESSAGE(removed_huge << " huge and " << removed_small << " small balls removed of " << cases << " pairs");
  // Not vacuous: with the plain doubles alone neither count exceeded a handful (the error scale is 2^far).
  CHECK(removed_huge >= cases / 5);
  CHECK(removed_small >= cases / 5);
}
