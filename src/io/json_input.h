// JSON input (nlohmann-json), with the line where each value starts, so that a reader can name the line of
// a bad value: FILE:LINE: reason (docs/contract.md, "Bad input").
#pragma once

#include <nlohmann/json.hpp>

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace apollonius {

// Invariant: mirrors its value: elements for an array, members for an object, both empty otherwise.
struct Json_lines {
  std::size_t line = 0;  // 1-based line where the value starts
  std::vector<Json_lines> elements;
  std::map<std::string, Json_lines, std::less<>> members;
};

struct Json_document {
  nlohmann::json value;
  Json_lines lines;
};

// A value of a document and its lines, for readers that walk the document.
class Json_node {
 public:
  Json_node(const nlohmann::json& value, const Json_lines& lines) : value_(value), lines_(lines) {}
  const nlohmann::json& value() const { return value_; }
  std::size_t line() const { return lines_.line; }
  // The member with this key of an object, if any.
  std::optional<Json_node> member(std::string_view key) const;
  std::size_t size() const { return lines_.elements.size(); }
  Json_node element(std::size_t i) const { return {value_[i], lines_.elements[i]}; }
  // "null", "a boolean", "a number", "a string", "an array", "an object": for messages.
  const char* kind() const;

 private:
  const nlohmann::json& value_;
  const Json_lines& lines_;
};

// Strict RFC 8259 JSON: one value, surrounded by whitespace only. Nesting deeper than 64 levels and a key
// repeated in one object are refused (nlohmann-json would keep the last). Throws Input_error (name, line,
// reason).
Json_document parse_json(std::string_view content, const std::string& name);

}  // namespace apollonius
