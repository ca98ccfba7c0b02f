// The filter stages after intervals for trisectors (trisector.h, curve_point.h): Mpfr_interval holds the exact
// result of every operation, and the geometry in wide and MPFR intervals from the first site of the closest
// pair has the exact geometry's kind and shape, with a canonical point's enclosure that holds arc_witness's
// exact point moved to that site: on clustered sites (wide) and on lattices one ulp off (MPFR), where plain
// intervals fail; the plain intervals' geometry, with its exact fallbacks for ties, where it decides.
#include <doctest/doctest.h>

#include <gmp.h>

#include <cmath>
#include <optional>
#include <random>
#include <string>

#include "predicates/arc_witness.h"
#include "predicates/curve_point.h"
#include "predicates/is_hidden.h"
#include "predicates/mpfr_interval.h"
#include "predicates/rational.h"
#include "predicates/rounding_guard.h"
#include "predicates/trisector_predicates.h"
#include "reference/site_generators.h"
#include "support/clustered_sites.h"
#include "support/site_triples.h"

using namespace apollonius;
using apollonius::testing::clustered_sites;
using apollonius::testing::for_each_triple;

namespace {

// The MPFR number x exactly.
Exact exact_value(mpfr_srcptr x) {
  mpz_t mantissa;
  mpz_init(mantissa);
  const long exponent = mpfr_get_z_2exp(mantissa, x);
  const Exact value = times_power_of_two(exact_integer(CGAL::Gmpz(mantissa)), static_cast<int>(exponent));
  mpz_clear(mantissa);
  return value;
}

bool holds(const Mpfr_interval& x, const Exact& value) {
  return exact_value(x.lower()) <= value && value <= exact_value(x.upper());
}

Root_number<Rational> number(const Exact& x) { return {to_rational(x), Rational(0), Rational(0), Rational(1)}; }

bool holds(const Mpfr_interval& x, const Root_number<Rational>& value) {
  return compare(value, number(exact_value(x.lower()))) != Sign::NEGATIVE &&
         compare(value, number(exact_value(x.upper()))) != Sign::POSITIVE;
}

bool holds(const Wide_interval& x, const Root_number<Rational>& value) {
  const auto bound = [&](double b) { return number(times_power_of_two(Exact(b), static_cast<int>(x.exponent()))); };
  return compare(value, bound(x.mantissa().inf())) != Sign::NEGATIVE &&
         compare(value, bound(x.mantissa().sup())) != Sign::POSITIVE;
}

// A double with a random 53-bit mantissa and binary exponent in [-300, 300], or a small integer.
double random_double(std::mt19937_64& random) {
  std::uniform_int_distribution<int> exponent(-300, 300), small(-3, 3), kind(0, 3);
  std::uniform_real_distribution<double> mantissa(-2, 2);
  if (kind(random) == 0) return small(random);
  return std::ldexp(std::round(std::ldexp(mantissa(random), 52)), exponent(random) - 52);
}

struct Framed_counts {
  int triples = 0, plain_failed = 0, decided = 0, enclosures = 0, enclosures_beyond_intervals = 0, other_origin = 0;
};

// The framed geometry in NT of the triple s against the exact one (see the file's comment).
template <class NT>
void check_framed(const std::array<Site, 3>& s, Framed_counts& counts) {
  const auto visible = [&](Site_index i, Site_index j) {
    return !is_hidden(s[i], i, s[j], j) && !is_hidden(s[j], j, s[i], i);
  };
  if (!visible(0, 1) || !visible(0, 2) || !visible(1, 2)) return;
  ++counts.triples;
  const Trisector t({0, 1, 2}, s);
  bool plain = true;
  try {
    (void)t.geometry<Interval>();
  } catch (const Uncertain_sign&) {
    plain = false;
    ++counts.plain_failed;
  }
  const Framed_trisector_geometry<NT>* framed = nullptr;
  try {
    framed = &t.framed_geometry<NT>();
  } catch (const Uncertain_sign&) {
    return;
  }
  ++counts.decided;
  const Trisector_geometry<Rational>& exact = t.geometry<Rational>();
  if (plain) {  // the intervals, with their exact fallbacks for ties (trisector.cpp, Exact_signs)
    CHECK(t.geometry<Interval>().kind == exact.kind);
    CHECK(t.geometry<Interval>().shape == exact.shape);
  }
  CHECK(framed->geometry.kind == exact.kind);
  CHECK(framed->geometry.shape == exact.shape);
  if (exact.kind != Trisector_kind::ellipse && exact.kind != Trisector_kind::hyperbola &&
      exact.kind != Trisector_kind::parabola)
    return;
  const std::optional<Framed_curve_point<NT>> enclosure = framed_enclosed_canonical_point<NT>(t);
  if (!enclosure) return;
  CHECK(enclosure->origin == framed->origin);
  ++counts.enclosures;
  counts.enclosures_beyond_intervals += !plain;
  counts.other_origin += enclosure->origin != 0;
  const Field_point<Rational> W = arc_witness(t, std::nullopt, std::nullopt).coordinates<Rational>();
  const Site &a = s[0], &o = s[static_cast<std::size_t>(enclosure->origin)];
  const double to[4] = {a.x, a.y, a.z, o.w}, from[4] = {o.x, o.y, o.z, a.w};
  for (int j = 0; j < 4; ++j) {
    CAPTURE(j);
    // X_o = X_a + 2 (p_a - p_o, w_o - w_a), over W's denominator.
    const Rational shift = Rational(2) * (Rational(to[j]) - Rational(from[j]));
    const Root_number<Rational> x{W.scaled[j].a + shift * W.denominator, W.scaled[j].b, W.discriminant, W.denominator};
    CHECK(holds(enclosure->X[j], x));
  }
}

std::string describe(const Framed_counts& c) {
  return std::to_string(c.triples) + " triples, " + std::to_string(c.plain_failed) + " beyond intervals; " +
         std::to_string(c.decided) + " decided; " + std::to_string(c.enclosures) + " canonical points enclosed, " +
         std::to_string(c.enclosures_beyond_intervals) + " where intervals failed, " + std::to_string(c.other_origin) +
         " from another origin than site 0";
}

}  // namespace

TEST_CASE("MPFR intervals hold the exact results of sums, products, quotients and square roots") {
  std::mt19937_64 random(20261202);
  int checked = 0, tight = 0, zeros = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    CAPTURE(trial);
    // Sums of products of up to 12 doubles, as the trisector's polynomials.
    Mpfr_interval total(0);
    Exact exact(0);
    for (int term = 0; term < 4; ++term) {
      Mpfr_interval product(1);
      Exact exact_product(1);
      for (int k = 1 + static_cast<int>(random() % 12); k > 0; --k) {
        const double x = random_double(random);
        product = product * Mpfr_interval(x);
        exact_product = exact_product * Exact(x);
      }
      if (random() % 2 == 0) {
        total = total - product, exact = exact - exact_product;
      } else {
        total = total + product, exact = exact + exact_product;
      }
      REQUIRE(holds(total, exact));
      ++checked;
    }
    tight += sign_if_certain(total).has_value();
    // x - x is exactly [0, 0]: ZERO is certain.
    const Mpfr_interval zero = total - total;
    if (exact_value(total.lower()) == exact_value(total.upper())) {
      CHECK(certain_sign(zero) == Sign::ZERO);
      ++zeros;
    }
    const double x = random_double(random), y = random_double(random);
    if (y != 0) {
      // q holds x / y iff q_lo y <= x <= q_hi y for y > 0 (reversed for y < 0).
      const Mpfr_interval q = Mpfr_interval(x) / Mpfr_interval(y);
      const Exact lo = exact_value(q.lower()), hi = exact_value(q.upper());
      CHECK((y > 0 ? lo * Exact(y) <= Exact(x) && Exact(x) <= hi * Exact(y)
                   : lo * Exact(y) >= Exact(x) && Exact(x) >= hi * Exact(y)));
      ++checked;
    } else {
      CHECK_THROWS_AS(Mpfr_interval(x) / Mpfr_interval(y), Uncertain_sign);
    }
    if (x > 0) {
      const Mpfr_interval r = sqrt(Mpfr_interval(x));
      CHECK(exact_value(r.lower()) * exact_value(r.lower()) <= Exact(x));
      CHECK(Exact(x) <= exact_value(r.upper()) * exact_value(r.upper()));
      ++checked;
    }
    CHECK(certain_sign(Mpfr_interval(x)) == certain_sign(x));
    Rounding_guard guard;
    const Interval i = Mpfr_interval(x).to_interval();
    CHECK((i.inf() == x && i.sup() == x));
  }
  CHECK(checked > 13000);
  CHECK(tight > 2500);  // 256 bits decide nearly every sign
  CHECK(zeros > 100);
}

TEST_CASE("the trisector's wide geometry and canonical point agree with the exact stage on clustered sites") {
  std::mt19937_64 random(20261201);
  Framed_counts counts;
  for (int trial = 0; trial < 6000; ++trial) {
    CAPTURE(trial);
    const std::vector<Site> s = clustered_sites(random, 3);
    check_framed<Wide_interval>({s[0], s[1], s[2]}, counts);
  }
  MESSAGE("wide: " << describe(counts));
  CHECK(counts.plain_failed > 400);
  CHECK(counts.decided > 1500);
  CHECK(counts.enclosures_beyond_intervals > 350);
  CHECK(counts.other_origin > 250);
}

TEST_CASE("the trisector's MPFR geometry and canonical point agree with the exact stage one ulp off a lattice") {
  Framed_counts lattice, clustered;
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    CAPTURE(seed);
    for_each_triple(generate_sites(Site_family::lattice_noise, 14, seed),
                    [&](const std::array<Site, 3>& s) { check_framed<Mpfr_interval>(s, lattice); });
  }
  std::mt19937_64 random(20261203);
  for (int trial = 0; trial < 2000; ++trial) {
    CAPTURE(trial);
    const std::vector<Site> s = clustered_sites(random, 3);
    check_framed<Mpfr_interval>({s[0], s[1], s[2]}, clustered);
  }
  MESSAGE("MPFR, lattice one ulp off: " << describe(lattice));
  MESSAGE("MPFR, clustered: " << describe(clustered));
  CHECK(lattice.plain_failed > 20);  // most ties go to the intervals' exact fallbacks
  CHECK(lattice.decided > 1350);
  CHECK(lattice.enclosures > 1350);
  CHECK(clustered.enclosures_beyond_intervals > 100);
}
