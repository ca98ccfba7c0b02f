// Rationals (number_types.h) for the predicates that divide (the trisectors' bases and centres). The
// vertex algebra stays in Exact (number_types.h), which every double is exactly and which never divides.
#pragma once

#include "predicates/number_types.h"

namespace apollonius {

// The same number, exactly.
Rational to_rational(const Exact& x);

}  // namespace apollonius
