// Staged evaluation (docs/design.md, "Arithmetic"), wrapped around a predicate from outside as in CGAL's
// Filtered_predicate: the predicate is one function template `evaluate<NT>`, run first with Interval
// under a Rounding_guard, and again with Exact only if some interval sign was uncertain.
#pragma once

#include <type_traits>
#include <utility>

#include "predicates/number_types.h"
#include "predicates/predicate_counter.h"
#include "predicates/rounding_guard.h"

namespace apollonius {

// Predicate must provide `static constexpr const char* name` and `template <class NT> static R evaluate(...)`;
// it may provide `static std::optional<R> static_filter(...)`, a cheaper first stage in plain doubles with
// a derived error bound (docs/ERROR_BOUNDS.md), which answers only when certain; it may provide
// `static std::optional<R> interval_stage(...)`, which replaces `evaluate<Interval>` (inside the same
// Rounding_guard) and answers nothing instead of throwing, where most evaluations go on to the exact
// stage and an exception would cost more than the predicate; it may provide
// `static std::optional<R> ball_stage(...)`, double-double balls in round-to-nearest (vertex_ball.h),
// tried where the intervals are not certain; it may provide `static std::optional<R> wide_stage(...)`,
// wide intervals (wide_interval.h) under a Rounding_guard, for values beyond the double range that the
// stages before overflow or underflow; it may provide `static std::optional<R> precise_stage(...)`, MPFR
// intervals (mpfr_interval.h), for signs a hair from zero; and `using Exact_number = Rational;` when
// its exact stage divides (the default, Exact, never does).
template <class P, class = void>
struct Exact_number_of {
  using type = Exact;
};
template <class P>
struct Exact_number_of<P, std::void_t<typename P::Exact_number>> {
  using type = typename P::Exact_number;
};

template <class Predicate>
class Filtered_predicate {
 public:
  template <class... Args>
  auto operator()(const Args&... args) const {
    counter().count_evaluation();
    if constexpr (has_static_filter<Predicate, Args...>(0)) {
      if (const auto certain = Predicate::static_filter(args...)) return *certain;
    }
    if constexpr (has_interval_stage<Predicate, Args...>(0)) {
      Rounding_guard guard;
      if (const auto certain = Predicate::interval_stage(args...)) return *certain;
    } else {
      Rounding_guard guard;
      try {
        return Predicate::template evaluate<Interval>(args...);
      } catch (const Uncertain_sign&) {
      }
    }
    if constexpr (has_ball_stage<Predicate, Args...>(0)) {
      if (const auto certain = Predicate::ball_stage(args...)) return *certain;
    }
    if constexpr (has_wide_stage<Predicate, Args...>(0)) {
      Rounding_guard guard;
      if (const auto certain = Predicate::wide_stage(args...)) return *certain;
    }
    if constexpr (has_precise_stage<Predicate, Args...>(0)) {
      if (const auto certain = Predicate::precise_stage(args...)) return *certain;
    }
    counter().count_exact_stage();
    return Predicate::template evaluate<typename Exact_number_of<Predicate>::type>(args...);
  }

  // The floating path: the predicate in plain doubles, no filter and no exact stage.
  template <class... Args>
  auto floating(const Args&... args) const {
    counter().count_evaluation();
    return Predicate::template evaluate<double>(args...);
  }

  template <class P, class... Args>
  static constexpr auto has_static_filter(int) -> decltype(P::static_filter(std::declval<const Args&>()...), true) {
    return true;
  }
  template <class P, class... Args>
  static constexpr bool has_static_filter(...) {
    return false;
  }

  template <class P, class... Args>
  static constexpr auto has_interval_stage(int) -> decltype(P::interval_stage(std::declval<const Args&>()...), true) {
    return true;
  }
  template <class P, class... Args>
  static constexpr bool has_interval_stage(...) {
    return false;
  }

  template <class P, class... Args>
  static constexpr auto has_ball_stage(int) -> decltype(P::ball_stage(std::declval<const Args&>()...), true) {
    return true;
  }
  template <class P, class... Args>
  static constexpr bool has_ball_stage(...) {
    return false;
  }

  template <class P, class... Args>
  static constexpr auto has_wide_stage(int) -> decltype(P::wide_stage(std::declval<const Args&>()...), true) {
    return true;
  }
  template <class P, class... Args>
  static constexpr bool has_wide_stage(...) {
    return false;
  }

  template <class P, class... Args>
  static constexpr auto has_precise_stage(int) -> decltype(P::precise_stage(std::declval<const Args&>()...), true) {
    return true;
  }
  template <class P, class... Args>
  static constexpr bool has_precise_stage(...) {
    return false;
  }

  static Predicate_counter& counter() {
    static Predicate_counter instance(Predicate::name);
    return instance;
  }
};

}  // namespace apollonius
