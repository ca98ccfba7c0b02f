// The double nearest to an exact root number (ties to even): the printed coordinates of a vertex.
#pragma once

#include <optional>

#include "predicates/root_sign.h"

namespace apollonius {

// Correctly rounded: a 256-bit MPFR estimate proposes a double, and exact comparisons with the midpoints
// to its neighbours confirm it or move it by one ulp. Overflows round to +-infinity.
double to_nearest_double(const Root_number<Exact>& x);

// A close approximation (MPFR, 256 bits, within 2^-120 of x), for estimates and error reports.
double approximate(const Root_number<Exact>& x);

// An e with 2^(e - 2) <= |x| <= 2^(e + 1), from the same approximation, at any magnitude (where x beyond
// the double range makes approximate() overflow or underflow); nothing for x = 0.
std::optional<long> binary_exponent(const Root_number<Exact>& x);

}  // namespace apollonius
