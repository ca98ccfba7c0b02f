// `apollonius3d vertices INPUT ...`: every vertex of the diagram, as text or JSON (docs/contract.md).
#pragma once

#include "cli/command.h"

namespace apollonius {

Command_run add_vertices_command(CLI::App& app);

}  // namespace apollonius
