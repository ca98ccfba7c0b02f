// A planar region, given by constraint polylines, triangulated and refined with CGAL's 2D meshing
// (Constrained_Delaunay_triangulation_2, Delaunay_mesher_no_edge_refinement_2, then Lloyd iterations of
// Mesh_global_optimizer_2 under a density): the parameter domain of a face in its bisector plane, or a
// wall's piece of a cell. The constraint points are never moved nor split, so regions that share a
// boundary polyline share its points. APPROXIMATE (doubles).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

#include "mesh/bisector_frame.h"

namespace apollonius {

using Point2 = std::array<double, 2>;

struct Plane_mesh_input {
  // Each polyline's consecutive points are joined by a constraint; `ids` names each point (>= 0, an
  // existing mesh point) or -1 (made here, lifted when used).
  struct Polyline {
    std::vector<Point2> points;
    std::vector<std::int64_t> ids;
  };
  std::vector<Polyline> polylines;
  // Whether the region of the complement of the polylines around this point is to be meshed.
  std::function<bool(const Point2&)> inside;
  // The embedding of the plane in R^3 (the sheet, or the wall) and the Lloyd density (eq. 37, or 1).
  std::function<Point3(const Point2&)> lift;
  std::function<double(const Point2&)> density;
  // The label of a region that a constraint between two existing points bounds, or -1 if it tells none.
  std::function<std::int64_t(std::int64_t, std::int64_t)> segment_label;
  std::int64_t default_label = -1;
  double step = 1;         // the spacing of the boundary samples, measured in R^3
  // Refined triangles' longest edge at most size_factor x step: 1.4 leaves interior edges about as long
  // as the boundary's chords once the Lloyd iterations have spread the points (measured: docs/benchmarks.md).
  double size_factor = 1.4;
  double lloyd_convergence = 0.001, lloyd_freeze = 0.001;
  int lloyd_iterations = 20;
  bool lattice = true;  // start the interior from a triangular lattice
};

struct Plane_mesh_output {
  std::vector<Point3> new_points;                  // referenced as id -1 - k
  std::vector<std::array<std::int64_t, 3>> triangles;  // counterclockwise in the plane
  std::vector<std::int64_t> labels;                // per triangle
  std::size_t lloyd_iterations = 0;
};

Plane_mesh_output mesh_plane_region(const Plane_mesh_input& input);

// Whether p is inside the closed polylines given as segments: an odd number of them cross the ray from p
// towards +x. Exact on the doubles given (each crossing by an exact orientation test); a point on a
// segment counts as outside of it.
bool odd_crossings(const std::vector<std::pair<Point2, Point2>>& segments, const Point2& p);

}  // namespace apollonius
