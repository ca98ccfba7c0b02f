#include "cli/arguments.h"

#include <charconv>
#include <cmath>
#include <sstream>

#include "io/atomic_file.h"

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

std::uint64_t parse_option_integer(const std::string& text, const std::string& option, std::uint64_t min,
                                   std::uint64_t max) {
  std::uint64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || value < min || value > max)
    throw Usage_error("option " + option + " needs an integer from " + std::to_string(min) + " to " +
                      std::to_string(max) + ", not '" + text + "'");
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

bool parse_diagram_option(const std::vector<std::string>& args, std::size_t& i, Diagram_options& options) {
  if (args[i] == "--threads") {
    options.threads = parse_threads(option_value(args, i));
    return true;
  }
  return parse_read_option(args[i], options.read_options);
}

void parse_diagram_option_or_input(const std::vector<std::string>& args, std::size_t& i, Diagram_options& options,
                                   std::string& input) {
  if (parse_diagram_option(args, i, options)) return;
  if (!input.empty()) throw Usage_error("unexpected argument '" + args[i] + "'");
  input = positional(args[i]);
}

double parse_coordinate_tolerance(const std::string& text) {
  const double tolerance = parse_option_number(text, "--coord-tol");
  if (tolerance < 0) throw Usage_error("option --coord-tol needs a number >= 0");
  return tolerance;
}

const std::string& positional(const std::string& argument) {
  if (argument.size() > 1 && argument[0] == '-') throw Usage_error("unknown option '" + argument + "'");
  return argument;
}

void write_command_output(const std::string& path, std::ostream& out, const std::function<void(std::ostream&)>& write) {
  if (path.empty()) {
    std::ostringstream buffer;
    write(buffer);
    out << buffer.str() << std::flush;
    return;
  }
  try {
    write_file_atomically(path, write);
  } catch (const std::runtime_error& e) {
    throw Usage_error(e.what());
  }
}

}  // namespace apollonius
