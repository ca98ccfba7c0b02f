// `apollonius3d centroidal INPUT --domain ...`: the centroidal Apollonius diagram in a box (docs/contract.md).
#pragma once

#include "cli/command.h"

namespace apollonius {

Command_run add_centroidal_command(CLI::App& app);

}  // namespace apollonius
