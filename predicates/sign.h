// The result type of every predicate, and the one place where an uncertain filter sign is rejected.
#pragma once

#include <stdexcept>

namespace apollonius {

enum class Sign : signed char { NEGATIVE = -1, ZERO = 0, POSITIVE = 1 };

constexpr Sign operator-(Sign s) { return static_cast<Sign>(-static_cast<int>(s)); }
constexpr Sign operator*(Sign a, Sign b) { return static_cast<Sign>(static_cast<int>(a) * static_cast<int>(b)); }
constexpr int to_int(Sign s) { return static_cast<int>(s); }

const char* to_string(Sign s);

// Thrown by a filter stage when its interval straddles zero. It is never turned into ZERO: the filter
// wrapper (filtered_predicate.h) catches it and reruns the predicate exactly.
struct Uncertain_sign : std::exception {
  const char* what() const noexcept override { return "uncertain sign in a filter stage"; }
};

}  // namespace apollonius
