// Hand-built quadruples with known answers for the vertex predicates.
#include <doctest/doctest.h>

#include <limits>
#include <random>

#include "predicates/compare_vertices.h"
#include "support/exact_checks.h"
#include "predicates/is_hidden.h"
#include "predicates/rounding_guard.h"
#include "reference/site_generators.h"
#include "predicates/vertex_conflict.h"
#include "predicates/vertex_rounding.h"
#include "predicates/vertices_of.h"

using namespace apollonius;
using namespace apollonius::testing;

namespace {

Quadruple_vertices vertices_of_sites(const std::vector<Site>& s) { return vertices_of(make_quadruple({0, 1, 2, 3}, s)); }

// Each own site of a vertex is exactly at distance r (an identity of the construction, checked exactly).
void check_own_sites_tie(const Vertex& v) {
  for (const Site& s : v.quadruple().sites) CHECK(vertex_conflict(v, s) == Sign::ZERO);
}

}  // namespace

TEST_CASE("four equal balls on a regular tetrahedron: one vertex at the centre, r = sqrt(3) - 1") {
  const std::vector<Site> s = {{1, 1, 1, 1}, {1, -1, -1, 1}, {-1, 1, -1, 1}, {-1, -1, 1, 1}};
  const Quadruple_vertices result = vertices_of_sites(s);
  REQUIRE(result.vertices.size() == 1);
  const auto p = exact_point(result.vertices[0]);
  for (int j = 0; j < 3; ++j) CHECK(exactly_equal(p[j], dyadic(0)));
  CHECK(exactly_equal(p[3], root_number(-1, 1, 3, 1)));
  CHECK(to_nearest_double(p[3]) == 0.7320508075688773);  // sqrt(3) - 1 = 0.73205080756887729352...
  check_own_sites_tie(result.vertices[0]);
}

TEST_CASE("four coplanar sites: two mirror vertices") {
  const std::vector<Site> s = {{0, 0, 0, 1}, {4, 0, 0, 1}, {0, 4, 0, 1}, {3, 3, 0, 0.5}};
  const Quadruple_vertices result = vertices_of_sites(s);
  CHECK_FALSE(result.rank_deficient);
  REQUIRE(result.vertices.size() == 2);
  const auto p = exact_point(result.vertices[0]), q = exact_point(result.vertices[1]);
  CHECK(exactly_equal(p[0], q[0]));
  CHECK(exactly_equal(p[1], q[1]));
  CHECK(exactly_equal(p[3], q[3]));
  CHECK(exactly_equal(p[2], Root_number<Exact>{-q[2].a, -q[2].b, q[2].d, q[2].denominator}));
  CHECK(compare(p[2], dyadic(0)) != Sign::ZERO);
  CHECK(compare_vertices(result.vertices[0], result.vertices[1]) != Sign::ZERO);
  for (const Vertex& v : result.vertices) check_own_sites_tie(v);
}

TEST_CASE("tangency with discriminant 0: one vertex, in the plane of four coplanar sites") {
  // Every site is at weighted distance 2 from the origin: |p| - w = 2, and the tangent sphere touches the plane.
  const std::vector<Site> s = {{3, 0, 0, 1}, {0, 5, 0, 3}, {-4, 0, 0, 2}, {0, -6, 0, 4}};
  const Quadruple_line<Exact> line = quadruple_line<Exact>(make_quadruple({0, 1, 2, 3}, s).sites);
  CHECK(certain_sign(line.discriminant) == Sign::ZERO);
  const Quadruple_vertices result = vertices_of_sites(s);
  REQUIRE(result.vertices.size() == 1);
  CHECK(result.vertices[0].root() == Root::SINGLE);
  const auto p = exact_point(result.vertices[0]);
  for (int j = 0; j < 3; ++j) CHECK(exactly_equal(p[j], dyadic(0)));
  CHECK(exactly_equal(p[3], dyadic(2)));
}

TEST_CASE("a non-coplanar quadruple with two valid roots") {
  const std::vector<Site> s = {{0, 0, 0, 1}, {4, 0, 0, 1}, {0, 4, 0, 1}, {3, 3, 0.25, 0.5}};
  const Quadruple_line<Exact> line = quadruple_line<Exact>(make_quadruple({0, 1, 2, 3}, s).sites);
  CHECK(line.pivot == 3);  // n_3 = det(a_1, a_2, a_3) != 0: not coplanar
  const Quadruple_vertices result = vertices_of_sites(s);
  REQUIRE(result.vertices.size() == 2);
  CHECK(result.vertices[0].root() == Root::MINUS);
  CHECK(result.vertices[1].root() == Root::PLUS);
  for (const Vertex& v : result.vertices) {
    check_own_sites_tie(v);
    const auto p = rounded_coordinates(v);
    for (const Site& site : s) CHECK(std::fabs(static_cast<double>(rounded_residual(p, site))) < 1e-12);
  }
}

TEST_CASE("a root with r + w < 0 for one of its sites is not a vertex") {
  // Equal weights: the root with negative r + w (the circumcentre at distance -|u|) is rejected.
  const std::vector<Site> s = {{0, 0, 0, 1}, {2, 0, 0, 1}, {0, 2, 0, 1}, {0, 0, 2, 1}};
  const Quadruple_vertices result = vertices_of_sites(s);
  REQUIRE(result.vertices.size() == 1);
  const auto p = exact_point(result.vertices[0]);
  for (int j = 0; j < 3; ++j) CHECK(exactly_equal(p[j], dyadic(1)));
  CHECK(exactly_equal(p[3], root_number(-1, 1, 3, 1)));
}

TEST_CASE("rank-deficient quadruples have no isolated vertex") {
  SUBCASE("collinear centres") {
    const Quadruple_vertices r = vertices_of_sites({{0, 0, 0, 1}, {1, 0, 0, 1}, {3, 0, 0, 2}, {7, 0, 0, 1}});
    CHECK(r.rank_deficient);
    CHECK(r.vertices.empty());
  }
  SUBCASE("coplanar cocircular centres with equal weights: the equidistant set is the circle's axis") {
    const Quadruple_vertices r = vertices_of_sites({{5, 0, 0, 1}, {0, 5, 0, 1}, {-3, 4, 0, 1}, {4, -3, 0, 1}});
    CHECK(r.rank_deficient);
    CHECK(r.vertices.empty());
  }
  SUBCASE("coplanar centres, weights an affine function of the position") {
    const Quadruple_vertices r = vertices_of_sites({{0, 0, 0, 1}, {1, 0, 0, 1.5}, {0, 1, 0, 1.25}, {2, 3, 0, 2.75}});
    CHECK(r.rank_deficient);
  }
}

TEST_CASE("vertex_conflict decides closer, tied and farther sites exactly") {
  const std::vector<Site> s = {{1, 1, 1, 1}, {1, -1, -1, 1}, {-1, 1, -1, 1}, {-1, -1, 1, 1}};
  const Vertex v = vertices_of_sites(s).vertices.at(0);  // centre 0, r = sqrt 3 - 1, weighted distance to sites
  // A site at distance sqrt(3) from the centre ties when w = 1, is closer when w > 1, farther when w < 1.
  CHECK(vertex_conflict(v, Site{1, -1, 1, 1}) == Sign::ZERO);
  CHECK(vertex_conflict(v, Site{1, -1, 1, 1.0000000000000002}) == Sign::NEGATIVE);
  CHECK(vertex_conflict(v, Site{1, -1, 1, 0.99999999999999989}) == Sign::POSITIVE);
  // r + w_s < 0: a ball of very negative weight can never be closer.
  CHECK(vertex_conflict(v, Site{0, 0, 0, -5}) == Sign::POSITIVE);
  // A site centred at the vertex is at weighted distance -w: farther than r = 0.732... for w = -0.75,
  // closer for w = -0.5.
  CHECK(vertex_conflict(v, Site{0, 0, 0, -0.75}) == Sign::POSITIVE);
  CHECK(vertex_conflict(v, Site{0, 0, 0, -0.5}) == Sign::NEGATIVE);
}

TEST_CASE("is_hidden: containment, internal tangency, duplicates") {
  const Site big{0, 0, 0, 3}, inside{1, 0, 0, 1}, tangent_inside{2, 0, 0, 1}, outside{2.5, 0, 0, 1};
  CHECK(is_hidden(inside, 1, big, 0));
  CHECK(is_hidden(tangent_inside, 1, big, 0));
  CHECK_FALSE(is_hidden(outside, 1, big, 0));
  CHECK_FALSE(is_hidden(big, 0, inside, 1));
  CHECK(is_hidden(big, 5, big, 2));
  CHECK_FALSE(is_hidden(big, 2, big, 5));
  // Tangent inside only up to the last bit: 2 + 2^-51 is outside.
  CHECK_FALSE(is_hidden(Site{2.0000000000000004, 0, 0, 1}, 1, big, 0));
}

TEST_CASE("exact_integer keeps the sign and zero (CGAL 5.5's Mpzf(Gmpz) drops both)") {
  const CGAL::Gmpz big = CGAL::Gmpz(1) << 200;
  CHECK(exact_integer(CGAL::Gmpz(0)).is_zero());
  CHECK(exact_integer(CGAL::Gmpz(-6)) == Exact(-6));
  CHECK(exact_integer(CGAL::Gmpz(7)) == Exact(7));
  CHECK(exact_integer(-big) + exact_integer(big) == Exact(0));
  CHECK(exact_integer(-big - 1) < Exact(-std::ldexp(1.0, 200)));
  CHECK(exact_integer(-big - 1) + Exact(std::ldexp(1.0, 200)) == Exact(-1));
}

TEST_CASE("enclosing_interval keeps the caller's rounding") {
  // Under a Rounding_guard, Interval's operations round outwards only while the mode stays upward: 1/3
  // then has distinct bounds, and a product of exact doubles that is not a double is strictly inside.
  Rounding_guard guard;
  const Interval before = Interval(1) / Interval(3);
  REQUIRE(before.inf() < before.sup());
  for (const Exact& x : {Exact(0.1) * Exact(0.1), Exact(std::ldexp(1.5, -1000)) * Exact(std::ldexp(1.0, -1000)),
                         Exact(std::ldexp(1.5, 1000)) * Exact(std::ldexp(1.0, 1000)), Exact(-3)}) {
    (void)enclosing_interval(x);
    const Interval third = Interval(1) / Interval(3);
    CHECK(third.inf() < third.sup());
    const Interval product = Interval(1.0000000000000002) * Interval(3.0131568673200204e+137);
    CHECK(product.inf() < product.sup());
  }
}

// The input where the lost rounding showed (fuzz_vertices, 2026-11-28): the brute force, which does not
// normalize the scale, reported the root of sites 0 1 3 4 at about (-7.25, -0.5, -9.7e90), to which site 2
// is closer by 6.2e-91 (a 400-digit evaluation). Its box, built from the exact coordinates, excluded the
// true y after the rounding was lost, and the interval stage of vertex_conflict then certified POSITIVE.
TEST_CASE("vertex_conflict at a root near 1e91 under every scaling") {
  const double raw[5][4] = {{-4, 3, -4, -4}, {-3.75, -3.75, -4, -4}, {-4, 0, -4, -4},
                            {-4, -8.8310950986181268e+45, -4.0000000000000009, 1.893406184664404e-55}, {-4, -4, -3, -3}};
  for (int k : {0, -50, -100, -200, -600, 50, 100, 200}) {
    CAPTURE(k);
    std::vector<Site> sites;
    for (const auto& r : raw) sites.push_back({std::ldexp(r[0], k), std::ldexp(r[1], k), std::ldexp(r[2], k), std::ldexp(r[3], k)});
    const Quadruple_vertices roots = vertices_of(make_quadruple({0, 1, 3, 4}, sites));
    REQUIRE(roots.vertices.size() == 1);
    CHECK(vertex_conflict(roots.vertices[0], sites[2]) == Sign::NEGATIVE);
    const Vertex exact_built = Vertices_of_predicate::evaluate<Exact>(make_quadruple({0, 1, 3, 4}, sites)).vertices[0];
    const std::array<Interval, 4> box = exact_built.point_interval();
    CHECK((box[1].inf() <= std::ldexp(-0.5, k) && std::ldexp(-0.5, k) <= box[1].sup()));
  }
}

TEST_CASE("enclosing_interval contains exact values beyond the double range") {
  Rounding_guard guard;
  const Exact huge = Exact(std::ldexp(1.5, 1000)) * Exact(std::ldexp(1.0, 1000));
  const Exact tiny = Exact(std::ldexp(1.5, -1000)) * Exact(std::ldexp(1.0, -1000));
  const Interval h = enclosing_interval(huge), t = enclosing_interval(tiny), n = enclosing_interval(-huge);
  CHECK(h.inf() == std::numeric_limits<double>::max());
  CHECK(std::isinf(h.sup()));
  CHECK(t.inf() == 0);
  CHECK(t.sup() > 0);
  CHECK(std::isinf(n.inf()));
  CHECK(n.sup() == -std::numeric_limits<double>::max());
  CHECK_THROWS_AS(certain_sign(t - Interval(0)), Uncertain_sign);
  const Interval tenth = enclosing_interval(Exact(1) * Exact(0.1));
  CHECK(tenth.inf() <= 0.1);
  CHECK(tenth.sup() >= 0.1);
  CHECK(tenth.sup() <= std::nextafter(0.1, 1.0));
  // 0.1^2 is not a double: strictly inside, within an ulp or two.
  const Exact square = Exact(0.1) * Exact(0.1);
  const Interval hundredth = enclosing_interval(square);
  CHECK(Exact(hundredth.inf()) < square);
  CHECK(square < Exact(hundredth.sup()));
  CHECK(hundredth.sup() <= std::nextafter(std::nextafter(hundredth.inf(), 1.0), 1.0));
  // Below the subnormal range in either sign, in the guard's upward rounding.
  const Interval negative_tiny = enclosing_interval(-tiny);
  CHECK(negative_tiny.sup() == 0);
  CHECK(negative_tiny.inf() < 0);
}

// The a priori bound of the first stage (double_with_magnitude.h) against the exact line, on every value
// quadruple_line computes, for quadruples of every generator family: lattices and cospherical sites cancel
// to exact zeros, scaled families sit at 2^+-300.
TEST_CASE("the first stage's a priori bounds hold on every value of the line") {
  std::size_t checked = 0;
  for (const std::string& name : site_family_names()) {
    for (std::uint64_t seed = 1; seed <= 60; ++seed) {
      CAPTURE(name);
      CAPTURE(seed);
      const std::vector<Site> sites = generate_sites(site_family_from_name(name), 12, seed);
      std::mt19937_64 random(seed);
      for (int trial = 0; trial < 40; ++trial) {
        std::array<Site_index, 4> pick{};
        for (Site_index& i : pick) i = static_cast<Site_index>(random() % sites.size());
        std::sort(pick.begin(), pick.end());
        if (std::adjacent_find(pick.begin(), pick.end()) != pick.end()) continue;
        const Quadruple q = make_quadruple(pick, sites);
        const Quadruple_line<Exact> exact = quadruple_line<Exact>(q.sites);
        Quadruple_line<Double_with_magnitude> fast;
        try {
          fast = quadruple_line<Double_with_magnitude>(q.sites);
        } catch (const Uncertain_sign&) {
          continue;  // no certain pivot: the next stage decides
        }
        REQUIRE(fast.pivot == exact.pivot);
        const auto within = [&](const Double_with_magnitude& x, const Exact& e) {
          if (!std::isfinite(x.error_bound())) return;  // overflowed: no sign is ever certain
          CAPTURE(x.value);
          CAPTURE(x.magnitude);
          const Exact distance = Exact(x.value) - e;
          CHECK(CGAL::abs(distance) <= Exact(x.error_bound()));
          ++checked;
        };
        for (int j = 0; j < 4; ++j) within(fast.n[j], exact.n[j]);
        if (fast.pivot < 0) continue;
        for (int j = 0; j < 4; ++j) within(fast.Q[j], exact.Q[j]);
        within(fast.A, exact.A);
        within(fast.B, exact.B);
        within(fast.C, exact.C);
        within(fast.discriminant, exact.discriminant);
      }
    }
  }
  MESSAGE(checked << " values within their bound");
  CHECK(checked > 100000);
}


TEST_CASE("the first stage decides equal balls in one lattice plane (exact zeros of n) without the later stages") {
  // Coplanar centres: n_3 (their orientation) is 0; equal weights: so are n_0, n_1, n_2 (the weight column).
  const std::array<Site, 4> sites{{{0, 0, 4, 1.5}, {4, 0, 4, 1.5}, {0, 8, 4, 1.5}, {12, 4, 4, 1.5}}};
  const Quadruple q = make_quadruple({0, 1, 2, 3}, std::vector<Site>(sites.begin(), sites.end()));
  const std::optional<Quadruple_vertices> fast = Vertices_of_predicate::static_filter(q);
  REQUIRE(fast.has_value());
  CHECK(fast->rank_deficient);
  CHECK(Vertices_of_predicate::evaluate<Exact>(q).rank_deficient);
  // Equal balls off the plane: n_0 = n_1 = n_2 = 0 exactly, n_3 pivots; the vertex is found at once.
  const std::array<Site, 4> spread{{{0, 0, 0, 1.5}, {4, 0, 0, 1.5}, {0, 4, 0, 1.5}, {0, 0, 4, 1.5}}};
  const Quadruple r = make_quadruple({0, 1, 2, 3}, std::vector<Site>(spread.begin(), spread.end()));
  const std::optional<Quadruple_vertices> found = Vertices_of_predicate::static_filter(r);
  REQUIRE(found.has_value());
  CHECK(found->vertices.size() == Vertices_of_predicate::evaluate<Exact>(r).vertices.size());
}

TEST_CASE("the exact pivot rule agrees with the exact line's pivot on every family") {
  std::size_t decided_exactly = 0, quadruples = 0;
  for (const std::string& name : site_family_names()) {
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
      CAPTURE(name);
      CAPTURE(seed);
      const std::vector<Site> sites = generate_sites(site_family_from_name(name), 10, seed);
      for (Site_index a = 0; a < 4; ++a)
        for (Site_index b = a + 1; b < 6; ++b)
          for (Site_index c = b + 1; c < 8; ++c)
            for (Site_index d = c + 1; d < 10; ++d) {
              const Quadruple q = make_quadruple({a, b, c, d}, sites);
              const Quadruple_line<Exact> exact = quadruple_line<Exact>(q.sites);
              const auto line = quadruple_line<Double_with_magnitude>(q.sites, Pivot_exact_where_uncertain{});
              CHECK(line.pivot == exact.pivot);
              ++quadruples;
              for (int k = 0; k < 4; ++k) {
                CHECK(null_vector_entry_nonzero(q.sites, k) == (certain_sign(exact.n[k]) != Sign::ZERO));
                if (!certainly_nonzero(line.n[k])) ++decided_exactly;
              }
            }
    }
  }
  MESSAGE(decided_exactly << " entries of n left to the exact test in " << quadruples << " quadruples");
  CHECK(decided_exactly > 1000);
}

TEST_CASE("Double_with_magnitude: the depths of quadruple_line's values are those of docs/ERROR_BOUNDS.md") {
  const std::array<Site, 4> sites{{{0, 0, 0, 1}, {3, 0, 0, 2}, {0, 4, 0, 1.5}, {1, 1, 5, 0.5}}};
  const Quadruple_line<Depth_count> line = quadruple_line<Depth_count>(sites);
  REQUIRE(line.pivot == 3);
  for (int j = 0; j < 4; ++j) CHECK(line.n[j].depth == 8);
  for (const int j : {0, 1, 2}) CHECK(line.Q[j].depth == 13);
  CHECK(line.A.depth == 20);
  CHECK(line.B.depth == 25);
  CHECK(line.C.depth == 30);
  CHECK(line.discriminant.depth == 52);
  CHECK(kQuadrupleLineDepth == 52);  // the deepest, which every bound uses
}

TEST_CASE("line_roots answers nothing, not a guess, where a filter's sign of A, B, C or the discriminant is uncertain") {
  Rounding_guard guard;
  const Interval straddling(-1, 1), positive(1, 2), negative(-2, -1), zero(0);
  const auto line_with = [&](Interval A, Interval B, Interval C, Interval discriminant) {
    Quadruple_line<Interval> line;
    line.pivot = 3;
    line.A = A, line.B = B, line.C = C, line.discriminant = discriminant;
    return line;
  };
  CHECK_FALSE(line_roots(line_with(straddling, positive, positive, positive)).has_value());
  CHECK_FALSE(line_roots(line_with(positive, positive, positive, straddling)).has_value());
  CHECK_FALSE(line_roots(line_with(zero, straddling, positive, positive)).has_value());
  CHECK_FALSE(line_roots(line_with(zero, zero, straddling, positive)).has_value());
  // Certain signs: two roots over a positive denominator, however A's sign was; one root from B; a ray.
  const std::optional<Line_roots<Interval>> two = line_roots(line_with(negative, positive, positive, positive));
  REQUIRE(two.has_value());
  REQUIRE(two->roots.size() == 2);
  for (const Line_root<Interval>& r : two->roots) CHECK(r.lambda.denominator.inf() > 0);
  CHECK(line_roots(line_with(positive, positive, positive, negative))->roots.empty());
  const std::optional<Line_roots<Interval>> one = line_roots(line_with(zero, negative, positive, positive));
  REQUIRE(one.has_value());
  REQUIRE(one->roots.size() == 1);
  CHECK(one->roots[0].root == Root::SINGLE);
  CHECK(one->roots[0].lambda.denominator.inf() > 0);
  CHECK(line_roots(line_with(zero, zero, zero, positive))->whole_line_on_cone);
  CHECK_FALSE(line_roots(line_with(zero, zero, negative, positive))->whole_line_on_cone);
  // Double_with_error: a value within its bound of 0 is uncertain.
  Quadruple_line<Double_with_error> unsure;
  unsure.pivot = 3;
  unsure.A = Double_with_error(1e-20, 1e-19);
  CHECK_FALSE(line_roots(unsure).has_value());
  CHECK_THROWS_AS(certain_sign(unsure.A), Uncertain_sign);
}

TEST_CASE("a line of nearly coplanar centres parametrized by its largest entry keeps the pivot's root labels") {
  // Sites 5e-324 or an ulp off a lattice plane: n_3 is tiny, and lambda = X_3 barely separates the mirror roots.
  std::mt19937_64 random(20261203);
  std::uniform_int_distribution<int> step(-1, 1), cell(0, 3), weight(0, 1), plane(0, 1);
  std::size_t quadruples = 0, decided = 0, two_roots = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    CAPTURE(trial);
    const double x = plane(random) ? 0.0 : 8.0;
    std::vector<Site> s;
    for (int m = 0; m < 4; ++m) {
      const int off = step(random);
      const double moved = off == 0 ? x : std::nextafter(x, off * std::numeric_limits<double>::infinity());
      s.push_back({moved, 4.0 * cell(random), 4.0 * cell(random), weight(random) ? 1.5 : 1.0});
    }
    bool distinct = true;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) distinct = distinct && !is_hidden(s[i], i, s[j], j) && !is_hidden(s[j], j, s[i], i);
    if (!distinct) continue;
    ++quadruples;
    const Quadruple q = make_quadruple({0, 1, 2, 3}, s);
    std::optional<Quadruple_vertices> conditioned;
    {
      Rounding_guard guard;
      conditioned = Vertices_of_predicate::conditioned_vertices(q);
    }
    if (!conditioned) continue;
    ++decided;
    const Quadruple_vertices exact = Vertices_of_predicate::evaluate<Exact>(q);
    CHECK(conditioned->rank_deficient == exact.rank_deficient);
    CHECK(conditioned->equidistant_curve == exact.equidistant_curve);
    REQUIRE(conditioned->vertices.size() == exact.vertices.size());
    const Quadruple_line<Exact> line = exact_quadruple_line(q.sites);
    for (std::size_t i = 0; i < exact.vertices.size(); ++i) {
      const Vertex &u = conditioned->vertices[i], &v = exact.vertices[i];
      CHECK(u.root() == v.root());
      const std::array<Interval, 4> a = u.point_interval(), b = v.point_interval();
      for (int j = 0; j < 4; ++j) CHECK((a[j].inf() <= b[j].sup() && b[j].inf() <= a[j].sup()));
    }
    two_roots += exact.vertices.size() == 2 && line.pivot == 3;
  }
  MESSAGE(decided << " of " << quadruples << " quadruples decided by the conditioned line, " << two_roots
                  << " with two roots at pivot 3");
  CHECK(decided * 2 > quadruples);
  CHECK(two_roots > 100);
}
