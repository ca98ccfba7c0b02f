// The boxes of a vertex made from its exact coordinates (vertices_of's exact stage; vertex.h): the box and
// the scaled box hold X and are a few ulps wide, also where the exact parts (D, d) or X itself leave the
// double range; and vertex_conflict's interval stage, which reads them, agrees with the exact stage.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <random>

#include "predicates/rounding_guard.h"
#include "predicates/vertex_conflict.h"
#include "predicates/vertices_of.h"

using namespace apollonius;

namespace {

// Sites of a small lattice (spacing 4, weights 1 or 1.5), each coordinate moved by at most one ulp: where
// four sites are nearly cospherical or coplanar, D and d underflow and one root lies far away. A
// coordinate 0 moves by 5e-324, so that the face x_axis = 0 (all four sites on it in half of the draws)
// gives vertices beyond 10^308.
std::vector<Site> nudged_lattice(std::mt19937_64& random) {
  std::uniform_int_distribution<int> cell(0, 2), step(-1, 1), weight(0, 1), face(-3, 2);
  const int on_face = face(random);  // an axis, or none if negative
  std::vector<Site> sites(4);
  for (Site& s : sites) {
    s = {4.0 * cell(random), 4.0 * cell(random), 4.0 * cell(random), weight(random) ? 1.5 : 1.0};
    if (on_face >= 0) (on_face == 0 ? s.x : on_face == 1 ? s.y : s.z) = 0;
    for (double* c : {&s.x, &s.y, &s.z})
      if (const int k = step(random); k != 0) *c = std::nextafter(*c, k * std::numeric_limits<double>::infinity());
  }
  return sites;
}

Root_number<Exact> exact_coordinate(const Vertex& v, int j) {
  const Vertex_coordinates<Exact>& X = v.coordinates<Exact>();
  return {X.scaled[j].a, X.scaled[j].b, X.discriminant, X.denominator};
}

// bound 2^k as an exact root number.
Root_number<Exact> dyadic_times_power_of_two(double bound, long k) {
  return {times_power_of_two(Exact(bound), static_cast<int>(k)), Exact(0), Exact(0), Exact(1)};
}

// Whether the interval times 2^k holds x (an infinite bound holds everything beyond it).
bool holds(const Interval& box, long k, const Root_number<Exact>& x) {
  const bool above_lower = std::isinf(box.inf()) || compare(x, dyadic_times_power_of_two(box.inf(), k)) != Sign::NEGATIVE;
  const bool below_upper = std::isinf(box.sup()) || compare(x, dyadic_times_power_of_two(box.sup(), k)) != Sign::POSITIVE;
  return above_lower && below_upper;
}

// At most 64 ulps of the larger bound wide, or within the subnormal range.
bool tight(const Interval& box) {
  const double magnitude = std::max(std::fabs(box.inf()), std::fabs(box.sup()));
  if (!(std::isfinite(magnitude) && box.sup() - box.inf() <= std::max(magnitude * 0x1p-46, 0x1p-1000)))
    MESSAGE("wide: [" << std::hexfloat << box.inf() << ", " << box.sup() << "]");
  return std::isfinite(magnitude) && box.sup() - box.inf() <= std::max(magnitude * 0x1p-46, 0x1p-1000);
}

// The vertices as vertices_of's exact stage makes them.
Quadruple_vertices exact_vertices(const std::vector<Site>& sites) {
  return Vertices_of_predicate::evaluate<Exact>(make_quadruple({0, 1, 2, 3}, sites));
}

}  // namespace

TEST_CASE("the box from exact coordinates is a few ulps wide, and a scaled box holds X beyond the double range") {
  std::mt19937_64 random(20261128);
  int vertices = 0, parts_out_of_range = 0, scaled = 0;
  for (int trial = 0; trial < 6000; ++trial) {
    const std::vector<Site> sites = nudged_lattice(random);
    for (const Vertex& v : exact_vertices(sites).vertices) {
      CAPTURE(trial);
      const Vertex_coordinates<Exact>& X = v.coordinates<Exact>();
      ++vertices;
      const long n = binary_exponent(X.denominator);
      if (n < -1000 || n > 1000) ++parts_out_of_range;
      // The scaled box is computed on first use: a copy that dropped its exact coordinates first computes
      // them again, and the same box.
      Vertex released = v;
      released.release_exact_values();
      const Scaled_box* again = released.scaled_box();
      const Scaled_box* box = v.scaled_box();
      REQUIRE((again == nullptr) == (box == nullptr));
      if (box != nullptr) {
        CHECK(again->exponent == box->exponent);
        for (int j = 0; j < 4; ++j) {
          CHECK(again->scaled[j].inf() == box->scaled[j].inf());
          CHECK(again->scaled[j].sup() == box->scaled[j].sup());
        }
      }
      for (int j = 0; j < 4; ++j) {
        const Root_number<Exact> x = exact_coordinate(v, j);
        CHECK(holds(v.coordinates<Interval>().scaled[j], 0, x));
        if (box != nullptr) {
          CHECK(holds(box->scaled[j], box->exponent, x));
          CHECK(tight(box->scaled[j]));
        } else {
          CHECK(tight(v.coordinates<Interval>().scaled[j]));
        }
      }
      if (box != nullptr) ++scaled;
    }
  }
  MESSAGE(vertices << " vertices, " << parts_out_of_range << " with a denominator beyond 2^+-1000, " << scaled
                   << " with a scaled box");
  // The cases this file is about occur, so that a regression in them fails here.
  CHECK(parts_out_of_range >= 100);
  CHECK(scaled >= 100);
}

TEST_CASE("vertex_conflict's interval stage agrees with the exact stage, and decides far vertices against other sites") {
  std::mt19937_64 random(1128);
  std::uniform_int_distribution<int> coordinate(-8, 16), weight(0, 1);
  int tests = 0, decided = 0, far_tests = 0, far_decided = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const std::vector<Site> sites = nudged_lattice(random);
    for (const Vertex& v : exact_vertices(sites).vertices) {
      const bool far = v.scaled_box() != nullptr;
      for (int k = 0; k < 20; ++k) {
        const Site s{1.0 * coordinate(random), 1.0 * coordinate(random), 1.0 * coordinate(random), weight(random) ? 1.5 : 1.0};
        std::optional<Sign> filtered;
        {
          Rounding_guard guard;
          filtered = Vertex_conflict_predicate::interval_stage(v, s);
        }
        const Sign exact = Vertex_conflict_predicate::evaluate<Exact>(v, s);
        CAPTURE(trial);
        CAPTURE(k);
        if (filtered) CHECK(*filtered == exact);
        ++tests;
        decided += filtered.has_value();
        far_tests += far;
        far_decided += far && filtered.has_value();
      }
    }
  }
  MESSAGE(decided << " of " << tests << " tests decided by intervals; " << far_decided << " of " << far_tests
                  << " for vertices with a scaled box");
  CHECK(far_tests >= 1000);
  CHECK(far_decided * 10 >= far_tests * 9);
  CHECK(decided * 10 >= tests * 9);
}
