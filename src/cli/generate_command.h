// `apollonius3d generate KIND --n N --seed S [-o OUT]`: the sites the tests generate, as balls text, so
// that any failing case can be reproduced.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace apollonius {

extern const char* const generate_usage;

// args[0] is "generate". Throws Usage_error for bad arguments.
int run_generate(const std::vector<std::string>& args, std::ostream& out);

}  // namespace apollonius
