// What the commands' argument parsers share: the usage error and the values of common options.
#pragma once

#include <cstddef>
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

// The value of --threads: an integer from 1 to 1024.
int parse_threads(const std::string& text);

// Whether argument is an option of the INPUT readers (--keep-hydrogens, --keep-waters), set in options.
bool parse_read_option(const std::string& argument, Read_options& options);

}  // namespace apollonius
