// The filters' trisector basis (trisector.cpp): where the first nonzero minor of the rows is tiny beside
// another, the interval geometry takes its basis from the larger minor's columns. Its e1, e2 and monotone must
// then be positive multiples of the exact ones (every predicate on them is a sign, homogeneous in each), and
// its centre and K, which do not depend on the basis, must hold the exact ones. On sites 5e-324 off a lattice
// plane beside sites at 4, where the first minor's basis had entries near 1e324, the intervals must decide.
#include <doctest/doctest.h>

#include <cmath>
#include <optional>
#include <random>
#include <string>

#include "predicates/is_hidden.h"
#include "predicates/rational.h"
#include "predicates/rounding_guard.h"
#include "predicates/trisector.h"
#include "reference/site_generators.h"
#include "support/site_triples.h"

using namespace apollonius;
using apollonius::testing::for_each_triple;

namespace {

// Whether c x lies in the box for some c > 0: each coordinate bounds c to an interval; they must meet above 0.
// An infinite bound of the box bounds nothing.
bool positive_multiple_in(const Vector4<Interval>& box, const Vector4<Rational>& x) {
  std::optional<Rational> low, high;  // c >= low, c <= high (nothing: unbounded)
  for (int j = 0; j < 4; ++j) {
    const bool lo_finite = std::isfinite(box[j].inf()), hi_finite = std::isfinite(box[j].sup());
    const Sign s = certain_sign(x[j]);
    if (s == Sign::ZERO) {
      if ((lo_finite && box[j].inf() > 0) || (hi_finite && box[j].sup() < 0)) return false;
      continue;
    }
    std::optional<Rational> a, b;  // c between a and b, before the sign of x[j] orders them
    if (lo_finite) a = Rational(box[j].inf()) / x[j];
    if (hi_finite) b = Rational(box[j].sup()) / x[j];
    if (s == Sign::NEGATIVE) std::swap(a, b);
    if (a && (!low || *a > *low)) low = a;
    if (b && (!high || *b < *high)) high = b;
  }
  return !high || (*high > 0 && (!low || *high >= *low));
}

bool holds(const Interval& box, const Rational& x) {
  return (!std::isfinite(box.inf()) || Rational(box.inf()) <= x) && (!std::isfinite(box.sup()) || x <= Rational(box.sup()));
}

struct Counts {
  int triples = 0, decided = 0;
};

void check_basis(const std::array<Site, 3>& s, Counts& counts) {
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j)
      if (is_hidden(s[i], static_cast<Site_index>(i), s[j], static_cast<Site_index>(j)) ||
          is_hidden(s[j], static_cast<Site_index>(j), s[i], static_cast<Site_index>(i)))
        return;
  ++counts.triples;
  const Trisector t({0, 1, 2}, s);
  const Trisector_geometry<Interval>* g = nullptr;
  try {
    g = &t.geometry<Interval>();
  } catch (const Uncertain_sign&) {
    return;
  }
  ++counts.decided;
  const Trisector_geometry<Rational>& exact = t.geometry<Rational>();
  CHECK(g->kind == exact.kind);
  CHECK(g->shape == exact.shape);
  if (exact.kind != Trisector_kind::ellipse && exact.kind != Trisector_kind::hyperbola) return;
  CHECK(positive_multiple_in(g->e1, exact.e1));
  CHECK(positive_multiple_in(g->e2, exact.e2));
  if (exact.kind == Trisector_kind::hyperbola) {  // monotone, for open curves only
    CHECK(positive_multiple_in(g->monotone, exact.monotone));
    CHECK(g->branch_axis == exact.branch_axis);
    CHECK(g->branch_sign == exact.branch_sign);
  }
  CHECK(holds(g->K, exact.K));
  for (int j = 0; j < 4; ++j) CHECK(holds(g->centre[j], exact.centre[j]));
}

// A site of the plane x = 0 of a lattice of spacing 4, moved off it by -5e-324, 0 or 5e-324.
Site off_plane(std::mt19937_64& random) {
  std::uniform_int_distribution<int> step(-1, 1), cell(0, 12), weight(0, 1);
  return {step(random) * 0x1p-1074, 4.0 * cell(random), 4.0 * cell(random), weight(random) ? 1.5 : 1.0};
}

}  // namespace

TEST_CASE("one ulp off a lattice plane the intervals decide, with the exact basis up to positive factors") {
  std::mt19937_64 random(20261203);
  Counts counts;
  for (int trial = 0; trial < 3000; ++trial) {
    CAPTURE(trial);
    const std::array<Site, 3> s{off_plane(random), off_plane(random), off_plane(random)};
    if (s[0] == s[1] || s[0] == s[2] || s[1] == s[2]) continue;
    CAPTURE(s[0].x);
    CAPTURE(s[1].x);
    CAPTURE(s[2].x);
    check_basis(s, counts);
  }
  MESSAGE(counts.decided << " of " << counts.triples << " triples decided in intervals");
  CHECK(counts.decided * 10 > counts.triples * 9);
}

TEST_CASE("on lattices one ulp off and on random sites the interval basis is the exact one up to positive factors") {
  Counts lattice, uniform;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    CAPTURE(seed);
    for_each_triple(generate_sites(Site_family::lattice_noise, 16, seed),
                    [&](const std::array<Site, 3>& s) { check_basis(s, lattice); });
    for_each_triple(generate_sites(Site_family::uniform, 12, seed),
                    [&](const std::array<Site, 3>& s) { check_basis(s, uniform); });
  }
  MESSAGE("lattice one ulp off: " << lattice.decided << " of " << lattice.triples << "; uniform: " << uniform.decided
                                  << " of " << uniform.triples);
  CHECK(lattice.decided > lattice.triples / 2);
  CHECK(uniform.decided * 100 > uniform.triples * 99);
}
