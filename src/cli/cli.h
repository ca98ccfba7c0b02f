// The command line (SPEC section 4). Exit codes: 0 ok, 1 discrepancies (certify), 2 usage or input
// error, 3 internal error.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace apollonius {

enum Exit_code : int { EXIT_OK = 0, EXIT_DISCREPANCIES = 1, EXIT_BAD_INPUT = 2, EXIT_INTERNAL_ERROR = 3 };

// Runs one command; `arguments` excludes the program name. Output that is not a file goes to `out`,
// messages to `err`.
int run_cli(const std::vector<std::string>& arguments, std::ostream& out, std::ostream& err);

}  // namespace apollonius
