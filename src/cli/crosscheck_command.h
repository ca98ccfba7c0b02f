// `apollonius3d crosscheck INPUT ...`: the octree certified against itself in plain doubles
// (docs/contract.md).
#pragma once

#include "cli/command.h"

namespace apollonius {

Command_run add_crosscheck_command(CLI::App& app);

}  // namespace apollonius
