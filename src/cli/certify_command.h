// `apollonius3d certify INPUT CLAIM ...`: judges another implementation's vertex list against the exact
// diagram (docs/contract.md).
#pragma once

#include "cli/command.h"

namespace apollonius {

Command_run add_certify_command(CLI::App& app);

}  // namespace apollonius
