// Staged evaluation (SPEC section 3), wrapped around a predicate from outside as in CGAL's
// Filtered_predicate: the predicate is one function template `evaluate<NT>`, run first with Interval
// under a Rounding_guard, and again with Exact only if some interval sign was uncertain.
#pragma once

#include "number_types.h"
#include "predicate_counter.h"
#include "rounding_guard.h"

namespace apollonius {

// Predicate must provide `static constexpr const char* name` and `template <class NT> static R evaluate(...)`.
template <class Predicate>
class Filtered_predicate {
 public:
  template <class... Args>
  auto operator()(const Args&... args) const {
    counter().count_evaluation();
    {
      Rounding_guard guard;
      try {
        return Predicate::template evaluate<Interval>(args...);
      } catch (const Uncertain_sign&) {
      }
    }
    counter().count_exact_stage();
    return Predicate::template evaluate<Exact>(args...);
  }

  static Predicate_counter& counter() {
    static Predicate_counter instance(Predicate::name);
    return instance;
  }
};

}  // namespace apollonius
