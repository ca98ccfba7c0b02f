#include "io/input_error.h"

#include <utility>

namespace apollonius {

namespace {

std::string located_message(const std::string& file, std::size_t line, const std::string& reason) {
  if (line == 0) return file + ": " + reason;
  return file + ":" + std::to_string(line) + ": " + reason;
}

}  // namespace

Input_error::Input_error(std::string file, std::size_t line, std::string reason)
    : std::runtime_error(located_message(file, line, reason)),
      file_(std::move(file)),
      line_(line),
      reason_(std::move(reason)) {}

}  // namespace apollonius
