// A JSON document written as it goes, in the layout of write_json_document (json_output.h) and with
// nlohmann-json's number and string forms, byte for byte, but with no document built first: for the whole
// diagram of a protein (a million values) building the ordered_json DOM and dumping it took as long as
// computing the edges and faces (docs/benchmarks.md).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <ostream>
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

  // Compact values (on the current line).
  void begin_array();
  void end_array();
  void begin_object();
  void end_object();
  void key(std::string_view name);
  void unsigned_number(std::uint64_t number);
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
  void separate();  // the comma before a value, unless it follows a key or opens its container
  char* room(std::size_t size);  // at least size bytes at the buffer's end (the caller advances used_)
  void raw(std::string_view text);
  void quoted(std::string_view text);  // a string's JSON form, as nlohmann dumps it
  void flush();

  std::ostream& out_;
  std::array<char, 1 << 16> buffer_;
  std::size_t used_ = 0;
  bool first_member_ = true, after_key_ = false;
  std::size_t lines_ = 0;
  std::vector<bool> first_in_;  // per open compact container: nothing written in it yet
};

}  // namespace apollonius
