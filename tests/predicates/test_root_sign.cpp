// Brute force against MPFR for the exact sign helpers of predicates/root_sign.h
// (sign_of_root_number, sign_of_two_root_sum, compare) with NT = Exact and NT = Interval, and for
// to_nearest_double of predicates/correct_rounding.h.
//
// Every input is an integer times a power of two (what the exact type holds), so the oracle of mpfr_oracle.h is
// rigorous: a root-number value is, up to a power of two, an algebraic integer, whose norm separates it
// from zero; MPFR at >= 1000 bits (more when the separation bound needs it) then certifies its sign.
// The Interval stage may throw Uncertain_sign but must never return a wrong sign (ZERO included).
//
// Each family of cases is one TEST_CASE, which asserts its own counts: the cases it ran, the zeros it
// found (all, none, some, or as many as elementary algebra predicts), and for random values that the
// Interval stage nearly always decides. A failure prints the family, the case index and its seed, and
// the inputs. The cases depend only on the base seed, which the environment variable
// APOLLONIUS_ROOT_SIGN_SEED overrides.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <limits>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "predicates/correct_rounding.h"
#include "support/mpfr_oracle.h"
#include "predicates/root_sign.h"
#include "predicates/rounding_guard.h"

namespace doctest {
template <>
struct StringMaker<apollonius::Sign> {
  static String convert(apollonius::Sign s) { return apollonius::to_string(s); }
};
}  // namespace doctest

namespace {

using apollonius::Exact;
using apollonius::Interval;
using apollonius::Root_number;
using apollonius::Sign;
using apollonius::to_int;
using oracle::Dy;
using oracle::dy;
using oracle::Random;
using oracle::scaled;
using oracle::Z;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kMax = std::numeric_limits<double>::max();
constexpr double kDenormMin = std::numeric_limits<double>::denorm_min();

std::uint64_t base_seed() {
  static const std::uint64_t seed = [] {
    const char* env = std::getenv("APOLLONIUS_ROOT_SIGN_SEED");
    return env != nullptr ? std::strtoull(env, nullptr, 0) : std::uint64_t{0x5eed2024};
  }();
  return seed;
}

std::uint64_t family_hash(const char* name) {  // FNV-1a
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (const char* c = name; *c != '\0'; ++c) h = (h ^ static_cast<unsigned char>(*c)) * 0x100000001b3ull;
  return h;
}

// How a case was made: zero or nonzero by construction, or unknown (random; then the algebraic test of
// the oracle decides, independently of MPFR).
enum class Made { unknown, zero, nonzero };

std::string name(Made made) {
  return made == Made::zero ? "zero" : made == Made::nonzero ? "nonzero" : "either (the algebra decides)";
}

// Runs body(rng) for `count` cases, each with its own seed.
template <class Body>
void run_family(const char* name, long count, Body&& body) {
  for (long i = 0; i < count; ++i) {
    const std::uint64_t seed = oracle::case_seed(base_seed(), family_hash(name), static_cast<std::uint64_t>(i));
    INFO("family ", name, ", case ", i, ", case seed ", seed, " (base seed ", base_seed(),
         ", set APOLLONIUS_ROOT_SIGN_SEED to reproduce)");
    Random rng(seed);
    body(rng);
  }
}

// ---------------------------------------------------------------------------------------------------
// Oracle and checks

// The sign of the integer form, with the oracle checked against itself: MPFR finds the value below the
// separation bound exactly when the algebra says it is zero, and never for a case built nonzero; a case
// built as zero must be below the bound.
int expected_sign(const oracle::Integer_form& form, Made made) {
  const oracle::Certified_sign o = oracle::certified_sign(form);
  const bool algebraic_zero = oracle::zero_by_algebra(form);
  INFO("oracle: MPFR precision ", o.precision, ", below bound ", o.below_bound, ", algebraic zero ", algebraic_zero);
  CHECK(o.below_bound == algebraic_zero);
  if (made == Made::zero) CHECK(o.below_bound);
  if (made == Made::nonzero) CHECK_FALSE(o.below_bound);
  return o.sign;
}

// Interval inputs: the tightest enclosure of each input (exact for doubles), possibly widened by one ulp
// downwards, upwards or both (a filter input carrying rounding error). A radicand or a denominator stays
// >= 0 when widened, so a zero radicand next to exact other inputs becomes [0, denorm_min].
enum class Role { value, nonnegative };  // nonnegative: a radicand or a denominator

enum Side : unsigned { keep = 0, down = 1, up = 2, both = 3 };

struct Input {
  std::pair<double, double> tight;
  Role role;
  Input(const Dy& x, Role r) : tight(oracle::enclosure(x)), role(r) {}
  Interval in(unsigned side) const {
    auto [lo, hi] = tight;
    if ((side & down) != 0) lo = std::nextafter(lo, -kInf);
    if ((side & up) != 0) hi = std::nextafter(hi, kInf);
    if (role == Role::nonnegative && lo < 0) lo = 0;
    return Interval(lo, hi);
  }
};

// The widening patterns tried on each case (one Side per input): none; all inputs both ways; only the
// radicands and denominators; only the other inputs; and three pseudo-random patterns drawn from the
// inputs' bits (so a case always gets the same ones).
using Pattern = std::vector<unsigned>;
constexpr long kPatterns = 7;
std::vector<Pattern> patterns(const std::vector<Input>& inputs) {
  const std::size_t n = inputs.size();
  std::vector<Pattern> result(kPatterns, Pattern(n, keep));
  std::uint64_t h = 0x243f6a8885a308d3ull;
  for (std::size_t i = 0; i < n; ++i) {
    result[1][i] = both;
    result[2][i] = inputs[i].role == Role::nonnegative ? both : keep;
    result[3][i] = inputs[i].role == Role::value ? both : keep;
    std::uint64_t lo_bits, hi_bits;
    std::memcpy(&lo_bits, &inputs[i].tight.first, sizeof lo_bits);
    std::memcpy(&hi_bits, &inputs[i].tight.second, sizeof hi_bits);
    h = oracle::splitmix(h ^ lo_bits ^ (hi_bits << 1));
  }
  for (std::size_t k = 4; k < kPatterns; ++k)
    for (std::size_t i = 0; i < n; ++i) {
      h = oracle::splitmix(h);
      result[k][i] = static_cast<unsigned>(h & 3u);
    }
  return result;
}

std::string describe(const Pattern& pattern) {
  static const char* const names[] = {"exact", "down", "up", "both"};
  std::string text = "input widening (in argument order):";
  for (unsigned side : pattern) text += std::string(" ") + names[side];
  return text;
}

struct Tally {
  long cases = 0;
  long zeros = 0;
  long decided[2] = {0, 0};    // Interval stage returned a sign: [0] tightest inputs, [1] widened inputs
  long uncertain[2] = {0, 0};  // Interval stage threw Uncertain_sign
  long interval_runs() const { return decided[0] + decided[1] + uncertain[0] + uncertain[1]; }
  double decided_fraction(int w) const {
    return static_cast<double>(decided[w]) / static_cast<double>(std::max(1L, decided[w] + uncertain[w]));
  }
};

// Runs call(intervals) under a Rounding_guard for every widening pattern: it may throw Uncertain_sign,
// but a sign it returns must be the expected one.
template <class Call>
void check_interval(Tally& tally, const std::vector<Input>& inputs, int expected, Call&& call) {
  for (const Pattern& pattern : patterns(inputs)) {
    const bool widened = std::any_of(pattern.begin(), pattern.end(), [](unsigned s) { return s != keep; });
    int got = 2;
    {
      apollonius::Rounding_guard guard;
      std::vector<Interval> intervals;
      for (std::size_t i = 0; i < inputs.size(); ++i) intervals.push_back(inputs[i].in(pattern[i]));
      try {
        got = to_int(call(intervals));
      } catch (const apollonius::Uncertain_sign&) {
      }
    }
    if (got == 2) {
      ++tally.uncertain[widened];
      continue;
    }
    ++tally.decided[widened];
    INFO("Interval stage returned a sign, with ", describe(pattern));
    CHECK(got == expected);
  }
}

void check_one_root(Tally& tally, const Dy& a, const Dy& b, const Dy& d, Made made) {
  INFO("sign_of_root_number(a, b, d) with a = ", a, ", b = ", b, ", d = ", d, ", built ", name(made));
  ++tally.cases;
  const int expected = expected_sign(oracle::integer_form(a, {{b, d}}), made);
  if (expected == 0) ++tally.zeros;
  CHECK(to_int(apollonius::sign_of_root_number(oracle::to_exact(a), oracle::to_exact(b), oracle::to_exact(d))) ==
        expected);
  check_interval(tally, {Input(a, Role::value), Input(b, Role::value), Input(d, Role::nonnegative)}, expected,
                 [](const std::vector<Interval>& i) { return apollonius::sign_of_root_number(i[0], i[1], i[2]); });
}

void check_two_roots(Tally& tally, const Dy& a, const Dy& b1, const Dy& d1, const Dy& b2, const Dy& d2, Made made) {
  INFO("sign_of_two_root_sum(a, b1, d1, b2, d2) with a = ", a, ", b1 = ", b1, ", d1 = ", d1, ", b2 = ", b2,
       ", d2 = ", d2, ", built ", name(made));
  ++tally.cases;
  const int expected = expected_sign(oracle::integer_form(a, {{b1, d1}, {b2, d2}}), made);
  if (expected == 0) ++tally.zeros;
  CHECK(to_int(apollonius::sign_of_two_root_sum(oracle::to_exact(a), oracle::to_exact(b1), oracle::to_exact(d1),
                                                oracle::to_exact(b2), oracle::to_exact(d2))) == expected);
  check_interval(tally,
                 {Input(a, Role::value), Input(b1, Role::value), Input(d1, Role::nonnegative), Input(b2, Role::value),
                  Input(d2, Role::nonnegative)},
                 expected, [](const std::vector<Interval>& i) {
                   return apollonius::sign_of_two_root_sum(i[0], i[1], i[2], i[3], i[4]);
                 });
}

// (a + b sqrt d) / den with den > 0.
struct Root {
  Dy a, b, d, den;
};

std::ostream& operator<<(std::ostream& os, const Root& x) {
  return os << "(" << x.a << " + " << x.b << " sqrt(" << x.d << ")) / " << x.den;
}

Root_number<Exact> to_exact(const Root& x) {
  return {oracle::to_exact(x.a), oracle::to_exact(x.b), oracle::to_exact(x.d), oracle::to_exact(x.den)};
}

// sign(x - y) = sign((x.a y.den - y.a x.den) + x.b y.den sqrt(x.d) - y.b x.den sqrt(y.d)), as den > 0.
oracle::Integer_form difference_form(const Root& x, const Root& y) {
  return oracle::integer_form(x.a * y.den - y.a * x.den, {{x.b * y.den, x.d}, {-(y.b * x.den), y.d}});
}

// Checks compare(x, y) and compare(y, x).
void check_compare(Tally& tally, const Root& x, const Root& y, Made made) {
  INFO("compare(x, y) with x = ", x, ", y = ", y, ", x - y built ", name(made));
  REQUIRE(oracle::sgn(x.den) > 0);
  REQUIRE(oracle::sgn(y.den) > 0);
  ++tally.cases;
  const int expected = expected_sign(difference_form(x, y), made);
  if (expected == 0) ++tally.zeros;
  const Root_number<Exact> ex = to_exact(x), ey = to_exact(y);
  CHECK(to_int(apollonius::compare(ex, ey)) == expected);
  CHECK(to_int(apollonius::compare(ey, ex)) == -expected);
  const std::vector<Input> inputs = {
      Input(x.a, Role::value), Input(x.b, Role::value), Input(x.d, Role::nonnegative), Input(x.den, Role::nonnegative),
      Input(y.a, Role::value), Input(y.b, Role::value), Input(y.d, Role::nonnegative), Input(y.den, Role::nonnegative)};
  check_interval(tally, inputs, expected, [](const std::vector<Interval>& i) {
    return apollonius::compare(Root_number<Interval>{i[0], i[1], i[2], i[3]},
                               Root_number<Interval>{i[4], i[5], i[6], i[7]});
  });
  check_interval(tally, inputs, -expected, [](const std::vector<Interval>& i) {
    return apollonius::compare(Root_number<Interval>{i[4], i[5], i[6], i[7]},
                               Root_number<Interval>{i[0], i[1], i[2], i[3]});
  });
}

std::string summary(const Tally& t) {
  char buffer[200];
  std::snprintf(buffer, sizeof buffer, "%6ld cases, %5ld zeros, Interval decided %5.1f%% (widened inputs: %5.1f%%)",
                t.cases, t.zeros, 100 * t.decided_fraction(0), 100 * t.decided_fraction(1));
  return buffer;
}

// What every family asserts about its own run, whatever else it asserts: it ran `cases` cases, and each
// ran the Interval stage `runs_per_case` times (once per widening pattern and call).
void check_ran(const Tally& t, const char* family, long cases, long runs_per_case) {
  MESSAGE(std::string(family), ": ", summary(t));
  CHECK(t.cases == cases);
  CHECK(t.interval_runs() == runs_per_case * cases);
}

// The zeros of a family that mixes zeros and nonzeros: some of each.
void check_mixed(const Tally& t) {
  CHECK(t.zeros > 0);
  CHECK(t.zeros < t.cases);
}

// ---------------------------------------------------------------------------------------------------
// Generators

// A scale exponent: mostly none, some small, some large.
long pick_scale(Random& rng, long large = 300) {
  const long kind = rng.uniform(0, 3);
  if (kind <= 1) return 0;
  if (kind == 2) return rng.uniform(-8, 8);
  return rng.uniform(-large, large);
}

// Bit lengths spread over tiny, medium and large.
long pick_bits(Random& rng) {
  switch (rng.uniform(0, 2)) {
    case 0: return rng.uniform(1, 4);
    case 1: return rng.uniform(20, 64);
    default: return rng.uniform(150, 200);
  }
}

Z maybe_zero(Random& rng, Z x, double p_zero) { return rng.chance(p_zero) ? Z(0) : x; }

// Random draws happen in separate statements throughout (never two in one argument list), so that a case
// seed gives the same case with any compiler.
enum class Kind { integer, natural, positive };
Dy random_scaled(Random& rng, Kind kind, long bits) {
  const Z m = kind == Kind::integer   ? rng.integer(bits)
              : kind == Kind::natural ? rng.natural(bits)
                                      : rng.positive(bits);
  const long e = pick_scale(rng);
  return scaled(dy(m), e);
}

// An exponent far from zero, of either sign.
long far_exponent(Random& rng, long lo, long hi) {
  const long sign = rng.sign();
  return sign * rng.uniform(lo, hi);
}
Dy far_scaled(Random& rng, Kind kind, long bits, long lo, long hi) {
  const Z m = kind == Kind::integer ? rng.integer(bits) : rng.natural(bits);
  const long e = far_exponent(rng, lo, hi);
  return scaled(dy(m), e);
}

// Value-preserving scale of a + b sqrt d by 2^e: a 2^e + (b 2^(e-f)) sqrt(d 2^(2f)), which keeps exact
// zeros exact.
struct One {
  Dy a, b, d;
};
One scale_one(const Dy& a, const Dy& b, const Dy& d, long e, long f) {
  return {scaled(a, e), scaled(b, e - f), scaled(d, 2 * f)};
}
One scale_one(const Dy& a, const Dy& b, const Dy& d, Random& rng) {
  const long e = pick_scale(rng);
  const long f = pick_scale(rng);
  return scale_one(a, b, d, e, f);
}

struct Two {
  Dy a, b1, d1, b2, d2;
};
Two scale_two(const Two& t, long e, long f1, long f2) {
  return {scaled(t.a, e), scaled(t.b1, e - f1), scaled(t.d1, 2 * f1), scaled(t.b2, e - f2), scaled(t.d2, 2 * f2)};
}
Two scale_two(const Two& t, Random& rng) {
  const long e = pick_scale(rng);
  const long f1 = pick_scale(rng);
  const long f2 = pick_scale(rng);
  return scale_two(t, e, f1, f2);
}

// Convergents p/q of the continued fraction of sqrt(D), D not a square, until q has >= target_bits bits:
// |q sqrt(D) - p| < 1/q, the classic near-zero of a + b sqrt d.
std::pair<Z, Z> sqrt_convergent(long D, long target_bits) {
  const long a0 = static_cast<long>(std::sqrt(static_cast<double>(D)));
  long m = 0, den = 1, a = a0;
  Z p_prev(1), q_prev(0), p(a0), q(1);
  while (oracle::bits_of(q) < target_bits) {
    m = den * a - m;
    den = (D - m * m) / den;
    a = (a0 + m) / den;
    Z p_next = Z(a) * p + p_prev, q_next = Z(a) * q + q_prev;
    p_prev = p;
    q_prev = q;
    p = p_next;
    q = q_next;
  }
  return {p, q};
}

long random_non_square(Random& rng, long max_bits) {
  for (;;) {
    const long D = rng.uniform(2, (1L << max_bits));
    const long r = static_cast<long>(std::sqrt(static_cast<double>(D)));
    if (r * r != D && (r + 1) * (r + 1) != D && (r - 1) * (r - 1) != D) return D;
  }
}

}  // namespace

// ===================================================================================================
// sign_of_root_number: one TEST_CASE per family

namespace {

// The exhaustive family's ranges, and its zeros counted by elementary algebra: sqrt(d) is the integer s
// when d = s^2 and irrational otherwise, so a + b sqrt(d) = 0 exactly when a + b s = 0, or a = b = 0.
constexpr long kOneA = 6, kOneB = 4, kOneD = 20;
long one_root_small_zeros() {
  long zeros = 0;
  for (long a = -kOneA; a <= kOneA; ++a)
    for (long b = -kOneB; b <= kOneB; ++b)
      for (long d = 0; d <= kOneD; ++d) {
        long s = 0;
        while ((s + 1) * (s + 1) <= d) ++s;
        zeros += s * s == d ? a + b * s == 0 : a == 0 && b == 0;
      }
  return zeros;
}

}  // namespace

TEST_CASE("sign_of_root_number: every small a, b, d under scalings") {
  Tally tally;
  // Every small combination, under value-preserving scalings that also overflow and underflow doubles.
  const long scalings[][2] = {{0, 0}, {3, -2}, {-300, 300}, {300, -150}, {900, 0}, {-1000, 10}, {0, 520}, {0, -540}};
  for (const auto& s : scalings) {
    for (long a = -kOneA; a <= kOneA; ++a) {
      for (long b = -kOneB; b <= kOneB; ++b) {
        for (long d = 0; d <= kOneD; ++d) {
          INFO("exhaustive family, scaling e = ", s[0], ", f = ", s[1]);
          const One c = scale_one(dy(a), dy(b), dy(d), s[0], s[1]);
          check_one_root(tally, c.a, c.b, c.d, Made::unknown);
        }
      }
    }
  }
  const long per_scaling = (2 * kOneA + 1) * (2 * kOneB + 1) * (kOneD + 1);
  check_ran(tally, "one/exhaustive", 8 * per_scaling, kPatterns);
  CHECK(tally.zeros == 8 * one_root_small_zeros());
}

TEST_CASE("sign_of_root_number: random") {
  Tally tally;
  run_family("one/random", 10000, [&](Random& rng) {
    const Dy a = random_scaled(rng, Kind::integer, 200), b = random_scaled(rng, Kind::integer, 200),
             d = random_scaled(rng, Kind::natural, 200);
    check_one_root(tally, a, b, d, Made::unknown);
  });
  check_ran(tally, "one/random", 10000, kPatterns);
  // The filter is not vacuous: on random well-separated values the Interval stage nearly always decides.
  CHECK(tally.decided_fraction(0) > 0.9);
}

TEST_CASE("sign_of_root_number: sparse") {
  Tally tally;
  run_family("one/sparse", 10000, [&](Random& rng) {
    const Z a = maybe_zero(rng, rng.signed_(rng.with_bits(pick_bits(rng))), 0.2);
    const Z b = maybe_zero(rng, rng.signed_(rng.with_bits(pick_bits(rng))), 0.2);
    const Z d = maybe_zero(rng, rng.with_bits(pick_bits(rng)), 0.2);
    const One c = scale_one(dy(a), dy(b), dy(d), rng);
    check_one_root(tally, c.a, c.b, c.d, Made::unknown);
  });
  check_ran(tally, "one/sparse", 10000, kPatterns);
  check_mixed(tally);
}

TEST_CASE("sign_of_root_number: exact zeros") {
  Tally tally;
  run_family("one/exact zero", 10000, [&](Random& rng) {
    Z a, b, d;
    switch (rng.uniform(0, 4)) {
      case 0: {  // d = s^2, a = -b s (any signs; s = 0 gives d = 0, a = 0)
        const Z s = rng.natural(100);
        b = rng.nonzero(100);
        d = s * s;
        a = -(b * s);
        break;
      }
      case 1: d = rng.natural(200); break;  // a = b = 0
      case 2: b = rng.integer(200); break;  // a = 0, d = 0
      case 3: break;                        // all zero
      default: {                            // s a power of two: the exact type may strip it into the exponent
        const Z s = oracle::shl(Z(1), static_cast<unsigned long>(rng.uniform(0, 150)));
        b = rng.nonzero(100);
        d = s * s;
        a = -(b * s);
      }
    }
    const One c = scale_one(dy(a), dy(b), dy(d), rng);
    check_one_root(tally, c.a, c.b, c.d, Made::zero);
  });
  check_ran(tally, "one/exact zero", 10000, kPatterns);
  CHECK(tally.zeros == tally.cases);
}

TEST_CASE("sign_of_root_number: near zeros") {
  Tally tally;
  run_family("one/near zero", 10000, [&](Random& rng) {
    const Z s = rng.positive(100), b = rng.nonzero(100);
    Z a = -(b * s), d = s * s;
    switch (rng.uniform(0, 2)) {
      case 0: d = d + Z(rng.uniform(0, 1) == 0 ? 1 : -1); break;  // d = s^2 +- 1
      case 1: d = d + Z(rng.uniform(1, 1 << 10)); break;          // d slightly above s^2
      default: a = a + Z(rng.sign()); break;                      // rational, off by one
    }
    const One c = scale_one(dy(a), dy(b), dy(d), rng);
    check_one_root(tally, c.a, c.b, c.d, Made::nonzero);
  });
  check_ran(tally, "one/near zero", 10000, kPatterns);
  CHECK(tally.zeros == 0);
}

TEST_CASE("sign_of_root_number: continued fractions") {
  Tally tally;
  run_family("one/continued fraction", 3000, [&](Random& rng) {
    // q sqrt(D) - p within 1/q of zero, with every sign combination.
    const long D = random_non_square(rng, 20);
    const auto [p, q] = sqrt_convergent(D, rng.uniform(1, 190));
    const Z sigma = Z(rng.sign());
    const Z k = rng.positive(8);  // d = D k^2 changes the representation, not the value
    const One c = scale_one(dy(-(sigma * p)), dy(sigma * q), dy(Z(D)), rng);
    check_one_root(tally, c.a, c.b, c.d, Made::nonzero);
    check_one_root(tally, c.a * dy(k), c.b, c.d * dy(k * k), Made::nonzero);
  });
  check_ran(tally, "one/continued fraction", 2 * 3000, kPatterns);
  CHECK(tally.zeros == 0);
}

TEST_CASE("sign_of_root_number: equal magnitudes") {
  Tally tally;
  run_family("one/equal magnitudes", 3000, [&](Random& rng) {
    // |a| = |b| sqrt(d): zero or 2a depending on the signs.
    const Z s = rng.positive(120), b = rng.nonzero(80);
    const bool opposite = rng.chance(0.5);
    const Z a = opposite ? -(b * s) : b * s;
    const One c = scale_one(dy(a), dy(b), dy(s * s), rng);
    check_one_root(tally, c.a, c.b, c.d, opposite ? Made::zero : Made::nonzero);
  });
  check_ran(tally, "one/equal magnitudes", 3000, kPatterns);
  check_mixed(tally);
}

TEST_CASE("sign_of_root_number: extreme exponents") {
  Tally tally;
  run_family("one/extreme exponents", 5000, [&](Random& rng) {
    // Inputs far outside the double range: Interval must throw or be right.
    if (rng.chance(0.5)) {
      const Dy a = far_scaled(rng, Kind::integer, 200, 900, 1300), b = far_scaled(rng, Kind::integer, 200, 900, 1300),
               d = far_scaled(rng, Kind::natural, 200, 900, 1300);
      check_one_root(tally, a, b, d, Made::unknown);
    } else {
      const Z s = rng.natural(100), b = rng.nonzero(100);
      const Z a = rng.chance(0.5) ? -(b * s) : -(b * s) + Z(rng.sign());
      const long e = far_exponent(rng, 900, 1300), f = rng.uniform(-600, 600);
      const One c = scale_one(dy(a), dy(b), dy(s * s), e, f);
      check_one_root(tally, c.a, c.b, c.d, Made::unknown);
    }
  });
  check_ran(tally, "one/extreme exponents", 5000, kPatterns);
  check_mixed(tally);
}

// ===================================================================================================
// sign_of_two_root_sum: one TEST_CASE per family

namespace {

// The exhaustive family's ranges, and its zeros counted by elementary algebra: each sqrt(d) below is
// r + s sqrt(2) + t sqrt(3) for integers r, s, t, and 1, sqrt(2), sqrt(3) are linearly independent over Q.
constexpr long kTwoA = 3, kTwoB = 2;
constexpr long kTwoD1[] = {0, 1, 2, 3, 4, 8};
constexpr long kTwoD2[] = {0, 1, 2, 4, 9, 18};
std::array<long, 3> sqrt_in_basis(long d) {
  switch (d) {
    case 0: return {0, 0, 0};
    case 1: return {1, 0, 0};
    case 2: return {0, 1, 0};
    case 3: return {0, 0, 1};
    case 4: return {2, 0, 0};
    case 8: return {0, 2, 0};
    case 9: return {3, 0, 0};
    case 18: return {0, 3, 0};
    default: throw std::logic_error("sqrt_in_basis: no such radicand");
  }
}
long two_root_small_zeros() {
  long zeros = 0;
  for (long a = -kTwoA; a <= kTwoA; ++a)
    for (long b1 = -kTwoB; b1 <= kTwoB; ++b1)
      for (long d1 : kTwoD1)
        for (long b2 = -kTwoB; b2 <= kTwoB; ++b2)
          for (long d2 : kTwoD2) {
            const std::array<long, 3> r1 = sqrt_in_basis(d1), r2 = sqrt_in_basis(d2);
            zeros += a + b1 * r1[0] + b2 * r2[0] == 0 && b1 * r1[1] + b2 * r2[1] == 0 && b1 * r1[2] + b2 * r2[2] == 0;
          }
  return zeros;
}

}  // namespace

TEST_CASE("sign_of_two_root_sum: every small a, b1, d1, b2, d2 under scalings") {
  Tally tally;
  const long scalings[][3] = {{0, 0, 0}, {5, -3, 2}, {-600, 100, -250}, {700, 0, 0}};
  for (const auto& s : scalings) {
    for (long a = -kTwoA; a <= kTwoA; ++a)
      for (long b1 = -kTwoB; b1 <= kTwoB; ++b1)
        for (long d1 : kTwoD1)
          for (long b2 = -kTwoB; b2 <= kTwoB; ++b2)
            for (long d2 : kTwoD2) {
              INFO("exhaustive family, scaling e = ", s[0], ", f1 = ", s[1], ", f2 = ", s[2]);
              const Two c = scale_two({dy(a), dy(b1), dy(d1), dy(b2), dy(d2)}, s[0], s[1], s[2]);
              check_two_roots(tally, c.a, c.b1, c.d1, c.b2, c.d2, Made::unknown);
            }
  }
  const long per_scaling = (2 * kTwoA + 1) * (2 * kTwoB + 1) * (2 * kTwoB + 1) * static_cast<long>(std::size(kTwoD1)) *
                           static_cast<long>(std::size(kTwoD2));
  check_ran(tally, "two/exhaustive", 4 * per_scaling, kPatterns);
  CHECK(tally.zeros == 4 * two_root_small_zeros());
}

TEST_CASE("sign_of_two_root_sum: random") {
  Tally tally;
  run_family("two/random", 10000, [&](Random& rng) {
    const Dy a = random_scaled(rng, Kind::integer, 200), b1 = random_scaled(rng, Kind::integer, 200),
             d1 = random_scaled(rng, Kind::natural, 200), b2 = random_scaled(rng, Kind::integer, 200),
             d2 = random_scaled(rng, Kind::natural, 200);
    check_two_roots(tally, a, b1, d1, b2, d2, Made::unknown);
  });
  check_ran(tally, "two/random", 10000, kPatterns);
  // The filter is not vacuous: on random well-separated values the Interval stage nearly always decides.
  CHECK(tally.decided_fraction(0) > 0.9);
}

TEST_CASE("sign_of_two_root_sum: sparse") {
  Tally tally;
  run_family("two/sparse", 10000, [&](Random& rng) {
    auto entry = [&](bool nonnegative) {
      const Z x = rng.with_bits(pick_bits(rng));
      return dy(maybe_zero(rng, nonnegative ? x : rng.signed_(x), 0.25));
    };
    const Dy a = entry(false), b1 = entry(false), d1 = entry(true), b2 = entry(false), d2 = entry(true);
    const Two c = scale_two({a, b1, d1, b2, d2}, rng);
    check_two_roots(tally, c.a, c.b1, c.d1, c.b2, c.d2, Made::unknown);
  });
  check_ran(tally, "two/sparse", 10000, kPatterns);
  check_mixed(tally);
}

TEST_CASE("sign_of_two_root_sum: exact zeros") {
  Tally tally;
  run_family("two/exact zero", 10000, [&](Random& rng) {
    Z a, b1, d1, b2, d2;
    switch (rng.uniform(0, 6)) {
      case 0: {  // d1 = t u^2, d2 = t v^2, a = 0, b1 u = -b2 v
        const Z t = rng.positive(60), u = rng.positive(50), v = rng.positive(50), k = rng.nonzero(40);
        const Z g = oracle::gcd_of(u, v);
        d1 = t * u * u;
        d2 = t * v * v;
        b1 = k * oracle::exact_div(v, g);
        b2 = -(k * oracle::exact_div(u, g));
        break;
      }
      case 1: {  // both radicands squares: a = -(b1 s1 + b2 s2)
        const Z s1 = rng.natural(80), s2 = rng.natural(80);
        b1 = rng.integer(80);
        b2 = rng.integer(80);
        d1 = s1 * s1;
        d2 = s2 * s2;
        a = -(b1 * s1 + b2 * s2);
        break;
      }
      case 2: {  // one root vanishes (d2 = 0 or b2 = 0), the other is rational
        const Z s = rng.natural(100);
        b1 = rng.integer(100);
        d1 = s * s;
        a = -(b1 * s);
        if (rng.chance(0.5))
          b2 = rng.integer(100);
        else
          d2 = rng.natural(100);
        break;
      }
      case 3: {  // same radicand, opposite coefficients
        d1 = d2 = rng.natural(200);
        b1 = rng.integer(100);
        b2 = -b1;
        break;
      }
      case 4: {  // rational part cancels a root with square radicand, the other root vanishes by b = 0
        const Z s = rng.positive(100);
        b2 = rng.nonzero(100);
        d2 = s * s;
        a = -(b2 * s);
        d1 = rng.natural(100);
        break;
      }
      case 5: {  // d1 = t u^2, d2 = t v^2 with t a square: everything rational
        const Z w = rng.positive(30), u = rng.positive(40), v = rng.positive(40);
        b1 = rng.integer(60);
        b2 = rng.integer(60);
        d1 = w * w * u * u;
        d2 = w * w * v * v;
        a = -(w * (b1 * u + b2 * v));
        break;
      }
      default:  // a = b1 = b2 = 0
        d1 = rng.natural(200);
        d2 = rng.natural(200);
    }
    if (rng.chance(0.5)) {  // the roles of the roots are symmetric
      std::swap(b1, b2);
      std::swap(d1, d2);
    }
    const Two c = scale_two({dy(a), dy(b1), dy(d1), dy(b2), dy(d2)}, rng);
    check_two_roots(tally, c.a, c.b1, c.d1, c.b2, c.d2, Made::zero);
  });
  check_ran(tally, "two/exact zero", 10000, kPatterns);
  CHECK(tally.zeros == tally.cases);
}

TEST_CASE("sign_of_two_root_sum: near zeros") {
  Tally tally;
  long unknown = 0;  // cases of the third kind, which the algebra decides
  run_family("two/near zero", 10000, [&](Random& rng) {
    Z a, b1, d1, b2, d2;
    Made made = Made::nonzero;
    switch (rng.uniform(0, 3)) {
      case 0: {  // sqrt(s^2 + 1) + sqrt(s^2 - 1) - 2 s ~ -1 / (4 s^3)
        const Z s = rng.positive(90) + Z(1);
        a = Z(-2) * s;
        b1 = b2 = Z(1);
        d1 = s * s + Z(1);
        d2 = s * s - Z(1);
        break;
      }
      case 1: {  // b1 sqrt(t u^2 + 1) + b2 sqrt(t v^2) with b1 u = -b2 v
        const Z t = rng.positive(60), u = rng.positive(50), v = rng.positive(50), k = rng.nonzero(30);
        const Z g = oracle::gcd_of(u, v);
        d1 = t * u * u + Z(1);
        d2 = t * v * v;
        b1 = k * oracle::exact_div(v, g);
        b2 = -(k * oracle::exact_div(u, g));
        break;
      }
      case 2: {  // (q1 sqrt D1 - p1) + (q2 sqrt D2 - p2): two near-zeros of either sign
        const long D1 = random_non_square(rng, 16), D2 = random_non_square(rng, 16);
        const auto [p1, q1] = sqrt_convergent(D1, rng.uniform(1, 100));
        const auto [p2, q2] = sqrt_convergent(D2, rng.uniform(1, 100));
        const Z s1 = Z(rng.sign()), s2 = Z(rng.sign());
        a = -(s1 * p1 + s2 * p2);
        b1 = s1 * q1;
        b2 = s2 * q2;
        d1 = Z(D1);
        d2 = Z(D2);
        made = Made::unknown;  // D1 D2 may be a square: the algebra decides
        ++unknown;
        break;
      }
      default: {  // d1 = s1^2 + 1, d2 = s2^2, a = -(b1 s1 + b2 s2)
        const Z s1 = rng.positive(90), s2 = rng.natural(90);
        b1 = rng.nonzero(60);
        b2 = rng.integer(60);
        d1 = s1 * s1 + Z(1);
        d2 = s2 * s2;
        a = -(b1 * s1 + b2 * s2);
      }
    }
    if (rng.chance(0.5)) {  // negate the whole sum
      a = -a;
      b1 = -b1;
      b2 = -b2;
    }
    if (rng.chance(0.5)) {
      std::swap(b1, b2);
      std::swap(d1, d2);
    }
    const Two c = scale_two({dy(a), dy(b1), dy(d1), dy(b2), dy(d2)}, rng);
    check_two_roots(tally, c.a, c.b1, c.d1, c.b2, c.d2, made);
  });
  check_ran(tally, "two/near zero", 10000, kPatterns);
  // Only the cases of the third kind can be zero (when D1 D2 is a square and the convergents match).
  CHECK(unknown > 0);
  CHECK(tally.zeros <= unknown);
}

TEST_CASE("sign_of_two_root_sum: equal magnitudes") {
  Tally tally;
  run_family("two/equal magnitudes", 5000, [&](Random& rng) {
    // |a| = |b1| sqrt(d1) = |b2| sqrt(d2) (or two of them equal and the third zero) with every sign.
    const Z s1 = rng.positive(50), s2 = rng.positive(50), k = rng.positive(40);
    Z a = s1 * s2 * k * Z(rng.sign()), b1 = s2 * k * Z(rng.sign()), b2 = s1 * k * Z(rng.sign());
    Z d1 = s1 * s1, d2 = s2 * s2;
    switch (rng.uniform(0, 3)) {
      case 0: break;
      case 1: a = Z(0); break;
      case 2: b1 = Z(0); break;
      default: {  // irrational: d1 = t s1^2, d2 = t s2^2, a = 0
        const Z t = rng.positive(40);
        d1 = d1 * t;
        d2 = d2 * t;
        a = Z(0);
      }
    }
    const Two c = scale_two({dy(a), dy(b1), dy(d1), dy(b2), dy(d2)}, rng);
    check_two_roots(tally, c.a, c.b1, c.d1, c.b2, c.d2, Made::unknown);
  });
  check_ran(tally, "two/equal magnitudes", 5000, kPatterns);
  check_mixed(tally);
}

TEST_CASE("sign_of_two_root_sum: extreme exponents") {
  Tally tally;
  run_family("two/extreme exponents", 5000, [&](Random& rng) {
    if (rng.chance(0.5)) {
      const Dy a = far_scaled(rng, Kind::integer, 200, 600, 1300), b1 = far_scaled(rng, Kind::integer, 200, 600, 1300),
               d1 = far_scaled(rng, Kind::natural, 200, 600, 1300), b2 = far_scaled(rng, Kind::integer, 200, 600, 1300),
               d2 = far_scaled(rng, Kind::natural, 200, 600, 1300);
      check_two_roots(tally, a, b1, d1, b2, d2, Made::unknown);
    } else {  // an exact zero or a near-zero, moved far away
      const Z t = rng.positive(60), u = rng.positive(50), v = rng.positive(50), k = rng.nonzero(30);
      const Z g = oracle::gcd_of(u, v);
      const bool zero = rng.chance(0.5);
      const long e = far_exponent(rng, 600, 1300), f1 = rng.uniform(-300, 300), f2 = rng.uniform(-300, 300);
      const Two c = scale_two({dy(0), dy(k * oracle::exact_div(v, g)), dy(t * u * u + Z(zero ? 0 : 1)),
                               dy(-(k * oracle::exact_div(u, g))), dy(t * v * v)},
                              e, f1, f2);
      check_two_roots(tally, c.a, c.b1, c.d1, c.b2, c.d2, zero ? Made::zero : Made::nonzero);
    }
  });
  check_ran(tally, "two/extreme exponents", 5000, kPatterns);
  check_mixed(tally);
}

// ===================================================================================================
// compare(Root_number, Root_number): one TEST_CASE per family

namespace {

Root random_root(Random& rng, long bits) {
  // (braced initializers are evaluated in order)
  return {random_scaled(rng, Kind::integer, bits), random_scaled(rng, Kind::integer, bits),
          random_scaled(rng, Kind::natural, bits), random_scaled(rng, Kind::positive, bits)};
}

// The same value as x, written differently.
Root same_value(Random& rng, const Root& x) {
  switch (rng.uniform(0, 3)) {
    case 0: {  // numerator and denominator times k > 0 (k a power of two or not)
      const Dy k = rng.chance(0.5) ? dy(rng.positive(60)) : scaled(dy(1), rng.uniform(-300, 300));
      return {x.a * k, x.b * k, x.d, x.den * k};
    }
    case 1: {  // b sqrt(d u^2 / w^2 ...): b sqrt(d) = (b / u) sqrt(d u^2), with b a multiple of u
      const Z u = rng.positive(30);
      return {x.a * dy(u), x.b, x.d * dy(u * u), x.den * dy(u)};  // (a u + b sqrt(d u^2)) / (den u)
    }
    case 2: {  // sqrt(4 d) = 2 sqrt(d): (2a + b sqrt(4d)) / (2 den)
      return {scaled(x.a, 1), x.b, scaled(x.d, 2), scaled(x.den, 1)};
    }
    default: return x;  // the very same representation
  }
}

// The exhaustive family's values (a + b sqrt d) / den: d in {0, 1, 2, 4, 8} and den in {1, 2} give many
// equal values.
struct Small_root {
  long a, b, d, den;
};
std::vector<Small_root> small_roots() {
  std::vector<Small_root> small;
  for (long a = -2; a <= 2; ++a)
    for (long b = -1; b <= 1; ++b)
      for (long d : {0, 1, 2, 4, 8})
        for (long den : {1, 2}) small.push_back({a, b, d, den});
  return small;
}

// The equal ordered pairs among them, counted by elementary algebra: each sqrt(d) is r + s sqrt(2) for
// integers r, s, and 1, sqrt(2) are linearly independent over Q.
long small_equal_pairs(const std::vector<Small_root>& small) {
  const auto parts = [](const Small_root& x) {
    const long r = x.d == 1 ? 1 : x.d == 4 ? 2 : 0, s = x.d == 2 ? 1 : x.d == 8 ? 2 : 0;
    return std::array<long, 2>{x.a + x.b * r, x.b * s};  // the numerator (a + b r) + (b s) sqrt(2)
  };
  long pairs = 0;
  for (const Small_root& x : small)
    for (const Small_root& y : small) {
      const std::array<long, 2> px = parts(x), py = parts(y);
      pairs += px[0] * y.den == py[0] * x.den && px[1] * y.den == py[1] * x.den;
    }
  return pairs;
}

}  // namespace

TEST_CASE("compare: all pairs of small root numbers") {
  Tally tally;
  const std::vector<Small_root> small = small_roots();
  for (const Small_root& x : small)
    for (const Small_root& y : small) {
      INFO("exhaustive family");
      check_compare(tally, {dy(x.a), dy(x.b), dy(x.d), dy(x.den)}, {dy(y.a), dy(y.b), dy(y.d), dy(y.den)},
                    Made::unknown);
    }
  check_ran(tally, "compare/exhaustive", static_cast<long>(small.size() * small.size()), 2 * kPatterns);
  CHECK(tally.zeros == small_equal_pairs(small));
}

TEST_CASE("compare: random") {
  Tally tally;
  run_family("compare/random", 10000, [&](Random& rng) {
    const Root x = random_root(rng, 150);
    const Root y = random_root(rng, 150);
    check_compare(tally, x, y, Made::unknown);
  });
  check_ran(tally, "compare/random", 10000, 2 * kPatterns);
  // The filter is not vacuous: on random well-separated values the Interval stage nearly always decides.
  CHECK(tally.decided_fraction(0) > 0.9);
}

TEST_CASE("compare: the same value written differently") {
  Tally tally;
  run_family("compare/same value", 10000, [&](Random& rng) {
    Root x = random_root(rng, 100);
    switch (rng.uniform(0, 3)) {
      case 0: break;
      case 1: {  // x rational through a square radicand, y rational through b = 0 or d = 0
        const Z s = rng.natural(80);
        const long f = pick_scale(rng);
        x.d = dy(s * s, 2 * f);
        const Dy rational = x.a + x.b * dy(s, f);
        const Root y = rng.chance(0.5) ? Root{rational, dy(0), dy(rng.natural(100)), x.den}
                                       : Root{rational, dy(rng.integer(100)), dy(0), x.den};
        check_compare(tally, x, same_value(rng, y), Made::zero);
        return;
      }
      case 2: {  // sqrt(d u^2) = u sqrt(d): y = (a + (b u) sqrt(d)) / den
        const Z u = rng.positive(40);
        const Root y{x.a, x.b * dy(u), x.d, x.den};
        x.d = x.d * dy(u * u);
        check_compare(tally, rng.chance(0.5) ? x : same_value(rng, x), y, Made::zero);
        return;
      }
      default: {  // the negated value written twice: sign conventions of a and b
        x = {-x.a, -x.b, x.d, x.den};
      }
    }
    check_compare(tally, x, same_value(rng, x), Made::zero);
  });
  check_ran(tally, "compare/same value", 10000, 2 * kPatterns);
  CHECK(tally.zeros == tally.cases);
}

TEST_CASE("compare: near values") {
  Tally tally;
  run_family("compare/near", 10000, [&](Random& rng) {
    const Root x = random_root(rng, 80);
    switch (rng.uniform(0, 2)) {
      case 0: {  // y = (a k + b sqrt(k^2 d + delta)) / (den k), b != 0: the radicand moves by delta / k^2
        Root x2 = x;
        if (oracle::sgn(x2.b) == 0) x2.b = dy(1);
        if (oracle::sgn(x2.d) == 0) x2.d = dy(1);
        const Z k = rng.positive(100);
        const Dy delta = scaled(dy(rng.sign()), x2.d.e);
        const Root y{x2.a * dy(k), x2.b, x2.d * dy(k * k) + delta, x2.den * dy(k)};
        check_compare(tally, x2, y, Made::nonzero);
        break;
      }
      case 1: {  // y = x + 1 / (den K)
        const Z K = rng.positive(200);
        const Root y{x.a * dy(K) + dy(1, x.a.e), x.b * dy(K), x.d, x.den * dy(K)};
        check_compare(tally, x, y, Made::nonzero);
        break;
      }
      default: {  // p / q against sqrt(D): a convergent
        const long D = random_non_square(rng, 20);
        const auto [p, q] = sqrt_convergent(D, rng.uniform(1, 150));
        const long e = pick_scale(rng);
        const Root y{dy(0), scaled(dy(1), e), dy(Z(D)), dy(1)};
        const Root z{scaled(dy(p), e), dy(0), dy(rng.natural(20)), dy(q)};
        check_compare(tally, z, y, Made::nonzero);
      }
    }
  });
  check_ran(tally, "compare/near", 10000, 2 * kPatterns);
  CHECK(tally.zeros == 0);
}

TEST_CASE("compare: extreme exponents") {
  Tally tally;
  run_family("compare/extreme exponents", 5000, [&](Random& rng) {
    Root x = random_root(rng, 150), y = random_root(rng, 150);
    x.a = scaled(x.a, far_exponent(rng, 300, 1200));
    x.den = scaled(x.den, far_exponent(rng, 300, 1200));
    y.b = scaled(y.b, far_exponent(rng, 300, 1200));
    y.d = scaled(y.d, far_exponent(rng, 300, 1200));
    if (rng.chance(0.5)) {
      check_compare(tally, x, y, Made::unknown);
    } else {
      check_compare(tally, x, same_value(rng, x), Made::zero);
    }
  });
  check_ran(tally, "compare/extreme exponents", 5000, 2 * kPatterns);
  check_mixed(tally);
}

// ===================================================================================================
// to_nearest_double

namespace {

bool same_double(double x, double y) { return x == y || (std::isnan(x) && std::isnan(y)); }

bool is_even(double g) {
  std::uint64_t bits;
  std::memcpy(&bits, &g, sizeof g);
  return (bits & 1u) == 0;
}

struct Nearest_tally {
  long cases = 0;
  long rational = 0;
  long enclosed = 0;
};

std::string hex(double x) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%a", x);
  return buffer;
}

// x is rational when b = 0 or d is a dyadic square: then (a + b sqrt d) / den.
std::optional<Dy> rational_numerator(const Root& x) {
  if (oracle::sgn(x.b) == 0) return x.a;
  const std::optional<Dy> s = oracle::dyadic_sqrt(x.d);
  if (!s) return std::nullopt;
  return x.a + x.b * *s;
}

// Checks to_nearest_double(x) against the oracles: for a rational x the exact quotient rounded by MPFR's
// IEEE emulation, for any x the MPFR enclosure when it is certain (never at an exact midpoint; an
// irrational x is never a midpoint, so it must be certain). When the case was built with a known answer,
// the oracles must agree with it too.
void check_nearest(Nearest_tally& tally, const Root& x, std::optional<double> built) {
  INFO("to_nearest_double(x) with x = ", x);
  ++tally.cases;
  std::optional<double> expected;
  if (const std::optional<Dy> numerator = rational_numerator(x)) {
    expected = oracle::nearest_of_quotient(*numerator, x.den);
    ++tally.rational;
  }
  const oracle::Certified_double o = oracle::certified_nearest(x.a, x.b, x.d, x.den);
  if (o.certain) {
    ++tally.enclosed;
    INFO("MPFR enclosure at ", o.precision, " bits gives ", hex(o.value));
    if (expected) CHECK(same_double(*expected, o.value));
    expected = o.value;
  }
  REQUIRE(expected.has_value());
  if (built) {
    INFO("built to round to ", hex(*built), ", the oracle says ", hex(*expected));
    CHECK(same_double(*built, *expected));
    expected = built;
  }
  const double got = apollonius::to_nearest_double(to_exact(x));
  INFO("expected ", hex(*expected), ", got ", hex(got));
  CHECK(same_double(got, *expected));
}

// A random finite double: any sign, exponent from subnormal to the top.
double random_double(Random& rng) {
  const double mantissa = std::ldexp(static_cast<double>(rng.word() >> 11), -53);  // [0, 1)
  double g;
  switch (rng.uniform(0, 3)) {
    case 0: g = std::ldexp(mantissa, static_cast<int>(rng.uniform(-1074, 0))); break;  // includes subnormals
    case 1: g = std::ldexp(0.5 + mantissa / 2, static_cast<int>(rng.uniform(-1021, 1024))); break;
    case 2: g = std::ldexp(static_cast<double>(rng.uniform(0, 16)), -1074); break;  // smallest subnormals
    default: g = std::nextafter(kMax, 0.0) - std::ldexp(static_cast<double>(rng.uniform(0, 4)), 971);  // top
  }
  return rng.chance(0.5) ? -g : g;
}

// x written as (a + b sqrt d) / den in one of several ways, all exact.
Root represent(Random& rng, const Dy& value) {
  const Z k = rng.positive(64);
  switch (rng.uniform(0, 5)) {
    case 0: return {value, dy(0), dy(0), dy(1)};
    case 1: return {value * dy(k), dy(0), dy(rng.natural(60)), dy(k)};  // b = 0, d != 0
    case 2: return {value * dy(k), dy(rng.nonzero(60)), dy(0), dy(k)};  // d = 0, b != 0
    case 3: {                                                           // d = s^2, cancelling a
      const Z s = rng.positive(100), b = rng.nonzero(100);
      return {value * dy(k) - dy(b * s), dy(b), dy(s * s), dy(k)};
    }
    case 4: {  // sqrt(value^2) with the sign in b
      const int sign = oracle::sgn(value) < 0 ? -1 : 1;
      return {dy(0), dy(sign), value * value, dy(1)};
    }
    default: {  // a power-of-two denominator
      const long e = rng.uniform(-1200, 1200);
      return {scaled(value, e), dy(0), dy(0), scaled(dy(1), e)};
    }
  }
}

// The midpoint between lo and its upper neighbour hi (hi may be +inf for lo = max: the rounding boundary
// max + ulp/2), and the even one of the two (+inf beyond max).
struct Midpoint {
  double lo, hi;
  Dy value;
  double even;
};

Midpoint midpoint_above(double lo) {
  Midpoint m;
  m.lo = lo == 0 ? 0.0 : lo;
  m.hi = std::nextafter(m.lo, kInf);
  if (std::isinf(m.hi)) {
    m.value = oracle::dy_of_double(kMax) + dy(1, 970);
    m.even = kInf;
  } else {
    m.value = scaled(oracle::dy_of_double(m.lo) + oracle::dy_of_double(m.hi), -1);
    m.even = is_even(m.lo) ? m.lo : m.hi;
  }
  return m;
}

// A value a hair away from m (above it if `up`), irrational, in one of two forms:
//  - sqrt(M^2 2^(2K) + delta) 2^(E-K) with m = M 2^E: above |m| exactly when delta > 0;
//  - (C - sqrt(N^2 + delta)) 2^E with C = N + M: below m exactly when delta > 0.
Root near(Random& rng, const Dy& m, bool up) {
  const long delta_size = rng.uniform(1, 1 << 20);
  const Z k = rng.chance(0.5) ? Z(1) : rng.positive(40);  // a common factor of numerator and denominator
  if (rng.chance(0.5)) {
    const long K = rng.uniform(12, 200);
    const int sm = oracle::sgn(m);
    const bool away = (sm > 0) == up;  // farther from zero
    const Z M = oracle::abs_of(m.m);
    const Dy d = dy(oracle::shl(M * M, static_cast<unsigned long>(2 * K)) + Z(away ? delta_size : -delta_size));
    return {dy(0), dy(Z(sm) * k, m.e - K), d, dy(k)};
  }
  const long N_bits = rng.uniform(60, 250);
  const Z N = oracle::shl(Z(1), static_cast<unsigned long>(N_bits)) + rng.natural(60);
  const Z C = N + m.m;
  const Dy d = dy(N * N + Z(up ? -delta_size : delta_size));
  return {dy(C * k, m.e), dy(-k, m.e), d, dy(k)};
}

// The lower neighbour of a midpoint: special doubles (zero, subnormals, powers of two, the top).
double special_lo(Random& rng) {
  const double specials[] = {0.0,
                             -kDenormMin,
                             kDenormMin,
                             2 * kDenormMin,
                             std::nextafter(std::numeric_limits<double>::min(), 0.0),  // largest subnormal
                             -std::numeric_limits<double>::min(),
                             std::nextafter(1.0, 0.0),
                             -1.0,
                             1.0,
                             std::nextafter(0x1p-1022, 0.0),
                             std::nextafter(kMax, 0.0),
                             -kMax,
                             kMax,
                             -std::nextafter(kMax, 0.0),
                             std::nextafter(0x1p1000, 0.0),
                             -0x1p-1000};
  return specials[rng.uniform(0, static_cast<long>(sizeof specials / sizeof specials[0]) - 1)];
}

void report(const Nearest_tally& tally, const char* family) {
  MESSAGE(std::string(family), ": ", tally.cases, " cases (", tally.rational, " rational, ", tally.enclosed,
          " certified by the MPFR enclosure)");
}

}  // namespace

TEST_CASE("to_nearest_double: random values") {
  Nearest_tally tally;
  run_family("nearest/random", 12000, [&](Random& rng) {
    Z a = rng.integer(120), b = rng.integer(120), d = rng.natural(200);
    const Z den = rng.positive(120);
    switch (rng.uniform(0, 9)) {
      case 0: a = Z(0); break;
      case 1: b = Z(0); break;
      case 2: d = Z(0); break;
      case 3:
      case 4: {  // heavy cancellation: a = -b floor(sqrt(d)) + small
        if (oracle::sgn(b) == 0) b = Z(1);
        a = -(b * oracle::isqrt(d)) + Z(rng.uniform(-3, 3));
        break;
      }
      default: break;
    }
    // Move the magnitude anywhere from far below the subnormals to beyond the overflow threshold.
    const long size = std::max(oracle::bits_of(a), oracle::bits_of(b) + oracle::bits_of(d) / 2) - oracle::bits_of(den);
    const long shift = rng.uniform(-1130, 1090) - size;
    const long shift_d = 2 * rng.uniform(-100, 100);
    const Root x{dy(a, shift), dy(b, shift - shift_d / 2), dy(d, shift_d), dy(den)};
    check_nearest(tally, x, std::nullopt);
  });
  report(tally, "nearest/random");
  CHECK(tally.cases == 12000);
  CHECK(tally.rational > 0);
  CHECK(tally.enclosed > 0);
}

TEST_CASE("to_nearest_double: exact doubles") {
  Nearest_tally tally;
  run_family("nearest/exact double", 3000, [&](Random& rng) {
    const double g = random_double(rng);
    check_nearest(tally, represent(rng, oracle::dy_of_double(g)), g);
  });
  report(tally, "nearest/exact double");
  CHECK(tally.cases == 3000);
  // A double is rational and no midpoint: both oracles answer every case.
  CHECK(tally.rational == tally.cases);
  CHECK(tally.enclosed == tally.cases);
}

TEST_CASE("to_nearest_double: exact midpoints") {
  Nearest_tally tally;
  // Exact midpoints: the tie goes to the even neighbour (to +-infinity beyond max).
  run_family("nearest/midpoint", 4000, [&](Random& rng) {
    const double lo = rng.chance(0.3) ? special_lo(rng) : random_double(rng);
    if (lo == kMax || lo == -kMax) {  // the overflow boundary max + ulp/2, rounding to infinity
      const Midpoint m = midpoint_above(kMax);
      const bool negative = lo < 0;
      check_nearest(tally, represent(rng, negative ? -m.value : m.value), negative ? -kInf : kInf);
      return;
    }
    const Midpoint m = midpoint_above(lo);
    INFO("midpoint between ", hex(m.lo), " and ", hex(m.hi));
    check_nearest(tally, represent(rng, m.value), m.even);
  });
  report(tally, "nearest/midpoint");
  CHECK(tally.cases == 4000);
  // A midpoint is rational, and the MPFR enclosure is never certain at one: the rational oracle decides.
  CHECK(tally.rational == tally.cases);
  CHECK(tally.enclosed == 0);
}

TEST_CASE("to_nearest_double: near midpoints") {
  Nearest_tally tally;
  // A hair above or below a midpoint (irrational): the MPFR oracle must agree with the construction.
  run_family("nearest/near midpoint", 4000, [&](Random& rng) {
    double lo = rng.chance(0.3) ? special_lo(rng) : random_double(rng);
    if (lo == -kMax) lo = kMax;  // -max has no midpoint below it inside the range: use the top boundary
    const bool up = rng.chance(0.5);
    const bool negate = rng.chance(0.5);
    const Midpoint m = midpoint_above(lo);
    double expected = up ? m.hi : m.lo;
    Dy value = m.value;
    bool flip = false;
    if (lo == kMax && negate) {  // mirror the top boundary to the bottom one
      value = -value;
      expected = up ? -kMax : -kInf;
      flip = true;
    }
    INFO("near midpoint between ", hex(m.lo), " and ", hex(m.hi), ", ", up ? "above" : "below",
         flip ? " (mirrored)" : "");
    const Root x = near(rng, value, up);
    check_nearest(tally, x, expected);  // irrational: the MPFR enclosure must be certain and agree
  });
  report(tally, "nearest/near midpoint");
  CHECK(tally.cases == 4000);
  CHECK(tally.enclosed == tally.cases);
}

TEST_CASE("to_nearest_double: fixed corner cases (overflow, subnormals, ties)") {
  Nearest_tally tally;
  const Dy half_ulp_max = dy(1, 970);
  const Dy top = oracle::dy_of_double(kMax) + half_ulp_max;  // max + ulp/2: rounds to infinity (tie)
  struct Fixed {
    Root x;
    double expected;
  };
  const Fixed fixed[] = {
      {{dy(1, 1024), dy(0), dy(0), dy(1)}, kInf},
      {{dy(-1, 1024), dy(0), dy(0), dy(1)}, -kInf},
      {{top, dy(0), dy(0), dy(1)}, kInf},
      {{-top, dy(0), dy(0), dy(1)}, -kInf},
      {{top - dy(1, 900), dy(0), dy(0), dy(1)}, kMax},
      {{dy(1, 5000), dy(3), dy(1, 4000), dy(1)}, kInf},
      {{dy(0), dy(-1), dy(3, 4000), dy(1)}, -kInf},
      {{dy(0), dy(1), dy(3, 2000), dy(1)}, std::sqrt(3.0) * 0x1p1000},  // correctly rounded by IEEE sqrt
      {{dy(1, 1100), dy(0), dy(0), dy(1, 1100)}, 1.0},                  // huge over huge
      {{dy(1, -1100), dy(0), dy(0), dy(1, -1100)}, 1.0},                // tiny over tiny
      {{dy(1, -1075), dy(0), dy(0), dy(1)}, 0.0},                       // denorm_min / 2: tie to 0
      {{dy(-1, -1075), dy(0), dy(0), dy(1)}, -0.0},
      {{dy(3, -1075), dy(0), dy(0), dy(1)}, 2 * kDenormMin},  // 1.5 denorm_min: tie to 2
      {{dy(5, -1075), dy(0), dy(0), dy(1)}, 2 * kDenormMin},  // 2.5 denorm_min: tie to 2
      {{dy(7, -1075), dy(0), dy(0), dy(1)}, 4 * kDenormMin},  // 3.5 denorm_min: tie to 4
      {{dy(1, -1200), dy(0), dy(0), dy(1)}, 0.0},
      {{dy(0), dy(1), dy(1, -2300), dy(1)}, 0.0},                                      // sqrt(2^-2300) = 2^-1150
      {{dy(0), dy(1), dy(1, -2148), dy(1)}, kDenormMin},                               // sqrt = 2^-1074 exactly
      {{dy(0), dy(1), dy(1, -2150), dy(1)}, 0.0},                                      // sqrt = 2^-1075: tie to 0
      {{dy(0), dy(1), dy(Z(1) + oracle::shl(Z(1), 2000), -4150), dy(1)}, kDenormMin},  // a hair above
      {{dy(0), dy(-1), dy(Z(1) + oracle::shl(Z(1), 2000), -4150), dy(1)}, -kDenormMin},
      {{dy(0), dy(0), dy(0), dy(7)}, 0.0},
      {{dy(1), dy(-1), dy(1), dy(3)}, 0.0},                 // exact zero through the root
      {{dy(2), dy(-1), dy(2), dy(1)}, 2 - std::sqrt(2.0)},  // 0.5857...: expected from the MPFR oracle
      {{dy(1, -1022), dy(0), dy(0), dy(1)}, std::numeric_limits<double>::min()},
      {{dy((1L << 53) - 1, -1075), dy(0), dy(0), dy(1)}, std::numeric_limits<double>::min()},  // tie: up
      {{dy((1L << 53) - 3, -1075), dy(0), dy(0), dy(1)}, std::nextafter(0x1p-1022, 0.0) - kDenormMin},
  };
  for (const Fixed& f : fixed) {
    const bool by_mpfr = f.x.a.m == Z(2) && f.x.b.m == Z(-1);
    check_nearest(tally, f.x, by_mpfr ? std::nullopt : std::optional<double>(f.expected));
  }
  report(tally, "nearest/fixed");
  CHECK(tally.cases == static_cast<long>(std::size(fixed)));
}
