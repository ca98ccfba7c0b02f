// Doubles as text that reads back as the same double (docs/contract.md prints "%.17g").
#pragma once

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

namespace apollonius {

namespace round_trip_detail {

__extension__ typedef unsigned __int128 Wide;  // GCC and clang; __extension__ keeps -Wpedantic quiet

constexpr std::uint64_t power_of_ten(int k) {
  std::uint64_t p = 1;
  for (int i = 0; i < k; ++i) p *= 10;
  return p;
}
constexpr std::uint64_t kLeast17 = power_of_ten(16), kBeyond17 = power_of_ten(17);

// round(m 2^e 10^k) to nearest, ties to even, exactly; needs 0 <= k <= 32 (m 5^k < 2^128 for m < 2^53).
inline Wide scaled_rounded(std::uint64_t m, int e, int k) {
  Wide p = m;
  for (int i = 0; i < k; ++i) p *= 5;
  const int shift = e + k;  // m 2^e 10^k = p 2^shift
  if (shift >= 0) return shift >= 64 ? ~Wide{0} : p << shift;  // beyond 17 digits either way
  const int drop = -shift;
  if (drop >= 127) return 0;
  const Wide kept = p >> drop, rest = p - (kept << drop), half = Wide{1} << (drop - 1);
  return rest > half || (rest == half && (kept & 1)) ? kept + 1 : kept;
}

}  // namespace round_trip_detail

// Writes value as printf's "%.17g" does into out (room for 32 chars) and returns the end. 17 significant
// digits identify every finite double. Values in [1e-14, 1e17) take an exact integer path: the 17 digits
// are m 2^e 10^(16 - d) rounded to nearest (ties to even, as printf rounds the exact binary value) in
// 128-bit arithmetic, d the decimal exponent. Others, zeros and non-finite values go to std::to_chars,
// which prints as printf does.
inline char* write_round_trip(char* out, double value) {
  using namespace round_trip_detail;
  const double magnitude = std::fabs(value);
  if (!(magnitude >= 1e-14 && magnitude < 1e17))
    return std::to_chars(out, out + 32, value, std::chars_format::general, 17).ptr;
  int exponent;
  const double fraction = std::frexp(magnitude, &exponent);  // magnitude = fraction 2^exponent, fraction in [1/2, 1)
  const auto m = static_cast<std::uint64_t>(std::ldexp(fraction, 53));
  const int e = exponent - 53;
  // d with 10^d <= magnitude < 10^(d + 1), from an estimate corrected exactly: 17 digits N in [10^16, 10^17).
  // The estimate is off by at most one, and d lies in [-15, 16]: 16 - d stays in [0, 32].
  int d = std::clamp(static_cast<int>(std::floor(std::log10(magnitude))), -15, 16);
  Wide digits = scaled_rounded(m, e, 16 - d);
  if (digits >= kBeyond17) {  // the estimate was low
    digits = scaled_rounded(m, e, 16 - ++d);
  } else if (digits <= kLeast17) {  // it may be high: a value below 10^d takes its digits from d - 1
    const Wide lower = scaled_rounded(m, e, 17 - d);
    if (lower < kBeyond17) digits = lower, --d;
  }
  if (digits >= kBeyond17) digits = kLeast17, ++d;  // rounded up to the next power of ten, as printf does
  char text[17];
  auto n = static_cast<std::uint64_t>(digits);
  for (int i = 16; i >= 0; --i, n /= 10) text[i] = static_cast<char>('0' + n % 10);
  int significant = 17;  // "%g" drops trailing zeros of the fraction
  while (significant > 1 && text[significant - 1] == '0') --significant;
  if (value < 0) *out++ = '-';
  // d <= 16 here: the doubles of [1e16, 1e17) are integers of 17 digits, so rounding never carries to 1e17,
  // and %g's scientific form (exponent < -4 or >= 17) only ever has a negative exponent.
  if (d < -4) {  // scientific: D.DDDe-XX
    *out++ = text[0];
    if (significant > 1) {
      *out++ = '.';
      std::memcpy(out, text + 1, significant - 1), out += significant - 1;
    }
    const int shown = -d;
    *out++ = 'e', *out++ = '-';
    if (shown < 10) *out++ = '0';
    return std::to_chars(out, out + 4, shown).ptr;
  }
  if (d < 0) {  // 0.000DDD
    *out++ = '0', *out++ = '.';
    for (int i = -1; i > d; --i) *out++ = '0';
    std::memcpy(out, text, significant);
    return out + significant;
  }
  const int whole = d + 1;  // digits before the point
  std::memcpy(out, text, whole), out += whole;
  if (significant > whole) {
    *out++ = '.';
    std::memcpy(out, text + whole, significant - whole), out += significant - whole;
  }
  return out;
}

inline std::string round_trip(double value) {
  char text[32];
  return std::string(text, write_round_trip(text, value));
}

}  // namespace apollonius
