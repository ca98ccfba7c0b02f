// `apollonius3d mesh INPUT -o OUT.ply|OUT.obj`: triangle meshes of the faces and cells (docs/contract.md).
#pragma once

#include "cli/command.h"

namespace apollonius {

Command_run add_mesh_command(CLI::App& app);

}  // namespace apollonius
