#include "io/text_input.h"

#include <sys/stat.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <iterator>
#include <memory>

#include "io/input_error.h"

namespace apollonius {

namespace {

struct Close_file {
  void operator()(std::FILE* file) const { std::fclose(file); }
};
using File = std::unique_ptr<std::FILE, Close_file>;

// C stdio rather than iostreams, so that a failure's reason is errno's. A directory is refused here:
// it would open, then fail on the first read with a less clear message.
File open_for_reading(const std::string& path) {
  File file(std::fopen(path.c_str(), "rb"));
  if (!file) throw Input_error(path, 0, std::string("cannot open: ") + std::strerror(errno));
  struct stat status;
  if (fstat(fileno(file.get()), &status) == 0 && S_ISDIR(status.st_mode)) {
    throw Input_error(path, 0, std::string("cannot open: ") + std::strerror(EISDIR));
  }
  return file;
}

std::string read_standard_input() {
  std::string content{std::istreambuf_iterator<char>(std::cin), std::istreambuf_iterator<char>()};
  if (std::cin.bad()) throw Input_error(stdin_name, 0, "cannot read");
  return content;
}

bool is_field_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

// std::from_chars gives the nearest double to the decimal text. It refuses a leading '+', which strtod
// and hand-written files allow.
std::from_chars_result scan_double(std::string_view field, double& value) {
  if (field.size() > 1 && field[0] == '+' && field[1] != '-' && field[1] != '+') field.remove_prefix(1);
  return std::from_chars(field.data(), field.data() + field.size(), value);
}

}  // namespace

std::string input_name(const std::string& path) { return path == "-" ? stdin_name : path; }

void check_readable(const std::string& path) { open_for_reading(path); }

std::string read_input_file(const std::string& path) {
  if (path == "-") return read_standard_input();
  File file = open_for_reading(path);
  std::string content;
  char buffer[1 << 16];
  std::size_t count;
  while ((count = std::fread(buffer, 1, sizeof buffer, file.get())) > 0) content.append(buffer, count);
  if (std::ferror(file.get())) throw Input_error(path, 0, std::string("cannot read: ") + std::strerror(errno));
  return content;
}

void reject_binary_data(std::string_view content, const std::string& name) {
  std::size_t line = 1;
  for (const char c : content) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte == '\n') ++line;
    const bool allowed_space = byte == '\t' || byte == '\n' || byte == '\r' || byte == '\f' || byte == '\v';
    if ((byte < 0x20 && !allowed_space) || byte == 0x7f) {
      char reason[32];
      std::snprintf(reason, sizeof reason, "binary data (byte 0x%02x)", byte);
      throw Input_error(name, line, reason);
    }
  }
}

std::vector<Text_line> split_lines(std::string_view content) {
  std::vector<Text_line> lines;
  std::size_t start = 0;
  while (start < content.size()) {
    std::size_t end = content.find('\n', start);
    if (end == std::string_view::npos) end = content.size();
    std::string_view text = content.substr(start, end - start);
    if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
    lines.push_back({lines.size() + 1, text});
    start = end + 1;
  }
  return lines;
}

std::vector<std::string_view> data_fields(std::string_view line) {
  line = line.substr(0, line.find('#'));
  std::vector<std::string_view> fields;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_field_space(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !is_field_space(line[i])) ++i;
    if (i > start) fields.push_back(line.substr(start, i - start));
  }
  return fields;
}

bool starts_like_number(std::string_view field) {
  double value;
  const std::from_chars_result result = scan_double(field, value);
  return result.ptr != field.data() || result.ec == std::errc::result_out_of_range;
}

double parse_number(std::string_view field, const std::string& name, std::size_t line, Infinity infinity) {
  double value;
  const std::from_chars_result result = scan_double(field, value);
  const std::string quoted = "'" + std::string(field) + "'";
  if (result.ec == std::errc::result_out_of_range) throw Input_error(name, line, "out of double range: " + quoted);
  if (result.ec != std::errc() || result.ptr != field.data() + field.size()) {
    throw Input_error(name, line, "not a number: " + quoted);
  }
  if (std::isnan(value) || (std::isinf(value) && infinity == Infinity::refused)) {
    throw Input_error(name, line, "not a finite number: " + quoted);
  }
  return value;
}

bool is_integer(std::string_view field) {
  long long value;
  return parse_integer(field, value);
}

}  // namespace apollonius
