// Triangle meshes of the faces of an Apollonius diagram, cut by a box (paper section 5.4; docs/contract.md,
// "mesh"). Each face's boundary edges are sampled at a step; faces that share an edge share its samples.
// A face is triangulated in its bisector plane (CGAL's constrained Delaunay triangulation and Delaunay
// refinement, the bisector_frame.h density for the Lloyd iterations, i.e. a centroidal Voronoi tessellation
// under the paper's eq. 37) and lifted onto its sheet. The faces are then cut by the box's six planes, and
// each cell's cut is closed by its pieces of the box's walls, so that every cell's mesh is closed.
// APPROXIMATE: coordinates are doubles. Which faces, edges and vertices exist is the exact diagram; which
// pieces of a face lie in the box is decided on the samples' coordinates.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "mesh/bisector_frame.h"
#include "predicates/axis_box.h"
#include "topology/topology.h"

namespace apollonius {

// A triangle of a face (site_a < site_b, both sites; face_id the topology's face) or of a wall: the piece
// of the box wall `wall` (0..5: x = lo, x = hi, y = lo, y = hi, z = lo, z = hi; 6: with a probe, the sphere
// of radius w + P about site_b) inside the cell of site_b, with site_a = -1 - wall and face_id = -1.
// Orientation: a face's normal points from site_a's cell into site_b's; a wall's out of the box (or ball).
struct Mesh_triangle {
  std::array<std::uint32_t, 3> vertices;
  std::int32_t site_a, site_b;
  std::int64_t face_id;
  bool is_wall() const { return site_a < 0; }
};

struct Mesh_statistics {
  std::size_t faces_meshed = 0, edge_samples = 0, lloyd_iterations = 0;
  std::size_t open_rims = 0;  // cut edges of a cell found on no wall (0 when every cell mesh closed)
  std::size_t faces_not_remeshed = 0;  // cut faces whose boundary did not allow meshing them again
  bool remesh_abandoned = false;       // some cell came out open after meshing cut faces again
  std::size_t open_cells = 0;          // cells whose mesh is not closed in the end (0 expected)
  double sampling_seconds = 0, faces_seconds = 0, cut_seconds = 0;
};

struct Diagram_mesh {
  std::vector<Point3> points;
  std::vector<Mesh_triangle> triangles;
  Axis_box box;
  double step = 0;
  Mesh_statistics statistics;
};

struct Mesh_options {
  double step = 0;                   // 0: 2% of the box's diagonal
  bool has_box = false;              // else the sites' bounding box grown by their largest weight
  Axis_box box{};
  bool has_probe = false;            // cut by the probe-expanded balls instead of a box (not with has_box)
  double probe = 1.4;                // P >= 0: face (i, j) where d_i <= P, closed by the spheres w_i + P
  std::vector<Site_index> sites;     // the cells to mesh (ascending); empty: every cell
  int lloyd_iterations = 20;
  bool remesh_cut_faces = true;  // cut faces meshed again from their new boundary (no slivers at walls)
  int threads = 1;
};

// The box `mesh` uses by default: the bounding box of the non-hidden sites' centres grown by their
// largest weight (at least 0); an axis of no extent is grown by half the largest extent (or 1).
Axis_box default_mesh_box(const std::vector<Site>& sites, const Diagram& diagram);

// Throws std::invalid_argument for a step that is not positive and finite or a box of no volume.
Diagram_mesh mesh_diagram(const std::vector<Site>& sites, const Diagram_topology& topology,
                          const Mesh_options& options = {});

}  // namespace apollonius
