// The command line of the apollonius3d binary (docs/contract.md): one subcommand per job. Exit codes: 0 ok,
// 1 discrepancies (certify, crosscheck), 2 usage or input error, 3 internal error.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "cli/command.h"

namespace apollonius {

// Runs one command; `arguments` excludes the program name. Output that is not a file goes to `out`,
// messages to `err`.
int run_cli(const std::vector<std::string>& arguments, std::ostream& out, std::ostream& err);

}  // namespace apollonius
