#include "io/read_sites.h"

#include <cctype>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string_view>

#include "io/input_error.h"
#include "io/read_structure.h"
#include "io/text_input.h"

namespace apollonius {

namespace {

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

std::string field_count_error(std::size_t expected, const char* shape, std::size_t found) {
  return "expected " + std::to_string(expected) + " fields '" + shape + "', found " + std::to_string(found);
}

// Balls text: `x y z w` on each data line. Called when the first data line is one, so never empty.
std::vector<Site> parse_balls(const std::vector<Text_line>& lines, const std::string& name,
                              std::vector<std::size_t>& site_lines) {
  std::vector<Site> sites;
  for (const Text_line& line : lines) {
    const std::vector<std::string_view> fields = data_fields(line.text);
    if (fields.empty()) continue;
    if (fields.size() != 4) throw Input_error(name, line.number, field_count_error(4, "x y z w", fields.size()));
    site_lines.push_back(line.number);
    sites.push_back({parse_number(fields[0], name, line.number), parse_number(fields[1], name, line.number),
                     parse_number(fields[2], name, line.number), parse_number(fields[3], name, line.number)});
  }
  return sites;
}

// vdrc: a count line, then exactly that many `id x y z r` lines; the ids are ignored, file order is kept.
std::vector<Site> parse_vdrc(const std::vector<Text_line>& lines, const std::string& name,
                             std::vector<std::size_t>& site_lines) {
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
    site_lines.push_back(line.number);
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
  if (starts_with_byte_order_mark(content))
    return read_sites_from_text(content.substr(byte_order_mark.size()), name, options);
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
  std::vector<std::size_t> site_lines;
  if (first_fields.size() == 1 && is_integer(first_fields[0])) {
    std::vector<Site> sites = parse_vdrc(lines, name, site_lines);
    return {std::move(sites), Input_format::vdrc, {}, std::move(site_lines)};
  }
  if (starts_like_number(first_fields[0])) {
    std::vector<Site> sites = parse_balls(lines, name, site_lines);
    return {std::move(sites), Input_format::balls, {}, std::move(site_lines)};
  }
  if (equals_ignoring_case(first_fields[0].substr(0, 5), "data_") || has_pdb_record(lines)) {
    Site_input input{{}, Input_format::structure, {}, {}};
    input.sites = read_structure(name, &content, options, options.atom_labels ? &input.labels : nullptr);
    return input;
  }
  throw Input_error(name, first_data_line->number,
                    "unrecognized input format (expected balls 'x y z w', vdrc, PDB or mmCIF)");
}

Site_input read_sites(const std::string& path, const Read_options& options) {
  if (path != "-" && is_structure_path(path)) {
    check_readable(path);  // the same "cannot open" error as for other inputs, before gemmi's own
    Site_input input{{}, Input_format::structure, {}, {}};
    input.sites = read_structure(path, nullptr, options, options.atom_labels ? &input.labels : nullptr);
    return input;
  }
  return read_sites_from_text(read_input_file(path), input_name(path), options);
}

std::vector<Site> sites_from_arrays(const double* centres, const double* weights, std::size_t count) {
  if (count == 0) throw Input_error("centres", 0, "empty input: no sites");
  if (count - 1 > std::numeric_limits<Site_index>::max())
    throw Input_error("centres", 0, std::to_string(count) + " sites, more than the " +
                                        std::to_string(std::uint64_t{std::numeric_limits<Site_index>::max()} + 1) +
                                        " that site indices can name");
  const auto check = [](double value, const char* array, std::size_t site, const char* coordinate) {
    if (std::isfinite(value)) return;
    const std::string printed = std::isnan(value) ? "nan" : value > 0 ? "inf" : "-inf";
    throw Input_error(array, 0, "site " + std::to_string(site) + coordinate + ": not a finite number: " + printed);
  };
  std::vector<Site> sites(count);
  for (std::size_t i = 0; i < count; ++i) {
    const double* c = centres + 3 * i;
    check(c[0], "centres", i, ", x"), check(c[1], "centres", i, ", y"), check(c[2], "centres", i, ", z");
    check(weights[i], "weights", i, "");
    sites[i] = Site{c[0], c[1], c[2], weights[i]};
  }
  return sites;
}

}  // namespace apollonius
