#include "io/json_value.h"

#include "io/input_error.h"

namespace apollonius {

namespace {

constexpr int kMaxDepth = 64;

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// Recursive descent over the content; line counts the line breaks passed so far.
class Json_parser {
 public:
  Json_parser(std::string_view content, const std::string& name) : content_(content), name_(name) {}

  Json_value document() {
    Json_value value = parse_value(0);
    skip_whitespace();
    if (position_ != content_.size()) fail("unexpected text after the JSON value");
    return value;
  }

 private:
  [[noreturn]] void fail(const std::string& reason) const { throw Input_error(name_, line_, reason); }

  bool at_end() const { return position_ >= content_.size(); }
  char peek() const { return at_end() ? '\0' : content_[position_]; }

  void skip_whitespace() {
    while (!at_end()) {
      const char c = content_[position_];
      if (c == '\n') {
        ++line_;
      } else if (c != ' ' && c != '\t' && c != '\r') {
        return;
      }
      ++position_;
    }
  }

  void expect(char c) {
    if (peek() != c) fail(std::string("expected '") + c + "'" + found());
    ++position_;
  }

  std::string found() const {
    if (at_end()) return ", found the end of the input";
    return std::string(", found '") + content_[position_] + "'";
  }

  Json_value parse_value(int depth) {
    skip_whitespace();
    Json_value value;
    value.line = line_;
    const char c = peek();
    if (c == '{' || c == '[') {
      if (depth == kMaxDepth) fail("JSON nested deeper than " + std::to_string(kMaxDepth) + " levels");
      if (c == '{') parse_object(value, depth + 1);
      else parse_array(value, depth + 1);
    } else if (c == '"') {
      value.kind = Json_value::Kind::string;
      value.text = parse_string();
    } else if (c == '-' || is_digit(c)) {
      value.kind = Json_value::Kind::number;
      value.text = parse_number();
    } else if (parse_literal("true")) {
      value.kind = Json_value::Kind::boolean;
      value.text = "true";
    } else if (parse_literal("false")) {
      value.kind = Json_value::Kind::boolean;
      value.text = "false";
    } else if (parse_literal("null")) {
      value.kind = Json_value::Kind::null;
    } else {
      fail("expected a JSON value" + found());
    }
    return value;
  }

  bool parse_literal(std::string_view word) {
    if (content_.substr(position_, word.size()) != word) return false;
    position_ += word.size();
    return true;
  }

  // open, then items separated by ',' (each read by parse_item), then close; no item is fine.
  template <class Item>
  void parse_sequence(char open, char close, const Item& parse_item) {
    expect(open);
    skip_whitespace();
    if (peek() != close) {
      for (;;) {
        parse_item();
        skip_whitespace();
        if (peek() == close) break;
        expect(',');
      }
    }
    ++position_;
  }

  void parse_object(Json_value& value, int depth) {
    value.kind = Json_value::Kind::object;
    parse_sequence('{', '}', [&] {
      skip_whitespace();
      if (peek() != '"') fail("expected a key string" + found());
      std::string key = parse_string();
      if (value.member(key) != nullptr) fail("duplicate key '" + key + "'");
      skip_whitespace();
      expect(':');
      value.members.emplace_back(std::move(key), parse_value(depth));
    });
  }

  void parse_array(Json_value& value, int depth) {
    value.kind = Json_value::Kind::array;
    parse_sequence('[', ']', [&] { value.elements.push_back(parse_value(depth)); });
  }

  // -?(0|[1-9][0-9]*)(.[0-9]+)?([eE][+-]?[0-9]+)?
  std::string parse_number() {
    const std::size_t start = position_;
    if (peek() == '-') ++position_;
    if (peek() == '0') {
      ++position_;
    } else if (is_digit(peek())) {
      while (is_digit(peek())) ++position_;
    } else {
      fail("expected a digit" + found());
    }
    if (peek() == '.') {
      ++position_;
      if (!is_digit(peek())) fail("expected a digit after '.'" + found());
      while (is_digit(peek())) ++position_;
    }
    if (peek() == 'e' || peek() == 'E') {
      ++position_;
      if (peek() == '+' || peek() == '-') ++position_;
      if (!is_digit(peek())) fail("expected an exponent" + found());
      while (is_digit(peek())) ++position_;
    }
    return std::string(content_.substr(start, position_ - start));
  }

  unsigned hex4() {
    unsigned code = 0;
    for (int i = 0; i < 4; ++i, ++position_) {
      const char c = peek();
      code <<= 4;
      if (is_digit(c)) code |= static_cast<unsigned>(c - '0');
      else if (c >= 'a' && c <= 'f') code |= static_cast<unsigned>(c - 'a' + 10);
      else if (c >= 'A' && c <= 'F') code |= static_cast<unsigned>(c - 'A' + 10);
      else fail("expected 4 hexadecimal digits after \\u" + found());
    }
    return code;
  }

  static void append_utf8(std::string& out, unsigned code) {
    if (code < 0x80) {
      out += static_cast<char>(code);
    } else if (code < 0x800) {
      out += static_cast<char>(0xc0 | (code >> 6));
      out += static_cast<char>(0x80 | (code & 0x3f));
    } else if (code < 0x10000) {
      out += static_cast<char>(0xe0 | (code >> 12));
      out += static_cast<char>(0x80 | ((code >> 6) & 0x3f));
      out += static_cast<char>(0x80 | (code & 0x3f));
    } else {
      out += static_cast<char>(0xf0 | (code >> 18));
      out += static_cast<char>(0x80 | ((code >> 12) & 0x3f));
      out += static_cast<char>(0x80 | ((code >> 6) & 0x3f));
      out += static_cast<char>(0x80 | (code & 0x3f));
    }
  }

  // A \u escape; a high surrogate must be followed by the escape of a low one.
  unsigned unicode_escape() {
    const unsigned code = hex4();
    if (code < 0xd800 || code > 0xdfff) return code;
    if (code > 0xdbff || !parse_literal("\\u")) fail("unpaired UTF-16 surrogate in a string");
    const unsigned low = hex4();
    if (low < 0xdc00 || low > 0xdfff) fail("unpaired UTF-16 surrogate in a string");
    return 0x10000 + ((code - 0xd800) << 10) + (low - 0xdc00);
  }

  std::string parse_string() {
    expect('"');
    std::string text;
    for (;;) {
      if (at_end()) fail("unterminated string");
      const char c = content_[position_++];
      if (c == '"') return text;
      if (static_cast<unsigned char>(c) < 0x20) fail("control character in a string");
      if (c != '\\') {
        text += c;
        continue;
      }
      const char escape = peek();
      ++position_;
      switch (escape) {
        case '"': case '\\': case '/': text += escape; break;
        case 'b': text += '\b'; break;
        case 'f': text += '\f'; break;
        case 'n': text += '\n'; break;
        case 'r': text += '\r'; break;
        case 't': text += '\t'; break;
        case 'u': append_utf8(text, unicode_escape()); break;
        default: --position_; fail("invalid escape in a string" + found());
      }
    }
  }

  std::string_view content_;
  const std::string& name_;
  std::size_t position_ = 0;
  std::size_t line_ = 1;
};

}  // namespace

const Json_value* Json_value::member(std::string_view key) const {
  for (const auto& [k, v] : members)
    if (k == key) return &v;
  return nullptr;
}

Json_value parse_json(std::string_view content, const std::string& name) { return Json_parser(content, name).document(); }

const char* describe(Json_value::Kind kind) {
  switch (kind) {
    case Json_value::Kind::null: return "null";
    case Json_value::Kind::boolean: return "true or false";
    case Json_value::Kind::number: return "a number";
    case Json_value::Kind::string: return "a string";
    case Json_value::Kind::array: return "an array";
    case Json_value::Kind::object: return "an object";
  }
  return "a JSON value";
}

}  // namespace apollonius
