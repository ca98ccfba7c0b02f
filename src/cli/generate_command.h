// `apollonius3d generate KIND --n N --seed S`: the sites of a reproducible family, exactly as the tests
// generate them (src/reference/site_generators.h).
#pragma once

#include "cli/command.h"

namespace apollonius {

Command_run add_generate_command(CLI::App& app);

}  // namespace apollonius
