#include "predicates/rational.h"

namespace apollonius {

Rational to_rational(const Exact& x) { return static_cast<Rational>(x); }

}  // namespace apollonius
