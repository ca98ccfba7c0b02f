// What the commands' argument parsers share: the usage error and the values of common options.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/read_sites.h"

namespace apollonius {

// A bad command line: the command exits 2 with the message and the usage text.
struct Usage_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The value after the option args[i]; advances i to it.
const std::string& option_value(const std::vector<std::string>& args, std::size_t& i);

// A finite number given to option.
double parse_option_number(const std::string& text, const std::string& option);

// An integer from min to max given to option.
std::uint64_t parse_option_integer(const std::string& text, const std::string& option, std::uint64_t min,
                                   std::uint64_t max);

// The value of --threads: an integer from 1 to 1024.
int parse_threads(const std::string& text);

// Whether argument is an option of the INPUT readers (--keep-hydrogens, --keep-waters), set in options.
bool parse_read_option(const std::string& argument, Read_options& options);

// The options of every command that reads an INPUT and computes its diagram.
struct Diagram_options {
  int threads = 1;
  Read_options read_options;
};

// Whether args[i] is one of them (--threads N, --keep-hydrogens, --keep-waters); advances i past it.
bool parse_diagram_option(const std::vector<std::string>& args, std::size_t& i, Diagram_options& options);

// args[i] as one of the diagram options or as the single positional INPUT (stored in input); anything
// else is a Usage_error. For commands whose only positional argument is INPUT.
void parse_diagram_option_or_input(const std::vector<std::string>& args, std::size_t& i, Diagram_options& options,
                                   std::string& input);

// The value of --coord-tol: a number >= 0.
double parse_coordinate_tolerance(const std::string& text);

// argument as a positional argument: a Usage_error if it looks like an option.
const std::string& positional(const std::string& argument);

// A command's output: written atomically to path, or to out when path is empty, where nothing appears
// unless all of it is ready. A file that cannot be written is a Usage_error.
void write_command_output(const std::string& path, std::ostream& out, const std::function<void(std::ostream&)>& write);

}  // namespace apollonius
