// A rational strictly between two different real numbers of Q(sqrt d1) and Q(sqrt d2): where a witness
// point goes between two vertices on a curve. Exact: the two numbers are enclosed by rational intervals
// from integer square roots at doubling precision until the intervals separate, which happens because the
// numbers differ; then the midpoint of the gap.
#pragma once

#include <utility>

#include "predicates/root_sign.h"
#include "predicates/rational.h"

namespace apollonius {

// Precondition: x < y (compare(x, y) == NEGATIVE).
Rational rational_between(const Root_number<Rational>& x, const Root_number<Rational>& y);

// Rationals low <= x <= high, from sqrt(d) enclosed within 2^-bits relative.
std::pair<Rational, Rational> rational_bounds(const Root_number<Rational>& x, unsigned long bits);

}  // namespace apollonius
