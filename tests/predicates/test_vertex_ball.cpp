// The double-double stages (vertex_ball.h) against the exact stages, on every quadruple of small inputs of
// every generator family: vertices_of's roots, the balls and boxes they give, vertex_conflict against every
// site, vertex_in_box against bounds on, next to and a few ulps from each coordinate and on the nearby
// lattice planes, and the rounding sides. Wherever a ball stage answers, it must equal the exact answer;
// on sites one ulp off a lattice (what the stage is for) it must answer almost every test that is no tie.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <map>
#include <string>

#include "predicates/vertex_conflict.h"
#include "predicates/vertex_in_box.h"
#include "predicates/vertex_rounding.h"
#include "predicates/vertices_of.h"
#include "reference/site_generators.h"
#include "support/exact_checks.h"
#include "support/time_limit.h"

using namespace apollonius;
using namespace apollonius::testing;

namespace {

struct Counts {
  std::size_t asked = 0, answered = 0;
  void count(bool answer) { ++asked, answered += answer ? 1 : 0; }
};

// Whether every number of the ball's range [hi + lo - error, hi + lo + error] brackets x (exact Mpzf bounds).
bool ball_contains(const Double_double_ball& ball, const Root_number<Exact>& x) {
  const Exact centre = Exact(ball.hi) + Exact(ball.lo), error(ball.error);
  const Root_number<Exact> low{centre - error, Exact(0), Exact(0), Exact(1)}, high{centre + error, Exact(0), Exact(0), Exact(1)};
  return compare(low, x) != Sign::POSITIVE && compare(x, high) != Sign::POSITIVE;
}

// X_j exactly, over its denominator.
Root_number<Exact> exact_x(const Vertex& v, int j) {
  const Vertex_coordinates<Exact>& X = v.coordinates<Exact>();
  return {X.scaled[j].a, X.scaled[j].b, X.discriminant, X.denominator};
}

// Doubles on, next to and two ulps from x, and the multiples of 1 and 4 around it (lattice planes).
std::vector<double> bounds_near(double x) {
  if (!std::isfinite(x)) return {};
  std::vector<double> bounds = {x, std::floor(x), std::ceil(x), 4 * std::floor(x / 4), 4 * std::ceil(x / 4)};
  double below = x, above = x;
  for (int step = 0; step < 2; ++step) {
    below = std::nextafter(below, -INFINITY), above = std::nextafter(above, INFINITY);
    bounds.push_back(below), bounds.push_back(above);
  }
  return bounds;
}

}  // namespace

TEST_CASE("the double-double stages equal the exact stages wherever they answer") {
  std::map<std::string, Counts> vertices, conflicts, boxes, sides;
  for (const std::string& name : site_family_names()) {
    for (std::uint64_t seed = 1; seed <= 8; ++seed) {
      const std::size_t n = 6 + seed % 4;
      const std::vector<Site> sites = generate_sites(site_family_from_name(name), n, seed);
      CAPTURE(name);
      CAPTURE(seed);
      testing::Input_time_limit limit(60.0, name + " seed " + std::to_string(seed));
      for (Site_index a = 0; a < n; ++a)
        for (Site_index b = a + 1; b < n; ++b)
          for (Site_index c = b + 1; c < n; ++c)
            for (Site_index d = c + 1; d < n; ++d) {
              const Quadruple q = make_quadruple({a, b, c, d}, sites);
              CAPTURE(a);
              CAPTURE(b);
              CAPTURE(c);
              CAPTURE(d);
              const Quadruple_vertices exact = Vertices_of_predicate::evaluate<Exact>(q);
              const std::optional<Quadruple_vertices> ball = vertices_from_balls(q);
              vertices[name].count(ball.has_value());
              if (ball) {
                CHECK(ball->rank_deficient == exact.rank_deficient);
                CHECK(ball->equidistant_curve == exact.equidistant_curve);
                REQUIRE(ball->vertices.size() == exact.vertices.size());
                for (std::size_t k = 0; k < exact.vertices.size(); ++k) {
                  const Vertex& v = ball->vertices[k];
                  CHECK(v.root() == exact.vertices[k].root());
                  REQUIRE(v.ball_coordinates() != nullptr);
                  for (int j = 0; j < 4; ++j) {
                    CAPTURE(j);
                    const Root_number<Exact> x = exact_x(exact.vertices[k], j);
                    CHECK(ball_contains((*v.ball_coordinates())[j], x));
                    const Interval box = v.coordinates<Interval>().scaled[j];
                    CHECK(compare(dyadic(box.inf()), x) != Sign::POSITIVE);
                    CHECK(compare(x, dyadic(box.sup())) != Sign::POSITIVE);
                  }
                }
              }
              for (const Vertex& v : exact.vertices) {
                const Ball_coordinates* X = v.ball_coordinates();
                if (X != nullptr)
                  for (int j = 0; j < 4; ++j) CHECK(ball_contains((*X)[j], exact_x(v, j)));
                for (const Site& s : sites) {
                  const std::optional<Sign> fast = Vertex_conflict_predicate::ball_stage(v, s);
                  const Sign sign = Vertex_conflict_predicate::evaluate<Exact>(v, s);
                  if (sign != Sign::ZERO) conflicts[name].count(fast.has_value());  // a tie never answers
                  if (fast) CHECK(*fast == sign);
                }
                const std::array<Root_number<Exact>, 4> p = exact_point(v);
                const std::array<double, 4>& rounded = v.rounded();
                for (int axis = 0; axis < 3; ++axis) {
                  CAPTURE(axis);
                  if (std::isfinite(rounded[axis])) {
                    const Sign side = v.rounding_sides()[axis];
                    CHECK(side == compare(p[axis], dyadic(rounded[axis])));
                  }
                  for (const double bound : bounds_near(rounded[axis])) {
                    Axis_box box{{-INFINITY, -INFINITY, -INFINITY}, {INFINITY, INFINITY, INFINITY}};
                    for (const bool upper : {false, true}) {
                      (upper ? box.hi : box.lo)[axis] = bound;
                      const std::optional<bool> fast = Vertex_in_box_predicate::ball_stage(v, box, {false, false, false});
                      if (compare(p[axis], dyadic(bound)) != Sign::ZERO) boxes[name].count(fast.has_value());
                      if (fast) CHECK(*fast == Vertex_in_box_predicate::evaluate<Exact>(v, box, {false, false, false}));
                      (upper ? box.hi : box.lo)[axis] = upper ? INFINITY : -INFINITY;
                    }
                  }
                }
              }
            }
      limit.stop();
    }
  }
  for (const auto& [name, c] : vertices)
    MESSAGE(name << ": balls decided " << c.answered << " of " << c.asked << " quadruples, " << conflicts[name].answered
                 << " of " << conflicts[name].asked << " conflicts, " << boxes[name].answered << " of "
                 << boxes[name].asked << " box bounds");
  // Sites one ulp off a lattice, what the stage is for: the conflicts and bounds that are no ties. Noise of
  // one ulp about 0 is subnormal (5e-324), below the balls' floor of 2^-511: those stay exact (8 % here).
  CHECK(vertices["lattice-noise"].answered * 10 > vertices["lattice-noise"].asked * 8);
  CHECK(conflicts["lattice-noise"].answered * 100 > conflicts["lattice-noise"].asked * 85);
  CHECK(boxes["lattice-noise"].answered * 100 > boxes["lattice-noise"].asked * 85);
}
