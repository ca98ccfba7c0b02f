#include "io/json_output.h"

#include <cmath>

namespace apollonius {

Json json_number(double value) {
  if (std::isfinite(value)) return value;
  return value > 0 ? "inf" : "-inf";
}

void add_point_members(Json& object, const std::array<double, 4>& point) {
  object["x"] = json_number(point[0]);
  object["y"] = json_number(point[1]);
  object["z"] = json_number(point[2]);
  object["r"] = json_number(point[3]);
}

namespace {

// Compact, on one line; bytes that are not UTF-8 (a file name, say) become U+FFFD instead of an exception.
std::string dump(const Json& value) { return value.dump(-1, ' ', false, Json::error_handler_t::replace); }

}  // namespace

void write_json_document(std::ostream& out, const Json& document) {
  out << "{";
  bool first_member = true;
  for (const auto& [key, value] : document.items()) {
    out << (first_member ? "\n  " : ",\n  ") << dump(Json(key)) << ": ";
    first_member = false;
    if (!value.is_array() || value.empty() || !(value.front().is_object() || value.front().is_array())) {
      out << dump(value);
      continue;
    }
    out << "[";
    bool first_element = true;
    for (const Json& element : value) {
      out << (first_element ? "\n    " : ",\n    ") << dump(element);
      first_element = false;
    }
    out << "\n  ]";
  }
  out << "\n}\n";
}

}  // namespace apollonius
