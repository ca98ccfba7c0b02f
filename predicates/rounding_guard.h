// RAII guards. Interval arithmetic needs the FPU rounding towards +infinity (CGAL's convention) while the
// guard lives; the caller's mode is restored when it goes out of scope.
#pragma once

#include <CGAL/FPU.h>

namespace apollonius {

class Rounding_guard {
 public:
  Rounding_guard() = default;
  Rounding_guard(const Rounding_guard&) = delete;
  Rounding_guard& operator=(const Rounding_guard&) = delete;

 private:
  CGAL::Protect_FPU_rounding<true> protect_;
};

// The same for round-to-nearest, which double-double balls need (vertex_ball.h) inside code that may run
// under a Rounding_guard.
class Nearest_rounding_guard {
 public:
  Nearest_rounding_guard() = default;
  Nearest_rounding_guard(const Nearest_rounding_guard&) = delete;
  Nearest_rounding_guard& operator=(const Nearest_rounding_guard&) = delete;

 private:
  CGAL::Protect_FPU_rounding<true> protect_{CGAL_FE_TONEAREST};
};

}  // namespace apollonius
