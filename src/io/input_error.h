// Bad input (docs/contract.md): a message naming the file, the line and the reason; the command exits 2.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace apollonius {

class Input_error : public std::runtime_error {
 public:
  // line 0 means the error concerns the whole file (missing, unreadable, empty).
  Input_error(std::string file, std::size_t line, std::string reason);
  const std::string& file() const { return file_; }
  std::size_t line() const { return line_; }
  const std::string& reason() const { return reason_; }

 private:
  std::string file_;
  std::size_t line_;
  std::string reason_;
};

}  // namespace apollonius
