// `apollonius3d certify INPUT CLAIM ...` (SPEC section 4): its usage text, argument parsing and run.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace apollonius {

extern const char* const certify_usage;

// args[0] is "certify". Returns 0 without discrepancies, 1 with; throws Usage_error or Input_error for
// bad arguments or input (exit 2), anything else for an internal error (exit 3). The summary goes to err.
int run_certify(const std::vector<std::string>& args, std::ostream& err);

}  // namespace apollonius
