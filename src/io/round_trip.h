// Doubles as text that reads back as the same double (SPEC section 4 prints "%.17g").
#pragma once

#include <charconv>
#include <string>

namespace apollonius {

// 17 significant digits identify every finite double; non-finite values print as inf, -inf or nan.
// std::to_chars with a precision is specified to print as printf's %.17g does, several times faster.
inline std::string round_trip(double value) {
  char text[32];
  const std::to_chars_result result = std::to_chars(text, text + sizeof text, value, std::chars_format::general, 17);
  return std::string(text, result.ptr);
}

}  // namespace apollonius
