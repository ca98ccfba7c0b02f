#include "io/json_stream.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>

#include <nlohmann/json.hpp>

namespace apollonius {

Json_stream::Json_stream(std::ostream& out) : out_(out) { raw("{"); }

Json_stream::~Json_stream() { flush(); }

void Json_stream::flush() {
  out_.write(buffer_.data(), static_cast<std::streamsize>(used_));
  used_ = 0;
}

void Json_stream::raw(std::string_view text) {
  for (std::size_t i = 0; i < text.size(); i += buffer_.size()) {
    const std::size_t n = std::min(buffer_.size(), text.size() - i);
    std::memcpy(room(n), text.data() + i, n), used_ += n;
  }
}

void Json_stream::member(std::string_view key) {
  raw(first_member_ ? "\n  " : ",\n  ");
  first_member_ = false;
  after_key_ = false;
  depth_ = 0, first_in_ = 0;
  quoted(key);  // as nlohmann dumps it
  raw(": ");
  after_key_ = true;
}

void Json_stream::begin_lines() {
  after_key_ = false;
  *room(1) = '[', ++used_;
  lines_ = 0;
}

void Json_stream::line() {
  raw(lines_++ == 0 ? "\n    " : ",\n    ");
  depth_ = 0, first_in_ = 0;
  after_key_ = true;  // the element follows with no comma
}

void Json_stream::end_lines() {
  raw(lines_ == 0 ? "]" : "\n  ]");
}

void Json_stream::finish() {
  raw("\n}\n");
  flush();
  out_.flush();
}

void Json_stream::key(std::string_view name) {
  separate();
  quoted(name);
  *room(1) = ':', ++used_;
  after_key_ = true;
}

void Json_stream::integer(long long number) {
  separate();
  char* at = room(24);
  used_ = static_cast<std::size_t>(std::to_chars(at, at + 24, number).ptr - buffer_.data());
}

void Json_stream::boolean(bool truth) {
  separate();
  raw(truth ? "true" : "false");
}

void Json_stream::null() {
  separate();
  raw("null");
}

void Json_stream::string(std::string_view text) {
  separate();
  quoted(text);
}

void Json_stream::quoted(std::string_view text) {
  // Printable ASCII other than '"' and '\\' is its own JSON form; anything else is escaped by nlohmann,
  // bytes that are not UTF-8 becoming U+FFFD (as json_output.h dumps).
  const bool plain = std::all_of(text.begin(), text.end(), [](char c) { return c >= 0x20 && c < 0x7f && c != '"' && c != '\\'; });
  if (!plain) {
    raw(nlohmann::json(std::string(text)).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
    return;
  }
  if (text.size() + 2 > buffer_.size()) {
    raw("\"");
    raw(text);
    raw("\"");
    return;
  }
  char* at = room(text.size() + 2);  // one copy: keys are most of the strings, a few per value
  at[0] = '"';
  std::memcpy(at + 1, text.data(), text.size());
  at[text.size() + 1] = '"';
  used_ += text.size() + 2;
}

void Json_stream::number_or_infinity(double number) {
  if (!std::isfinite(number)) return string(number > 0 ? "inf" : "-inf");
  separate();
  char* at = room(64);
  // The shortest round-trip form nlohmann's serializer prints (Grisu2, "1.0" for integers).
  used_ = static_cast<std::size_t>(nlohmann::detail::to_chars(at, at + 64, number) - buffer_.data());
}

}  // namespace apollonius
