// A JSON document written as it goes, in the layout of write_json_document (json_output.h) and with
// nlohmann-json's number and string forms, byte for byte, but with no document built first: for the whole
// diagram of a protein (a million values) building the ordered_json DOM and dumping it took as long as
// computing the edges and faces (docs/benchmarks.md).
#pragma once

#include <array>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <ostream>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace apollonius {

// Usage: member("key") then one value: a scalar, a compact array or object (begin_array ... end_array,
// key(...) before each value of an object), or a line array (begin_lines, line() before each element,
// end_lines). Invariant: the text written so far is a prefix of the document json_output.h would print
// for the same members and values.
class Json_stream {
 public:
  explicit Json_stream(std::ostream& out);
  Json_stream(const Json_stream&) = delete;
  Json_stream& operator=(const Json_stream&) = delete;
  ~Json_stream();  // writes what is buffered (finish() first to see errors in the stream's state)

  // A member of the top-level object, on a line of its own.
  void member(std::string_view key);
  // A top-level array whose elements are one per line (each an object or an array).
  void begin_lines();
  void line();
  void end_lines();
  // The top-level object's closing brace; flushes the buffer.
  void finish();

  // Compact values (on the current line). The hot ones are inline: a protein's whole diagram is millions
  // of them.
  void begin_array() { open('['); }
  void end_array() { close(']'); }
  void begin_object() { open('{'); }
  void end_object() { close('}'); }
  void key(std::string_view name);
  void unsigned_number(std::uint64_t number) {
    separate();
    char* at = room(24);
    used_ = static_cast<std::size_t>(std::to_chars(at, at + 24, number).ptr - buffer_.data());
  }
  void integer(long long number);
  void boolean(bool truth);
  void string(std::string_view text);
  void null();
  // A number, or the string "inf" or "-inf" (json_number in json_output.h).
  void number_or_infinity(double number);
  template <class Unsigned>
  void array_of(const std::vector<Unsigned>& numbers) {
    begin_array();
    for (Unsigned n : numbers) unsigned_number(n);
    end_array();
  }

 private:
  // The comma before a value, unless it follows a key or opens its container.
  void separate() {
    if (after_key_) {
      after_key_ = false;
      return;
    }
    if (depth_ == 0) return;
    const std::uint64_t bit = std::uint64_t{1} << (depth_ - 1);
    if (first_in_ & bit) {
      first_in_ &= ~bit;
      return;
    }
    *room(1) = ',', ++used_;
  }
  // At least size bytes at the buffer's end (the caller advances used_).
  char* room(std::size_t size) {
    if (used_ + size > buffer_.size()) flush();
    return buffer_.data() + used_;
  }
  void open(char bracket) {
    separate();
    if (depth_ == kMaxDepth) throw std::length_error("Json_stream: containers nested more than 64 deep");
    *room(1) = bracket, ++used_;
    first_in_ |= std::uint64_t{1} << depth_++;
  }
  void close(char bracket) {
    --depth_;
    *room(1) = bracket, ++used_;
  }
  void raw(std::string_view text);
  void quoted(std::string_view text);  // a string's JSON form, as nlohmann dumps it
  void flush();

  std::ostream& out_;
  std::array<char, 1 << 16> buffer_;
  std::size_t used_ = 0;
  bool first_member_ = true, after_key_ = false;
  std::size_t lines_ = 0;
  static constexpr int kMaxDepth = 64;
  int depth_ = 0;               // open compact containers
  std::uint64_t first_in_ = 0;  // bit d: nothing written yet in the open container at depth d
};

}  // namespace apollonius
