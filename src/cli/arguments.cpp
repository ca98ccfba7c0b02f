#include "cli/arguments.h"

#include <charconv>
#include <cmath>

namespace apollonius {

const std::string& option_value(const std::vector<std::string>& args, std::size_t& i) {
  if (i + 1 >= args.size()) throw Usage_error("option " + args[i] + " needs a value");
  return args[++i];
}

double parse_option_number(const std::string& text, const std::string& option) {
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
    throw Usage_error("option " + option + " needs finite numbers, not '" + text + "'");
  return value;
}

int parse_threads(const std::string& text) {
  const double threads = parse_option_number(text, "--threads");
  if (threads < 1 || threads > 1024 || threads != std::floor(threads))
    throw Usage_error("option --threads needs an integer from 1 to 1024");
  return static_cast<int>(threads);
}

bool parse_read_option(const std::string& argument, Read_options& options) {
  if (argument == "--keep-hydrogens") {
    options.keep_hydrogens = true;
  } else if (argument == "--keep-waters") {
    options.keep_waters = true;
  } else {
    return false;
  }
  return true;
}

}  // namespace apollonius
