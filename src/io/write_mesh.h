// Mesh files (docs/contract.md, "mesh"): PLY, binary little-endian or ASCII, with the vertices' double
// x, y, z and per triangle its vertex indices and int site_a, site_b, face_id; or OBJ, one group
// `o face_ID_A_B` per face and `o wall_W_I` per wall piece of cell I.
#pragma once

#include <ostream>

#include "mesh/diagram_mesh.h"

namespace apollonius {

void write_mesh_ply(std::ostream& out, const Diagram_mesh& mesh, bool ascii);
void write_mesh_obj(std::ostream& out, const Diagram_mesh& mesh);

}  // namespace apollonius
