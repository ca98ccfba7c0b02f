// `apollonius3d diagram INPUT ...`: the whole diagram, vertices, edges, faces and cells (docs/contract.md).
#pragma once

#include "cli/command.h"

namespace apollonius {

Command_run add_diagram_command(CLI::App& app);

}  // namespace apollonius
