// Why predicates/root_sign.h has its own two-root sign rule instead of CGAL's: CGAL 5.5's
// sign_a_plus_b_x_sqrt_e_plus_c_x_sqrt_f_plus_d_sqrt_e_x_f (CGAL/functions_on_signs.h) returns ZERO as
// soon as a + b sqrt(e) = 0, dropping the term (c + d sqrt(e)) sqrt(f). This test pins that bug down: if it
// fails, CGAL has changed, and the choice deserves a second look.
#include <doctest/doctest.h>

#include <CGAL/functions_on_signs.h>

#include "predicates/root_sign.h"

using apollonius::Exact;

TEST_CASE("CGAL's two-root sign helper says ZERO for a + b sqrt(e) = 0 whatever (c + d sqrt(e)) sqrt(f) is") {
  // 2 - sqrt(4) + c sqrt(2) = c sqrt(2); with d = 0 it is a + b sqrt(e) + c sqrt(f), our sign_of_two_root_sum.
  const Exact a(2), b(-1), e(4), d(0), f(2);
  for (const int c : {1, -1}) {
    CAPTURE(c);
    CHECK(to_int(apollonius::sign_of_two_root_sum(a, b, e, Exact(c), f)) == c);
    CHECK(CGAL::sign_a_plus_b_x_sqrt_e_plus_c_x_sqrt_f_plus_d_sqrt_e_x_f(a, b, Exact(c), d, e, f) == CGAL::ZERO);
  }
}
