#include "io/read_masses.h"

#include <cmath>

#include "io/input_error.h"
#include "io/round_trip.h"
#include "io/text_input.h"

namespace apollonius {

std::vector<double> read_masses_from_text(const std::string& content, const std::string& name, std::size_t site_count) {
  if (starts_with_byte_order_mark(content))
    return read_masses_from_text(content.substr(byte_order_mark.size()), name, site_count);
  reject_binary_data(content, name);
  std::vector<double> masses;
  double sum = 0;
  for (const Text_line& line : split_lines(content)) {
    const std::vector<std::string_view> fields = data_fields(line.text);
    if (fields.empty()) continue;
    if (fields.size() != 1)
      throw Input_error(name, line.number, "expected 1 field 'mass', found " + std::to_string(fields.size()));
    const double mass = parse_number(fields[0], name, line.number);
    if (!(mass > 0)) throw Input_error(name, line.number, "a mass must be positive, not " + round_trip(mass));
    if (masses.size() == site_count)
      throw Input_error(name, line.number, "more masses than the " + std::to_string(site_count) + " sites");
    masses.push_back(mass);
    sum += mass;
  }
  if (masses.size() != site_count)
    throw Input_error(name, 0, std::to_string(masses.size()) + " masses for " + std::to_string(site_count) + " sites");
  if (!(std::fabs(sum - 1) <= kMassSumTolerance))
    throw Input_error(name, 0, "the masses sum to " + round_trip(sum) + ", not 1 (within 1e-9)");
  return masses;
}

std::vector<double> read_masses(const std::string& path, std::size_t site_count) {
  return read_masses_from_text(read_input_file(path), input_name(path), site_count);
}

}  // namespace apollonius
