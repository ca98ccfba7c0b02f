// Output files are written atomically (docs/contract.md): readers see the old file or the whole new one,
// never a part, and a failed command leaves no output at all.
#pragma once

#include <functional>
#include <ostream>
#include <stdexcept>
#include <string>

namespace apollonius {

// An output file that cannot be written: the command exits 2, as for bad input.
struct Output_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Runs write on a stream to a new temporary file beside path, makes it durable (flush, fsync), then
// renames it over path. If write throws or any step fails, the temporary file is removed, path is left
// as it was, and the exception propagates; failures of the file itself are Output_error
// "cannot write PATH: REASON".
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write);

}  // namespace apollonius
