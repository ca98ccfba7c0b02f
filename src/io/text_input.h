// Line-based text inputs (sites, claimed vertices): whole files, lines, fields and numbers. Every failure
// is an Input_error naming the file, the 1-based line (0 for the whole file) and the reason.
#pragma once

#include <charconv>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace apollonius {

// How messages name standard input, which commands read for the path "-".
inline const std::string stdin_name = "<stdin>";

// path itself, or stdin_name for "-".
std::string input_name(const std::string& path);

// Throws unless path names a file that opens for reading (a directory does not).
void check_readable(const std::string& path);

// The whole content of path, or of standard input for "-".
std::string read_input_file(const std::string& path);

// The UTF-8 byte-order mark that some editors write at the start of a text file; readers skip it.
inline constexpr std::string_view byte_order_mark = "\xEF\xBB\xBF";

inline bool starts_with_byte_order_mark(std::string_view content) {
  return content.substr(0, byte_order_mark.size()) == byte_order_mark;
}

// Text may hold tabs, line and page breaks; any other control byte means this is no text file.
void reject_binary_data(std::string_view content, const std::string& name);

// Invariant: text holds neither the line break nor a '\r' before it; number is 1-based.
struct Text_line {
  std::size_t number;
  std::string_view text;
};

// A final line break does not start another (empty) line.
std::vector<Text_line> split_lines(std::string_view content);

// The whitespace-separated fields of a line before any '#'. A line without fields (blank or a comment)
// carries no data.
std::vector<std::string_view> data_fields(std::string_view line);

// Whether the field starts like a number (it may still be out of range or have trailing junk).
bool starts_like_number(std::string_view field);

enum class Infinity { refused, allowed };

// The double nearest to the decimal field (a leading '+' is allowed). NaN is always refused; "inf" and
// "-inf" only with Infinity::allowed (vertex lists print coordinates that overflow so).
double parse_number(std::string_view field, const std::string& name, std::size_t line,
                    Infinity infinity = Infinity::refused);

// Whether the whole field is an integer of the type, which then holds it.
template <class Integer>
bool parse_integer(std::string_view field, Integer& value) {
  const std::from_chars_result result = std::from_chars(field.data(), field.data() + field.size(), value);
  return result.ec == std::errc() && result.ptr == field.data() + field.size();
}

bool is_integer(std::string_view field);

}  // namespace apollonius
