#include "io/json_output.h"

#include <cmath>
#include <cstdio>

namespace apollonius {

std::string json_number(double value) {
  if (std::isfinite(value)) return round_trip(value);
  return "\"" + round_trip(value) + "\"";
}

std::string json_point_members(const std::array<double, 4>& point) {
  return "\"x\": " + json_number(point[0]) + ", \"y\": " + json_number(point[1]) + ", \"z\": " + json_number(point[2]) +
         ", \"r\": " + json_number(point[3]);
}

std::string json_string(const std::string& text) {
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      quoted += '\\';
      quoted += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char escape[8];
      std::snprintf(escape, sizeof escape, "\\u%04x", static_cast<unsigned>(c));
      quoted += escape;
    } else {
      quoted += c;
    }
  }
  return quoted + "\"";
}

}  // namespace apollonius
