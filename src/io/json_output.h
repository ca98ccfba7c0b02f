// Pieces of JSON output shared by the writers (vertex lists, certify reports).
#pragma once

#include <array>
#include <cstddef>
#include <ostream>
#include <string>

#include "io/round_trip.h"

namespace apollonius {

// A number, or the string "inf" or "-inf", which JSON lacks.
std::string json_number(double value);

// "x": X, "y": Y, "z": Z, "r": R, the members of a vertex or point object.
std::string json_point_members(const std::array<double, 4>& point);

// A quoted, escaped string.
std::string json_string(const std::string& text);

// [a, b, c] on one line.
template <class Integers>
std::string json_array(const Integers& values) {
  std::string array = "[";
  for (const auto value : values) {
    if (array.size() > 1) array += ", ";
    array += std::to_string(value);
  }
  return array + "]";
}

// Elements one per line between "[" and "]", separated by commas, element(i) giving the i-th.
template <class Element>
void write_json_lines(std::ostream& out, std::size_t count, const Element& element) {
  out << "[";
  for (std::size_t i = 0; i < count; ++i) out << (i == 0 ? "\n    " : ",\n    ") << element(i);
  out << (count == 0 ? "]" : "\n  ]");
}

}  // namespace apollonius
