// RAII guard: interval arithmetic needs the FPU rounding towards +infinity (CGAL's convention) while the
// guard lives, and round-to-nearest is restored when it goes out of scope.
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

}  // namespace apollonius
