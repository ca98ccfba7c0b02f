// Wide_interval (wide_interval.h) holds the exact value of every operation over the whole exponent range,
// and vertices_of's wide stage agrees with the exact stage on sites spread from 5e-324 to 1e300, where
// plain intervals fail.
#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <random>

#include "predicates/is_hidden.h"
#include "predicates/rounding_guard.h"
#include "predicates/vertex_conflict.h"
#include "predicates/vertices_of.h"
#include "predicates/wide_interval.h"
#include "support/clustered_sites.h"

using namespace apollonius;
using apollonius::testing::clustered_sites;

namespace {

// A double of random sign, mantissa and binary exponent in [-1074, 1000] (subnormals included).
double spread_double(std::mt19937_64& random) {
  std::uniform_int_distribution<int> exponent(-1074, 1000), sign(0, 1), small(0, 3);
  std::uniform_real_distribution<double> mantissa(1, 2);
  if (small(random) == 0) return (sign(random) ? -1 : 1) * static_cast<double>(small(random));  // 0 to 3
  const double x = std::ldexp(std::round(std::ldexp(mantissa(random), 52)), exponent(random) - 52);
  return sign(random) ? -x : x;
}

// inf 2^e <= x <= sup 2^e, exactly.
bool holds(const Wide_interval& w, const Exact& x) {
  const int e = static_cast<int>(w.exponent());
  const Interval& m = w.mantissa();
  return (std::isinf(m.inf()) || times_power_of_two(Exact(m.inf()), e) <= x) &&
         (std::isinf(m.sup()) || x <= times_power_of_two(Exact(m.sup()), e));
}

struct Both {
  Wide_interval wide;
  Exact exact;
};

// Whether each exact X_j lies in the vertex's plain box, and in its scaled box where there is one.
bool boxes_hold(const Vertex& filtered, const Vertex& exact) {
  const Vertex_coordinates<Exact>& X = exact.coordinates<Exact>();
  for (int j = 0; j < 4; ++j) {
    const Root_number<Exact> x{X.scaled[j].a, X.scaled[j].b, X.discriminant, X.denominator};
    const auto within = [&](const Interval& box, long k) {
      const auto bound = [&](double b) {
        return Root_number<Exact>{times_power_of_two(Exact(b), static_cast<int>(k)), Exact(0), Exact(0), Exact(1)};
      };
      return (std::isinf(box.inf()) || compare(x, bound(box.inf())) != Sign::NEGATIVE) &&
             (std::isinf(box.sup()) || compare(x, bound(box.sup())) != Sign::POSITIVE);
    };
    if (!within(filtered.coordinates<Interval>().scaled[j], 0)) return false;
    if (const Scaled_box* box = filtered.scaled_box())
      if (!within(box->scaled[j], box->exponent)) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("wide intervals hold the exact results of sums and products of degree up to 16 across the range") {
  std::mt19937_64 random(20261128);
  std::uniform_int_distribution<int> operation(0, 3);
  int checked = 0, narrow = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    CAPTURE(trial);
    // A random polynomial: products of up to 16 leaves, then sums of such products, as the line's minors.
    Both total{Wide_interval(0), Exact(0)};
    for (int term = 0; term < 4; ++term) {
      Both product{Wide_interval(1), Exact(1)};
      const int degree = 1 + static_cast<int>(random() % 16);
      for (int k = 0; k < degree; ++k) {
        const double x = spread_double(random);
        Rounding_guard guard;
        product = {product.wide * Wide_interval(x), product.exact * Exact(x)};
      }
      Rounding_guard guard;
      if (operation(random) == 0)
        total = {total.wide - product.wide, total.exact - product.exact};
      else
        total = {total.wide + product.wide, total.exact + product.exact};
      REQUIRE(holds(total.wide, total.exact));
      ++checked;
    }
    Rounding_guard guard;
    const Interval& m = total.wide.mantissa();
    if (m.sup() - m.inf() <= 0x1p-40) ++narrow;
  }
  CHECK(checked == 12000);
  CHECK(narrow > 2000);  // most sums do not cancel: the enclosure stays tight
}

TEST_CASE("wide intervals: quotients, square roots and signs hold the exact value") {
  std::mt19937_64 random(7);
  int checked = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    CAPTURE(trial);
    const double x = spread_double(random), y = spread_double(random);
    Rounding_guard guard;
    const Wide_interval wx(x), wy(y);
    if (y != 0) {
      // x / y holds q iff q y = x for the real quotient: check q_lo <= x / y <= q_hi by multiplying out.
      const Wide_interval q = wx / wy;
      const int e = static_cast<int>(q.exponent());
      const Exact lo = times_power_of_two(Exact(q.mantissa().inf()), e), hi = times_power_of_two(Exact(q.mantissa().sup()), e);
      const Exact ex(x), ey(y);
      const bool positive = y > 0;
      CHECK((positive ? lo * ey <= ex : lo * ey >= ex));
      CHECK((positive ? ex <= hi * ey : ex >= hi * ey));
      ++checked;
    }
    if (x > 0) {
      const Wide_interval r = sqrt(wx);
      const int e = static_cast<int>(r.exponent());
      const Exact lo = times_power_of_two(Exact(r.mantissa().inf()), e), hi = times_power_of_two(Exact(r.mantissa().sup()), e);
      CHECK(lo * lo <= Exact(x));
      CHECK(Exact(x) <= hi * hi);
      ++checked;
    }
    CHECK(certain_sign(wx) == certain_sign(x));
    CHECK(holds(wx, Exact(x)));
    const Interval back = wx.to_interval();
    CHECK((back.inf() == x && back.sup() == x));
  }
  CHECK(checked > 15000);
  Rounding_guard guard;
  CHECK_THROWS_AS(Wide_interval(1) / (Wide_interval(1) - Wide_interval(1)), Uncertain_sign);
  const Wide_interval straddling = Wide_interval(1) + Wide_interval(0x1p-60) - Wide_interval(1);
  CHECK_THROWS_AS(certain_sign(straddling - Wide_interval(0x1p-60)), Uncertain_sign);  // never ZERO
}

TEST_CASE("vertices_of's wide stage agrees with the exact stage on sites from 5e-324 to 1e300") {
  std::mt19937_64 random(20261129);
  std::uniform_int_distribution<int> exponent(-1074, 1000), small(-4, 4);
  int decided = 0, undecided = 0, plain_failed = 0, vertices = 0, scaled = 0, gate_open = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    CAPTURE(trial);
    std::array<Site, 4> s;
    for (Site& site : s) {
      // Each site at its own scale, as in the fuzz inputs that spent seconds in the exact stage.
      const double scale = std::ldexp(1.0, exponent(random));
      site = {scale * small(random), scale * small(random), scale * small(random), scale * std::abs(small(random)) / 4};
    }
    const Quadruple q = make_quadruple({0, 1, 2, 3}, {s.begin(), s.end()});
    gate_open += Vertices_of_predicate::may_leave_double_range(q);
    std::optional<Quadruple_vertices> wide;
    {
      Rounding_guard guard;
      try {
        (void)Vertices_of_predicate::evaluate<Interval>(q);
      } catch (const Uncertain_sign&) {
        ++plain_failed;
      }
      try {
        wide = Vertices_of_predicate::evaluate<Wide_interval>(q);
      } catch (const Uncertain_sign&) {
      }
    }
    if (!wide) {
      ++undecided;
      continue;
    }
    ++decided;
    const Quadruple_vertices exact = Vertices_of_predicate::evaluate<Exact>(q);
    CHECK(wide->rank_deficient == exact.rank_deficient);
    CHECK(wide->equidistant_curve == exact.equidistant_curve);
    REQUIRE(wide->vertices.size() == exact.vertices.size());
    for (std::size_t r = 0; r < exact.vertices.size(); ++r) {
      const Vertex& w = wide->vertices[r];
      CHECK(w.root() == exact.vertices[r].root());
      ++vertices;
      // The exact X lies in the plain box, and in the scaled box where there is one.
      const Vertex_coordinates<Exact>& X = exact.vertices[r].coordinates<Exact>();
      for (int j = 0; j < 4; ++j) {
        const Root_number<Exact> x{X.scaled[j].a, X.scaled[j].b, X.discriminant, X.denominator};
        const auto within = [&](const Interval& box, long k) {
          const auto bound = [&](double b) { return Root_number<Exact>{times_power_of_two(Exact(b), static_cast<int>(k)), Exact(0), Exact(0), Exact(1)}; };
          return (std::isinf(box.inf()) || compare(x, bound(box.inf())) != Sign::NEGATIVE) &&
                 (std::isinf(box.sup()) || compare(x, bound(box.sup())) != Sign::POSITIVE);
        };
        CHECK(within(w.coordinates<Interval>().scaled[j], 0));
        if (const Scaled_box* box = w.scaled_box()) CHECK(within(box->scaled[j], box->exponent));
      }
      scaled += w.scaled_box() != nullptr;
    }
  }
  MESSAGE("wide stage: " << decided << " decided, " << undecided << " not; plain intervals failed on " << plain_failed
                         << "; " << vertices << " vertices, " << scaled << " with a scaled box");
  CHECK(gate_open > 3800);  // vertices_of tries the wide stage on these
  CHECK(plain_failed > 2000);
  CHECK(decided > 1500);  // most of the rest tie exactly (a coordinate 0 in one site in nine)
  CHECK(vertices > 1000);
  CHECK(scaled > 100);
}

TEST_CASE("the wide stage is tried only where the relative coordinates may leave the double range") {
  const double tiny = std::numeric_limits<double>::denorm_min();
  // One ulp off a lattice: nearly degenerate, of ordinary size; wide intervals would fail as plain ones do.
  const std::vector<Site> nudged = {{0, 0, tiny, 1}, {4, 0, 0, 1}, {0, std::nextafter(4.0, 5.0), tiny, 1.5}, {4, 4, 0, 1}};
  CHECK_FALSE(Vertices_of_predicate::may_leave_double_range(make_quadruple({0, 1, 2, 3}, nudged)));
  const std::vector<Site> spread = {{0, 0, 0, 1}, {1e266, 0, 0, 1}, {0, 1, 0, 0}, {0, 0, 1, 0}};
  CHECK(Vertices_of_predicate::may_leave_double_range(make_quadruple({0, 1, 2, 3}, spread)));
  const std::vector<Site> small = {{0, 0, 0, 0}, {1e-300, 0, 0, 0}, {0, 1e-300, 0, 0}, {0, 0, 1e-300, 0}};
  CHECK(Vertices_of_predicate::may_leave_double_range(make_quadruple({0, 1, 2, 3}, small)));
  const std::vector<Site> overflowing = {{-1.7e308, 0, 0, 0}, {1.7e308, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
  CHECK(Vertices_of_predicate::may_leave_double_range(make_quadruple({0, 1, 2, 3}, overflowing)));
}

// The wide stage from another origin (vertices_of.h): any site of the quadruple may be the line's origin,
// and the vertices, moved back to site 0, keep the exact stage's root labels, and their boxes hold them.
TEST_CASE("vertices_of's wide stage from any origin agrees with the exact stage on clustered sites") {
  std::mt19937_64 random(20261130);
  int decided = 0, vertices = 0, only_from_other_origin = 0;
  for (int trial = 0; trial < 6000; ++trial) {
    CAPTURE(trial);
    const std::vector<Site> sites = clustered_sites(random, 4);
    const Quadruple q = make_quadruple({0, 1, 2, 3}, sites);
    const Quadruple_vertices exact = Vertices_of_predicate::evaluate<Exact>(q);
    bool from_origin_0 = false;
    {
      Rounding_guard guard;
      try {
        const Quadruple_line<Wide_interval> line = quadruple_line<Wide_interval>(q.sites);
        from_origin_0 = Vertices_of_predicate::vertices_on_line_if_certain(line, q).has_value();
      } catch (const Uncertain_sign&) {
      }
    }
    for (int m = 1; m < 4; ++m) {
      CAPTURE(m);
      std::optional<Quadruple_vertices> wide;
      {
        Rounding_guard guard;
        try {
          wide = Vertices_of_predicate::wide_vertices_from_origin(q, m);
        } catch (const Uncertain_sign&) {
        }
      }
      if (!wide) continue;
      ++decided;
      only_from_other_origin += !from_origin_0;
      CHECK(wide->rank_deficient == exact.rank_deficient);
      CHECK(wide->equidistant_curve == exact.equidistant_curve);
      REQUIRE(wide->vertices.size() == exact.vertices.size());
      for (std::size_t r = 0; r < exact.vertices.size(); ++r) {
        CHECK(wide->vertices[r].root() == exact.vertices[r].root());
        CHECK(boxes_hold(wide->vertices[r], exact.vertices[r]));
        ++vertices;
      }
    }
  }
  MESSAGE("wide stage from sites 1 to 3: " << decided << " decided, " << vertices << " vertices, "
                                           << only_from_other_origin << " where origin 0 was not certain");
  CHECK(decided > 8000);
  CHECK(vertices > 600);
  CHECK(only_from_other_origin > 1500);
}

// vertex_conflict's and is_hidden's wide stages answer only the exact sign, and decide where a cluster's
// site lies a hair from a vertex's site (vertex_conflict.h).
TEST_CASE("vertex_conflict's and is_hidden's wide stages agree with the exact stage on clustered sites") {
  std::mt19937_64 random(20261131);
  int conflicts = 0, conflicts_beyond_intervals = 0, hidden = 0, hidden_beyond_intervals = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    CAPTURE(trial);
    const std::vector<Site> sites = clustered_sites(random, 8);
    const Quadruple q = make_quadruple({0, 1, 2, 3}, sites);
    const Quadruple_vertices exact = Vertices_of_predicate::evaluate<Exact>(q);
    for (const Vertex& v : exact.vertices)
      for (std::size_t t = 4; t < sites.size(); ++t) {
        CAPTURE(t);
        std::optional<Sign> interval, wide;
        {
          Rounding_guard guard;
          interval = Vertex_conflict_predicate::interval_stage(v, sites[t]);
          wide = Vertex_conflict_predicate::wide_stage(v, sites[t]);
        }
        if (!wide) continue;
        CHECK(*wide == Vertex_conflict_predicate::evaluate<Exact>(v, sites[t]));
        ++conflicts;
        conflicts_beyond_intervals += !interval;
      }
    for (Site_index i = 0; i < sites.size(); ++i)
      for (Site_index j = 0; j < sites.size(); ++j) {
        if (i == j) continue;
        std::optional<bool> interval, wide;
        {
          Rounding_guard guard;
          try {
            interval = Is_hidden_predicate::evaluate<Interval>(sites[i], i, sites[j], j);
          } catch (const Uncertain_sign&) {
          }
          wide = Is_hidden_predicate::wide_stage(sites[i], i, sites[j], j);
        }
        if (!wide) continue;
        CHECK(*wide == Is_hidden_predicate::evaluate<Exact>(sites[i], i, sites[j], j));
        ++hidden;
        hidden_beyond_intervals += !interval;
      }
  }
  MESSAGE("vertex_conflict: " << conflicts << " decided, " << conflicts_beyond_intervals
                              << " beyond the intervals; is_hidden: " << hidden << ", " << hidden_beyond_intervals);
  CHECK(conflicts > 1500);
  CHECK(conflicts_beyond_intervals > 800);
  CHECK(hidden > 150000);
  CHECK(hidden_beyond_intervals > 15000);
}
