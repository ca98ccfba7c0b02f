// JSON output (nlohmann-json): documents are ordered_json objects, members in the order written, laid out
// with each element of a top-level array on a line of its own, so that large outputs stay readable and
// line-oriented tools (grep, diff) work on them.
#pragma once

#include <nlohmann/json.hpp>

#include <array>
#include <ostream>

namespace apollonius {

using Json = nlohmann::ordered_json;

// A number, or the string "inf" or "-inf" for a coordinate that overflowed (JSON has no infinity).
Json json_number(double value);

// Adds "x", "y", "z", "r", the members of a vertex or point object.
void add_point_members(Json& object, const std::array<double, 4>& point);

// The top-level object: one member per line, the elements of its arrays one per line, anything deeper on
// the line of its element. Numbers are printed in shortest round-trip form.
void write_json_document(std::ostream& out, const Json& document);

}  // namespace apollonius
