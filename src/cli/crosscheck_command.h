// `apollonius3d crosscheck INPUT ...`: the floating path against the certified one (crosscheck.h).
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace apollonius {

extern const char* const crosscheck_usage;

// args[0] is "crosscheck". Disagreements go to out, a summary to err; returns 0 without disagreements,
// 1 with. Throws Usage_error or Input_error for bad arguments or input.
int run_crosscheck(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace apollonius
