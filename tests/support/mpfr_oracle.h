// A brute-force oracle for the exact sign helpers of predicates/root_sign.h and for
// predicates/correct_rounding.h: dyadic inputs (integer * 2^e, exactly what the exact type holds), signs of
// a + b1 sqrt(d1) + b2 sqrt(d2) certified with MPFR (at least 1000 bits), and round-to-nearest of
// (a + b sqrt d) / den certified with MPFR enclosures. It shares no code with the helpers under test.
#pragma once

#include <CGAL/Gmpz.h>
#include <CGAL/Mpzf.h>
#include <mpfr.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <ostream>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "predicates/number_types.h"

namespace oracle {

using Z = CGAL::Gmpz;

// CGAL::Gmpz is a shared handle: results are always written into freshly constructed values.
inline int sgn(const Z& x) { return mpz_sgn(x.mpz()); }
inline Z shl(const Z& x, unsigned long k) {
  Z r;
  mpz_mul_2exp(r.mpz(), x.mpz(), k);
  return r;
}
inline Z abs_of(const Z& x) {
  Z r;
  mpz_abs(r.mpz(), x.mpz());
  return r;
}
inline Z from_u64(std::uint64_t v) {
  Z r;
  mpz_import(r.mpz(), 1, 1, sizeof v, 0, 0, &v);
  return r;
}
inline Z isqrt(const Z& x) {
  Z r;
  mpz_sqrt(r.mpz(), x.mpz());
  return r;
}
inline bool is_square(const Z& x) { return sgn(x) >= 0 && mpz_perfect_square_p(x.mpz()) != 0; }
inline Z gcd_of(const Z& x, const Z& y) {
  Z r;
  mpz_gcd(r.mpz(), x.mpz(), y.mpz());
  return r;
}
inline Z exact_div(const Z& x, const Z& y) {
  Z r;
  mpz_divexact(r.mpz(), x.mpz(), y.mpz());
  return r;
}
inline long bits_of(const Z& x) { return sgn(x) == 0 ? 0 : static_cast<long>(mpz_sizeinbase(x.mpz(), 2)); }

// The dyadic number m * 2^e.
struct Dy {
  Z m;
  long e = 0;
};

inline Dy dy(long v, long e = 0) { return Dy{Z(v), e}; }
inline Dy dy(const Z& m, long e = 0) { return Dy{m, e}; }
inline int sgn(const Dy& x) { return sgn(x.m); }
inline Dy scaled(const Dy& x, long k) { return Dy{x.m, x.e + k}; }  // x * 2^k
inline Dy operator-(const Dy& x) { return Dy{-x.m, x.e}; }
inline Dy operator*(const Dy& x, const Dy& y) { return Dy{x.m * y.m, x.e + y.e}; }
inline Dy operator+(const Dy& x, const Dy& y) {
  if (sgn(x) == 0) return y;
  if (sgn(y) == 0) return x;
  const long e = std::min(x.e, y.e);
  return Dy{shl(x.m, static_cast<unsigned long>(x.e - e)) + shl(y.m, static_cast<unsigned long>(y.e - e)), e};
}
inline Dy operator-(const Dy& x, const Dy& y) { return x + (-y); }

inline std::ostream& operator<<(std::ostream& os, const Dy& x) {
  os << x.m;
  if (x.e != 0 && sgn(x) != 0) os << "*2^" << x.e;
  return os;
}

// The exact double g as a dyadic number (g finite).
inline Dy dy_of_double(double g) {
  if (g == 0) return dy(0);
  int exponent = 0;
  const double mantissa = std::frexp(g, &exponent);  // g = mantissa * 2^exponent, 0.5 <= |mantissa| < 1
  return Dy{Z(static_cast<long>(std::ldexp(mantissa, 53))), exponent - 53};
}

// Exactly 2^k as an Mpzf.
inline CGAL::Mpzf power_of_two(long k) {
  if (k >= 0) return apollonius::exact_integer(shl(Z(1), static_cast<unsigned long>(k)));
  CGAL::Mpzf r(1);
  for (; k < -1000; k += 1000) r = r * CGAL::Mpzf(std::ldexp(1.0, -1000));
  return r * CGAL::Mpzf(std::ldexp(1.0, static_cast<int>(k)));
}

inline CGAL::Mpzf to_exact(const Dy& x) { return apollonius::exact_integer(x.m) * power_of_two(x.e); }

// RAII MPFR number.
class Mp {
 public:
  explicit Mp(mpfr_prec_t precision) { mpfr_init2(v_, precision); }
  Mp(const Dy& x, mpfr_prec_t at_least) {
    mpfr_init2(v_, std::max<mpfr_prec_t>(at_least, bits_of(x.m) + 1));
    set_exactly(x);
  }
  ~Mp() { mpfr_clear(v_); }
  Mp(const Mp&) = delete;
  Mp& operator=(const Mp&) = delete;
  mpfr_ptr get() { return v_; }
  mpfr_srcptr get() const { return v_; }
  void set_exactly(const Dy& x) {
    if (mpfr_set_z_2exp(v_, x.m.mpz(), x.e, MPFR_RNDN) != 0) throw std::logic_error("oracle: inexact MPFR input");
  }

 private:
  mpfr_t v_;
};

// The smallest interval of doubles containing x (MPFR rounds correctly, also out of the double range:
// [max, inf] above it, [0, denorm_min] below it).
inline std::pair<double, double> enclosure(const Dy& x) {
  Mp v(x, 64);
  return {mpfr_get_d(v.get(), MPFR_RNDD), mpfr_get_d(v.get(), MPFR_RNDU)};
}

struct Root_term {
  Dy b, d;
};

// a + sum b_i sqrt(d_i) = 2^shift * (A + sum B_i sqrt(D_i)) with integers A, B_i, D_i: write
// d_i = D_i 2^(2 k_i) (making the exponent even by doubling D_i), then bring every term to the lowest
// exponent. Terms with b_i = 0 or d_i = 0 vanish.
struct Integer_form {
  Z a;
  std::vector<std::pair<Z, Z>> terms;  // (B_i, D_i), B_i != 0, D_i > 0
};

inline Integer_form integer_form(const Dy& a, const std::vector<Root_term>& roots) {
  struct Term {
    Z b, d;
    long e;
  };
  std::vector<Term> raw;
  for (const Root_term& r : roots) {
    if (sgn(r.d) < 0) throw std::logic_error("oracle: negative radicand");
    if (sgn(r.b) == 0 || sgn(r.d) == 0) continue;
    Z d = r.d.m;
    long ed = r.d.e;
    if (ed % 2 != 0) {
      d = shl(d, 1);
      ed -= 1;
    }
    raw.push_back({r.b.m, d, r.b.e + ed / 2});
  }
  long lowest = std::numeric_limits<long>::max();
  if (sgn(a) != 0) lowest = a.e;
  for (const Term& t : raw) lowest = std::min(lowest, t.e);
  Integer_form form;
  if (sgn(a) != 0) form.a = shl(a.m, static_cast<unsigned long>(a.e - lowest));
  for (const Term& t : raw) form.terms.emplace_back(shl(t.b, static_cast<unsigned long>(t.e - lowest)), t.d);
  return form;
}

// Whether A + sum B_i sqrt(D_i) is zero, decided by algebra alone (no numerics): perfect-square radicands
// join the rational part; sqrt(D) is irrational for a non-square D; for non-squares D1, D2 the numbers
// 1, sqrt(D1), sqrt(D2) are linearly independent over Q unless D1 D2 = s^2 is a square, and then
// sqrt(D2) = (s / D1) sqrt(D1).
inline bool zero_by_algebra(const Integer_form& form) {
  Z rational = form.a;
  std::vector<std::pair<Z, Z>> irrational;
  for (const auto& [b, d] : form.terms) {
    if (is_square(d))
      rational = rational + b * isqrt(d);
    else
      irrational.emplace_back(b, d);
  }
  if (irrational.empty()) return sgn(rational) == 0;
  if (irrational.size() == 1) return false;
  if (irrational.size() > 2) throw std::logic_error("oracle: at most two roots");
  const auto& [b1, d1] = irrational[0];
  const auto& [b2, d2] = irrational[1];
  const Z product = d1 * d2;
  if (!is_square(product)) return false;
  // x = rational + (b1 d1 + b2 s) / d1 * sqrt(d1)
  return sgn(rational) == 0 && sgn(b1 * d1 + b2 * isqrt(product)) == 0;
}

// The certified sign of x = A + sum B_i sqrt(D_i) (at most two roots), by MPFR.
//
// Separation bound. x is an algebraic integer of K = Q(sqrt(D1), sqrt(D2)), [K:Q] <= 4 (<= 2 with one
// root). Every embedding of K flips signs of the roots, so every conjugate of x has magnitude at most
// M = |A| + sum |B_i| sqrt(D_i). If x != 0 its norm, the product of its [K:Q] conjugates (embeddings
// are injective), is a nonzero integer, so |x| >= 1 / M^([K:Q]-1) >= 1 / M^k with k = 1 for one root and
// k = 3 for two (M >= 1 whenever x != 0). With M < 2^E: a nonzero x has |x| > 2^(-kE).
//
// Evaluation error. With the integers stored exactly and each of sqrt, *, + rounded to nearest at p bits
// (relative error <= 2^-p per operation), |v - x| <= 5 M 2^-p < 2^(E + 3 - p). We take
// p = max(1000, (k + 1) E + 8), so |v - x| < 2^(-kE - 5).
//
// Decision. "Below the bound" means |v| < 2^(-kE - 1). If x = 0 then |v| < 2^(-kE - 5): below. If x != 0
// then |v| > 2^(-kE) - 2^(-kE - 5) >= 2^(-kE - 1): not below, and sign(v) = sign(x) since |v - x| < |x|.
// So below_bound is exactly x == 0; the tests still assert it against the construction and against
// zero_by_algebra, so that the oracle itself is checked.
struct Certified_sign {
  int sign = 0;
  bool below_bound = false;
  mpfr_prec_t precision = 0;
};

inline Certified_sign certified_sign(const Integer_form& form) {
  if (form.terms.size() > 2) throw std::logic_error("oracle: at most two roots");
  const long k = form.terms.size() <= 1 ? 1 : 3;
  Mp m(64), t(64);
  mpfr_set_z(m.get(), form.a.mpz(), MPFR_RNDU);
  mpfr_abs(m.get(), m.get(), MPFR_RNDU);
  for (const auto& [b, d] : form.terms) {
    mpfr_set_z(t.get(), d.mpz(), MPFR_RNDU);
    mpfr_sqrt(t.get(), t.get(), MPFR_RNDU);
    Mp bb(64);
    mpfr_set_z(bb.get(), abs_of(b).mpz(), MPFR_RNDU);
    mpfr_mul(t.get(), t.get(), bb.get(), MPFR_RNDU);
    mpfr_add(m.get(), m.get(), t.get(), MPFR_RNDU);
  }
  Certified_sign result;
  if (mpfr_zero_p(m.get())) {
    result.below_bound = true;
    return result;
  }
  const long E = std::max<long>(1, mpfr_get_exp(m.get()));  // M < 2^E
  const mpfr_prec_t p = std::max<mpfr_prec_t>(1000, (k + 1) * E + 8);
  result.precision = p;
  Mp v(Dy{form.a, 0}, p);  // |A| <= M < 2^E: stored exactly, at precision p
  Mp root(p), term(p);
  for (const auto& [b, d] : form.terms) {
    Mp dd(Dy{d, 0}, p), bb(Dy{b, 0}, p);  // D <= M^2, |B| <= M: stored exactly
    mpfr_sqrt(root.get(), dd.get(), MPFR_RNDN);
    mpfr_mul(term.get(), root.get(), bb.get(), MPFR_RNDN);
    mpfr_add(v.get(), v.get(), term.get(), MPFR_RNDN);
  }
  result.below_bound = mpfr_zero_p(v.get()) || mpfr_get_exp(v.get()) <= -k * E - 1;  // |v| < 2^(-kE-1)
  result.sign = result.below_bound ? 0 : mpfr_sgn(v.get());
  return result;
}

// Round-to-nearest (ties to even) of x = (a + b sqrt d) / den, den > 0, certified by an MPFR enclosure:
// v is computed at p bits with |v - x| <= err = 8 M / den 2^-p (M = |a| + |b| sqrt d; the same per-operation
// argument as above plus one division), and the answer is certain when RN(v - err) == RN(v + err) (rounding
// is monotone). Precision doubles from 1000 up to 16000 bits; an exact midpoint is never certain.
struct Certified_double {
  bool certain = false;
  double value = 0;
  mpfr_prec_t precision = 0;
};

inline Certified_double certified_nearest(const Dy& a, const Dy& b, const Dy& d, const Dy& den) {
  Certified_double result;
  for (mpfr_prec_t p = 1000; p <= 16000; p *= 2) {
    result.precision = p;
    Mp ma(a, p), mb(b, p), md(d, p), mden(den, p);
    Mp v(p), root(p), bound(64), scratch(64);
    mpfr_sqrt(root.get(), md.get(), MPFR_RNDN);
    mpfr_mul(v.get(), root.get(), mb.get(), MPFR_RNDN);
    mpfr_add(v.get(), v.get(), ma.get(), MPFR_RNDN);
    mpfr_div(v.get(), v.get(), mden.get(), MPFR_RNDN);
    // err = 8 M / den * 2^-p, rounded upwards
    mpfr_sqrt(bound.get(), md.get(), MPFR_RNDU);
    mpfr_abs(scratch.get(), mb.get(), MPFR_RNDU);
    mpfr_mul(bound.get(), bound.get(), scratch.get(), MPFR_RNDU);
    mpfr_abs(scratch.get(), ma.get(), MPFR_RNDU);
    mpfr_add(bound.get(), bound.get(), scratch.get(), MPFR_RNDU);
    mpfr_div(bound.get(), bound.get(), mden.get(), MPFR_RNDU);
    mpfr_mul_2si(bound.get(), bound.get(), 3 - p, MPFR_RNDU);
    Mp lo(p + 64), hi(p + 64);
    mpfr_sub(lo.get(), v.get(), bound.get(), MPFR_RNDD);
    mpfr_add(hi.get(), v.get(), bound.get(), MPFR_RNDU);
    const double dlo = mpfr_get_d(lo.get(), MPFR_RNDN), dhi = mpfr_get_d(hi.get(), MPFR_RNDN);
    if (dlo == dhi) {  // -0 == +0: both are the zero of the double line
      result.certain = true;
      result.value = dhi;
      return result;
    }
  }
  return result;
}

// sqrt(d) when d is the square of a dyadic number.
inline std::optional<Dy> dyadic_sqrt(const Dy& d) {
  if (sgn(d) == 0) return dy(0);
  Z m = d.m;
  long e = d.e;
  if (e % 2 != 0) {
    m = shl(m, 1);
    e -= 1;
  }
  if (!is_square(m)) return std::nullopt;
  return Dy{isqrt(m), e / 2};
}

// Round-to-nearest, ties to even, of the rational num / den (den > 0) to a double, including subnormals
// and overflow, by MPFR's documented emulation of IEEE double: one correctly rounded division to 53 bits
// (unbounded exponent, ternary value t), then mpfr_check_range and mpfr_subnormalize in the exponent range
// of doubles, which use t to avoid double rounding.
inline double nearest_of_quotient(const Dy& num, const Dy& den) {
  if (sgn(num) == 0) return 0.0;
  Mp n(num, 2), dd(den, 2), q(53);
  int t = mpfr_div(q.get(), n.get(), dd.get(), MPFR_RNDN);
  const mpfr_exp_t emin = mpfr_get_emin(), emax = mpfr_get_emax();
  mpfr_set_emin(-1073);
  mpfr_set_emax(1024);
  t = mpfr_check_range(q.get(), t, MPFR_RNDN);
  t = mpfr_subnormalize(q.get(), t, MPFR_RNDN);
  const double result = mpfr_get_d(q.get(), MPFR_RNDN);
  mpfr_set_emin(emin);
  mpfr_set_emax(emax);
  return result;
}

// Deterministic per-case seeds: splitmix64 of (base, family, index).
inline std::uint64_t splitmix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}
inline std::uint64_t case_seed(std::uint64_t base, std::uint64_t family, std::uint64_t index) {
  return splitmix(splitmix(splitmix(base) ^ family) ^ index);
}

// Random integers for the generators.
class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}
  std::uint64_t word() { return engine_(); }
  long uniform(long lo, long hi) { return std::uniform_int_distribution<long>(lo, hi)(engine_); }
  bool chance(double p) { return std::uniform_real_distribution<double>(0, 1)(engine_) < p; }
  int sign() { return chance(0.5) ? 1 : -1; }
  // Nonnegative, exactly `bits` bits (0 for bits = 0).
  Z with_bits(long bits) {
    if (bits <= 0) return Z(0);
    Z r(0);
    for (long have = 0; have < bits; have += 64) r = shl(r, 64) + from_u64(word());
    Z t;
    mpz_fdiv_r_2exp(t.mpz(), r.mpz(), static_cast<unsigned long>(bits - 1));
    return t + shl(Z(1), static_cast<unsigned long>(bits - 1));
  }
  // Nonnegative with a bit length uniform in [0, max_bits]: small values are as likely as big ones.
  Z natural(long max_bits) { return with_bits(uniform(0, max_bits)); }
  Z positive(long max_bits) { return with_bits(uniform(1, std::max<long>(1, max_bits))); }
  Z integer(long max_bits) { return signed_(natural(max_bits)); }
  Z nonzero(long max_bits) { return signed_(positive(max_bits)); }
  Z signed_(const Z& x) { return chance(0.5) ? x : -x; }

 private:
  std::mt19937_64 engine_;
};

}  // namespace oracle
