#include "io/json_input.h"

#include <algorithm>
#include <iterator>

#include "io/input_error.h"

namespace apollonius {
namespace {

constexpr std::size_t kMaxDepth = 64;

// A character iterator that records how far nlohmann-json's lexer has read: the SAX events below then
// know where their token ends, and from that the line where the value starts.
class Recording_iterator {
 public:
  using iterator_category = std::input_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;

  Recording_iterator(const char* position, const char** read_up_to) : position_(position), read_up_to_(read_up_to) {}
  reference operator*() const { return *position_; }
  Recording_iterator& operator++() {
    *read_up_to_ = ++position_;
    return *this;
  }
  Recording_iterator operator++(int) {
    Recording_iterator before = *this;
    ++*this;
    return before;
  }
  friend bool operator==(const Recording_iterator& a, const Recording_iterator& b) { return a.position_ == b.position_; }
  friend bool operator!=(const Recording_iterator& a, const Recording_iterator& b) { return !(a == b); }

 private:
  const char* position_;
  const char** read_up_to_;
};

// Builds the document and its lines from nlohmann-json's SAX events. The lexer has read a token's last
// character when its event comes, and for a number one character more (the one that ends it); no token
// but a string spans lines, and a string cannot hold a raw line break.
class Document_builder : public nlohmann::json_sax<nlohmann::json> {
 public:
  Document_builder(std::string_view content, const char** read_up_to, Json_document& document)
      : content_(content), read_up_to_(read_up_to), document_(document) {
    for (std::size_t i = 0; i < content.size(); ++i)
      if (content[i] == '\n') line_breaks_.push_back(i);
  }

  // Set when an event refused the document; the parse then stops.
  std::string error;
  std::size_t error_line = 0;

  bool null() override { return add(nullptr, last_read()); }
  bool boolean(bool value) override { return add(value, last_read()); }
  bool number_integer(number_integer_t value) override { return add(value, number_end()); }
  bool number_unsigned(number_unsigned_t value) override { return add(value, number_end()); }
  bool number_float(number_float_t value, const string_t&) override { return add(value, number_end()); }
  bool string(string_t& value) override { return add(std::move(value), last_read()); }
  bool binary(binary_t&) override { return false; }  // JSON text has no binary values

  bool start_object(std::size_t) override { return open(nlohmann::json::object()); }
  bool start_array(std::size_t) override { return open(nlohmann::json::array()); }
  bool end_object() override { return close(); }
  bool end_array() override { return close(); }

  bool key(string_t& key) override {
    if (path_.back().value->contains(key)) return refuse("duplicate key \"" + key + "\"", last_read());
    key_ = std::move(key);
    return true;
  }

  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& e) override {
    // nlohmann-json says "[json.exception.parse_error.101] parse error at line L, column C: REASON".
    const std::string message = e.what();
    const std::size_t colon = message.find(": ");
    return refuse(colon == std::string::npos ? message : message.substr(colon + 2),
                  position == 0 ? 0 : std::min(position, content_.size()) - 1);
  }

 private:
  struct Open_value {
    nlohmann::json* value;
    Json_lines* lines;
  };

  // 1 + the line breaks before offset.
  std::size_t line_at(std::size_t offset) const {
    return 1 + static_cast<std::size_t>(std::lower_bound(line_breaks_.begin(), line_breaks_.end(), offset) -
                                        line_breaks_.begin());
  }
  std::size_t read() const { return static_cast<std::size_t>(*read_up_to_ - content_.data()); }
  std::size_t last_read() const { return read() - 1; }
  std::size_t number_end() const {
    const std::size_t last = last_read();
    const char c = content_[last];
    return (c >= '0' && c <= '9') ? last : last - 1;
  }

  bool refuse(std::string reason, std::size_t offset) {
    if (error.empty()) {
      error = std::move(reason);
      error_line = line_at(offset);
    }
    return false;
  }

  // Places value in the open array or object, or as the document; returns where it went.
  Open_value place(nlohmann::json&& value, std::size_t offset) {
    Json_lines lines;
    lines.line = line_at(offset);
    if (path_.empty()) {
      document_.value = std::move(value);
      document_.lines = std::move(lines);
      return {&document_.value, &document_.lines};
    }
    const Open_value& parent = path_.back();
    if (parent.value->is_array()) {
      parent.value->push_back(std::move(value));
      parent.lines->elements.push_back(std::move(lines));
      return {&parent.value->back(), &parent.lines->elements.back()};
    }
    nlohmann::json& member = (*parent.value)[key_];
    member = std::move(value);
    Json_lines& member_lines = parent.lines->members[key_] = std::move(lines);
    return {&member, &member_lines};
  }

  bool add(nlohmann::json&& value, std::size_t offset) {
    place(std::move(value), offset);
    return true;
  }
  bool open(nlohmann::json&& empty) {
    if (path_.size() >= kMaxDepth)
      return refuse("nested deeper than " + std::to_string(kMaxDepth) + " levels", last_read());
    path_.push_back(place(std::move(empty), last_read()));
    return true;
  }
  bool close() {
    path_.pop_back();
    return true;
  }

  std::string_view content_;
  const char** read_up_to_;
  Json_document& document_;
  std::vector<std::size_t> line_breaks_;  // offsets of '\n', ascending
  std::vector<Open_value> path_;          // the arrays and objects being read, outermost first
  std::string key_;                       // the key of the next member of the innermost object
};

}  // namespace

std::optional<Json_node> Json_node::member(std::string_view key) const {
  if (!value_.is_object()) return std::nullopt;
  const auto lines = lines_.members.find(key);
  if (lines == lines_.members.end()) return std::nullopt;
  return Json_node(*value_.find(std::string(key)), lines->second);
}

const char* Json_node::kind() const {
  switch (value_.type()) {
    case nlohmann::json::value_t::null: return "null";
    case nlohmann::json::value_t::boolean: return "a boolean";
    case nlohmann::json::value_t::number_integer:
    case nlohmann::json::value_t::number_unsigned:
    case nlohmann::json::value_t::number_float: return "a number";
    case nlohmann::json::value_t::string: return "a string";
    case nlohmann::json::value_t::array: return "an array";
    case nlohmann::json::value_t::object: return "an object";
    default: return "no JSON value";
  }
}

Json_document parse_json(std::string_view content, const std::string& name) {
  Json_document document;
  const char* read_up_to = content.data();
  Document_builder builder(content, &read_up_to, document);
  const Recording_iterator begin(content.data(), &read_up_to), end(content.data() + content.size(), &read_up_to);
  if (!nlohmann::json::sax_parse(begin, end, &builder))
    throw Input_error(name, builder.error_line, builder.error.empty() ? "not JSON" : builder.error);
  return document;
}

}  // namespace apollonius
