#include "io/read_sites.h"

#include <sys/stat.h>

#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <iterator>
#include <memory>
#include <string_view>

#include "io/input_error.h"
#include "io/read_structure.h"

namespace apollonius {

namespace {

const char* const stdin_name = "<stdin>";

// Whether text equals lowercase_text but for the case of its letters.
bool equals_ignoring_case(std::string_view text, std::string_view lowercase_text) {
  if (text.size() != lowercase_text.size()) return false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(text[i])) != lowercase_text[i]) return false;
  }
  return true;
}

bool ends_with_ignoring_case(std::string_view text, std::string_view lowercase_suffix) {
  return text.size() >= lowercase_suffix.size() &&
         equals_ignoring_case(text.substr(text.size() - lowercase_suffix.size()), lowercase_suffix);
}

// .pdb .ent .cif .mmcif, each optionally followed by .gz, in any case.
bool is_structure_path(const std::string& path) {
  std::string_view uncompressed = path;
  if (ends_with_ignoring_case(uncompressed, ".gz")) uncompressed.remove_suffix(3);
  for (std::string_view extension : {".pdb", ".ent", ".cif", ".mmcif"}) {
    if (ends_with_ignoring_case(uncompressed, extension)) return true;
  }
  return false;
}

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

std::string read_file(const std::string& path) {
  File file = open_for_reading(path);
  std::string content;
  char buffer[1 << 16];
  std::size_t count;
  while ((count = std::fread(buffer, 1, sizeof buffer, file.get())) > 0) content.append(buffer, count);
  if (std::ferror(file.get())) throw Input_error(path, 0, std::string("cannot read: ") + std::strerror(errno));
  return content;
}

std::string read_standard_input() {
  std::string content{std::istreambuf_iterator<char>(std::cin), std::istreambuf_iterator<char>()};
  if (std::cin.bad()) throw Input_error(stdin_name, 0, "cannot read");
  return content;
}

// Text may hold tabs, line and page breaks; any other control byte means this is no text file.
void reject_binary_data(const std::string& content, const std::string& name) {
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

// Invariant: text holds neither the line break nor a '\r' before it; number is 1-based.
struct Text_line {
  std::size_t number;
  std::string_view text;
};

// A final line break does not start another (empty) line.
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

bool is_field_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

// The whitespace-separated fields of a line before any '#'. A line without fields (blank or a comment)
// carries no data.
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

// std::from_chars gives the nearest double to the decimal text. It refuses a leading '+', which strtod
// and hand-written files allow.
std::from_chars_result scan_double(std::string_view field, double& value) {
  if (field.size() > 1 && field[0] == '+' && field[1] != '-' && field[1] != '+') field.remove_prefix(1);
  return std::from_chars(field.data(), field.data() + field.size(), value);
}

// Whether the field starts like a number (it may still be out of range or have trailing junk).
bool starts_like_number(std::string_view field) {
  double value;
  const std::from_chars_result result = scan_double(field, value);
  return result.ptr != field.data() || result.ec == std::errc::result_out_of_range;
}

double parse_number(std::string_view field, const std::string& name, std::size_t line) {
  double value;
  const std::from_chars_result result = scan_double(field, value);
  const std::string quoted = "'" + std::string(field) + "'";
  if (result.ec == std::errc::result_out_of_range) throw Input_error(name, line, "out of double range: " + quoted);
  if (result.ec != std::errc() || result.ptr != field.data() + field.size()) {
    throw Input_error(name, line, "not a number: " + quoted);
  }
  if (!std::isfinite(value)) throw Input_error(name, line, "not a finite number: " + quoted);
  return value;
}

template <class Integer>
bool parse_integer(std::string_view field, Integer& value) {
  const std::from_chars_result result = std::from_chars(field.data(), field.data() + field.size(), value);
  return result.ec == std::errc() && result.ptr == field.data() + field.size();
}

bool is_integer(std::string_view field) {
  long long value;
  return parse_integer(field, value);
}

std::string field_count_error(std::size_t expected, const char* shape, std::size_t found) {
  return "expected " + std::to_string(expected) + " fields '" + shape + "', found " + std::to_string(found);
}

// Balls text: `x y z w` on each data line. Called when the first data line is one, so never empty.
std::vector<Site> parse_balls(const std::vector<Text_line>& lines, const std::string& name) {
  std::vector<Site> sites;
  for (const Text_line& line : lines) {
    const std::vector<std::string_view> fields = data_fields(line.text);
    if (fields.empty()) continue;
    if (fields.size() != 4) throw Input_error(name, line.number, field_count_error(4, "x y z w", fields.size()));
    sites.push_back({parse_number(fields[0], name, line.number), parse_number(fields[1], name, line.number),
                     parse_number(fields[2], name, line.number), parse_number(fields[3], name, line.number)});
  }
  return sites;
}

// vdrc: a count line, then exactly that many `id x y z r` lines; the ids are ignored, file order is kept.
std::vector<Site> parse_vdrc(const std::vector<Text_line>& lines, const std::string& name) {
  std::vector<Site> sites;
  bool have_count = false;
  unsigned long long count = 0;
  for (const Text_line& line : lines) {
    const std::vector<std::string_view> fields = data_fields(line.text);
    if (fields.empty()) continue;
    if (!have_count) {
      if (!parse_integer(fields[0], count)) {
        throw Input_error(name, line.number, "not a ball count: '" + std::string(fields[0]) + "'");
      }
      have_count = true;
      continue;
    }
    if (sites.size() == count) {
      throw Input_error(name, line.number, "expected " + std::to_string(count) + " balls, found more");
    }
    if (fields.size() != 5) throw Input_error(name, line.number, field_count_error(5, "id x y z r", fields.size()));
    if (!is_integer(fields[0])) {
      throw Input_error(name, line.number, "not an integer id: '" + std::string(fields[0]) + "'");
    }
    sites.push_back({parse_number(fields[1], name, line.number), parse_number(fields[2], name, line.number),
                     parse_number(fields[3], name, line.number), parse_number(fields[4], name, line.number)});
  }
  if (sites.size() < count) {
    throw Input_error(name, lines.back().number,
                      "expected " + std::to_string(count) + " balls, found " + std::to_string(sites.size()));
  }
  if (sites.empty()) throw Input_error(name, 0, "empty input: no sites");  // a count of 0
  return sites;
}

bool has_pdb_record(const std::vector<Text_line>& lines) {
  for (const Text_line& line : lines) {
    for (std::string_view record : {"ATOM", "HETATM", "HEADER", "CRYST1", "MODEL", "REMARK", "TITLE", "COMPND"}) {
      if (line.text.substr(0, record.size()) == record) return true;
    }
  }
  return false;
}

}  // namespace

Site_input read_sites_from_text(const std::string& content, const std::string& name, const Read_options& options) {
  reject_binary_data(content, name);
  const std::vector<Text_line> lines = split_lines(content);

  const Text_line* first_data_line = nullptr;
  std::vector<std::string_view> first_fields;
  for (const Text_line& line : lines) {
    first_fields = data_fields(line.text);
    if (!first_fields.empty()) {
      first_data_line = &line;
      break;
    }
  }
  if (first_data_line == nullptr) throw Input_error(name, 0, "empty input: no sites");

  // The first data line decides, so that a malformed balls or vdrc file is reported at its bad line
  // rather than as an unknown format.
  if (first_fields.size() == 1 && is_integer(first_fields[0])) return {parse_vdrc(lines, name), Input_format::vdrc};
  if (starts_like_number(first_fields[0])) return {parse_balls(lines, name), Input_format::balls};
  if (equals_ignoring_case(first_fields[0].substr(0, 5), "data_") || has_pdb_record(lines)) {
    return {read_structure(name, &content, options), Input_format::structure};
  }
  throw Input_error(name, first_data_line->number,
                    "unrecognized input format (expected balls 'x y z w', vdrc, PDB or mmCIF)");
}

Site_input read_sites(const std::string& path, const Read_options& options) {
  if (path == "-") return read_sites_from_text(read_standard_input(), stdin_name, options);
  if (is_structure_path(path)) {
    open_for_reading(path);  // the same "cannot open" error as for other inputs, before gemmi's own
    return {read_structure(path, nullptr, options), Input_format::structure};
  }
  return read_sites_from_text(read_file(path), path, options);
}

}  // namespace apollonius
