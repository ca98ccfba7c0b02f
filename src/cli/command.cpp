#include "cli/command.h"

#include <charconv>
#include <cmath>
#include <sstream>

#include "io/atomic_file.h"
#include "io/chunked_buffer.h"

namespace apollonius {

void add_diagram_options(CLI::App& command, Diagram_options& options) {
  command.add_option("--threads", options.threads, "worker threads (the output is the same for every N)")
      ->check(integer_in_range(1, 1024))
      ->type_name("N")
      ->capture_default_str();
  command.add_flag("--keep-hydrogens", options.read_options.keep_hydrogens, "PDB/mmCIF: keep hydrogen atoms");
  command.add_flag("--keep-waters", options.read_options.keep_waters, "PDB/mmCIF: keep water molecules");
}

void add_output_option(CLI::App& command, std::string& output) {
  command.add_option("-o,--output", output, "output file, written atomically (default or -: standard output)")
      ->type_name("OUT");
}

const CLI::Validator finite_number(
    [](std::string& text) {
      double value = 0;
      std::istringstream in(text);
      if (!(in >> value) || !std::isfinite(value)) return "needs a finite number, not '" + text + "'";
      return std::string();
    },
    "NUMBER");

CLI::Validator integer_in_range(std::uint64_t min, std::uint64_t max) {
  const std::string range = "an integer from " + std::to_string(min) + " to " + std::to_string(max);
  return CLI::Validator(
      [=](std::string& text) {
        std::uint64_t value = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error != std::errc() || end != text.data() + text.size() || value < min || value > max)
          return "needs " + range + ", not '" + text + "'";
        return std::string();
      },
      "INTEGER");
}

namespace {
bool process_ends = false;  // set once by main, before any command runs
}  // namespace

void set_process_ends_after_command(bool ends) { process_ends = ends; }
bool process_ends_after_command() { return process_ends; }

void write_command_output(const std::string& path, std::ostream& out, const std::function<void(std::ostream&)>& write) {
  if (path.empty() || path == "-") {
    Chunked_buffer buffer;
    std::ostream stream(&buffer);
    write(stream);
    buffer.write_to(out);
    out.flush();
    return;
  }
  write_file_atomically(path, write);
}

}  // namespace apollonius
