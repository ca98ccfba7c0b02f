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
// The stages a predicate may provide, as expressions on its arguments, and whether it provides one:
// provides<Stage, P, Args...> is true where Stage<P, Args...> names a type.
template <class P, class... A>
using Static_filter = decltype(P::static_filter(std::declval<const A&>()...));
template <class P, class... A>
using Interval_stage = decltype(P::interval_stage(std::declval<const A&>()...));
template <class P, class... A>
using Ball_stage = decltype(P::ball_stage(std::declval<const A&>()...));
template <class P, class... A>
using Wide_stage = decltype(P::wide_stage(std::declval<const A&>()...));
template <class P, class... A>
using Precise_stage = decltype(P::precise_stage(std::declval<const A&>()...));

template <class, template <class...> class Stage, class... Ts>
struct Provides : std::false_type {};
template <template <class...> class Stage, class... Ts>
struct Provides<std::void_t<Stage<Ts...>>, Stage, Ts...> : std::true_type {};
template <template <class...> class Stage, class... Ts>
inline constexpr bool provides = Provides<void, Stage, Ts...>::value;

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
    if constexpr (provides<Static_filter, Predicate, Args...>) {
      if (const auto certain = Predicate::static_filter(args...)) return *certain;
    }
    if constexpr (provides<Interval_stage, Predicate, Args...>) {
      Rounding_guard guard;
      if (const auto certain = Predicate::interval_stage(args...)) return *certain;
    } else {
      Rounding_guard guard;
      try {
        return Predicate::template evaluate<Interval>(args...);
      } catch (const Uncertain_sign&) {
      }
    }
    if constexpr (provides<Ball_stage, Predicate, Args...>) {
      if (const auto certain = Predicate::ball_stage(args...)) return *certain;
    }
    if constexpr (provides<Wide_stage, Predicate, Args...>) {
      Rounding_guard guard;
      if (const auto certain = Predicate::wide_stage(args...)) return *certain;
    }
    if constexpr (provides<Precise_stage, Predicate, Args...>) {
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

  static Predicate_counter& counter() {
    static Predicate_counter instance(Predicate::name);
    return instance;
  }
};

}  // namespace apollonius
