// A JSON document read into a tree that remembers the line of every value, so that a reader of a JSON
// input can name the line of a bad value (SPEC section 4: file, line and reason).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace apollonius {

struct Json_value {
  enum class Kind { null, boolean, number, string, array, object };
  Kind kind = Kind::null;
  std::size_t line = 0;  // 1-based line where the value starts
  // number: its literal text (convert it with from_chars for the nearest double); string: the decoded
  // text (UTF-8); boolean: "true" or "false".
  std::string text;
  std::vector<Json_value> elements;                         // array, in order
  std::vector<std::pair<std::string, Json_value>> members;  // object, in order, keys distinct

  // The member with this key, or nullptr (also when this is no object).
  const Json_value* member(std::string_view key) const;
};

// Strict RFC 8259 JSON: one value, surrounded by whitespace only; nesting deeper than 64 levels and
// duplicate keys in one object are refused. Throws Input_error (name, line, reason).
Json_value parse_json(std::string_view content, const std::string& name);

// "null", "true or false", "a number", "a string", "an array", "an object": for messages.
const char* describe(Json_value::Kind kind);

}  // namespace apollonius
