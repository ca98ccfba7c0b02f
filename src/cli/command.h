// What every command of the binary shares: how it is registered with the parser, the options of commands
// that compute a diagram, and where its output goes.
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <ostream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "io/read_sites.h"

namespace apollonius {

enum Exit_code : int { EXIT_OK = 0, EXIT_DISCREPANCIES = 1, EXIT_BAD_INPUT = 2, EXIT_INTERNAL_ERROR = 3 };

// A bad command line found after parsing (options that contradict each other): exit 2 with the message.
struct Usage_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Runs a parsed command: its output goes to `out` (unless to a file), messages to `err`; returns the exit code.
using Command_run = std::function<int(std::ostream& out, std::ostream& err)>;

// Registers a subcommand on `app`; the returned function runs it once `app` has parsed its arguments.
using Command_registration = std::function<Command_run(CLI::App& app)>;

// The options of every command that reads an INPUT and computes its diagram.
struct Diagram_options {
  int threads = 1;
  Read_options read_options;
};

// --threads N, --keep-hydrogens, --keep-waters.
void add_diagram_options(CLI::App& command, Diagram_options& options);

// -o,--output OUT (default and "-": standard output).
void add_output_option(CLI::App& command, std::string& output);

// A finite double (CLI11 converts "inf" and "nan" too).
extern const CLI::Validator finite_number;

// A whole decimal number from min to max (CLI11 2.1's own conversion saturates 2^64 and wraps -1).
CLI::Validator integer_in_range(std::uint64_t min, std::uint64_t max);

// Writes a command's output atomically to path, or to `out` when path is empty or "-", where nothing
// appears unless all of it is ready. A file that cannot be written is an Output_error (exit 2).
void write_command_output(const std::string& path, std::ostream& out, const std::function<void(std::ostream&)>& write);

// Whether the process ends when the command returns (set by main; not for a test that runs commands in turn).
void set_process_ends_after_command(bool ends);
bool process_ends_after_command();

// Frees `value` now, or, when the process ends after the command, never: a command's large results, once
// written, took longer to free block by block than the system takes to reclaim their pages (clang's
// -disable-free does the same). What is kept stays reachable, so no leak checker reports it.
template <class T>
void release_or_keep_until_exit(T&& value) {
  std::decay_t<T> owned(std::forward<T>(value));
  if (!process_ends_after_command()) return;
  static auto* kept = new std::vector<std::shared_ptr<void>>();
  kept->push_back(std::make_shared<std::decay_t<T>>(std::move(owned)));
}

}  // namespace apollonius
