// Doubles as text that reads back as the same double (SPEC section 4 prints "%.17g").
#pragma once

#include <cstdio>
#include <string>

namespace apollonius {

// 17 significant digits identify every finite double; non-finite values print as inf, -inf or nan.
inline std::string round_trip(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

}  // namespace apollonius
