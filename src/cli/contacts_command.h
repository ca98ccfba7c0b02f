// `apollonius3d contacts INPUT [--probe P]`: contact areas, SAS areas and volumes (docs/contract.md).
#pragma once

#include "cli/command.h"

namespace apollonius {

Command_run add_contacts_command(CLI::App& app);

}  // namespace apollonius
