// The two arithmetics the algorithms run with (docs/design.md, "Arithmetic"), as geometric traits in the way of CGAL's
// kernels: the octree reaches geometry only through one of them, so its combinatorics never see a number
// type.
//  - Certified_kernel: the filtered exact predicates, and double filters that count their rounding errors.
//  - Floating_kernel: the same predicates and filters in plain doubles, with no error bound, no filter and
//    no exact stage (`--arith float`). It exists to be compared with the certified path (`crosscheck`)
//    and to measure what exactness costs; it is never the default.
#pragma once

#include <array>

#include "predicates/axis_box.h"
#include "predicates/compare_vertices.h"
#include "predicates/is_hidden.h"
#include "predicates/lift_outside_span.h"
#include "predicates/power_lift_outside_span.h"
#include "predicates/vertex_conflict.h"
#include "predicates/vertex_in_box.h"
#include "predicates/vertex_rounding.h"
#include "predicates/vertices_of.h"

namespace apollonius {

struct Certified_kernel {
  static constexpr const char* name = "certified";
  // Multiplies the rounding-error slack of the double filters (centre_expansion.h).
  static constexpr double filter_slack = 1;
  // The far field's ranges over a patch of directions are outward-rounded intervals.
  static constexpr bool rounds_outwards = true;

  static Quadruple_vertices vertices_of_quadruple(const Quadruple& q) { return vertices_of(q); }
  static bool in_box(const Vertex& v, const Axis_box& box, const std::array<bool, 3>& closed_above) {
    return vertex_in_box(v, box, closed_above);
  }
  static Sign conflict(const Vertex& v, const Site& s) { return vertex_conflict(v, s); }
  static Sign compare(const Vertex& u, const Vertex& v) { return compare_vertices(u, v); }
  static bool outside_lift_span(const Lift_basis& basis, const Site& s) { return lift_outside_span(basis, s); }
  static bool outside_power_lift_span(const std::array<Site, 4>& basis, const Site& s) { return power_lift_outside_span(basis, s); }
  static bool hidden(const Site& i, Site_index index_i, const Site& j, Site_index index_j) {
    return is_hidden(i, index_i, j, index_j);
  }
  static void release_exact_values(Vertex& v) { v.release_exact_values(); }
  // The correctly rounded x, y, z, r; reused when vertex_in_box's exact stage computed them already.
  static std::array<double, 4> printed_coordinates(const Vertex& v) {
    const std::array<double, 4>* known = v.rounded_if_computed();
    return known != nullptr ? *known : rounded_coordinates(v);
  }
};

struct Floating_kernel {
  static constexpr const char* name = "float";
  static constexpr double filter_slack = 0;
  static constexpr bool rounds_outwards = false;

  static Quadruple_vertices vertices_of_quadruple(const Quadruple& q) { return vertices_of.floating(q); }
  static bool in_box(const Vertex& v, const Axis_box& box, const std::array<bool, 3>& closed_above) {
    return vertex_in_box.floating(v, box, closed_above);
  }
  static Sign conflict(const Vertex& v, const Site& s) { return vertex_conflict.floating(v, s); }
  static Sign compare(const Vertex& u, const Vertex& v) { return compare_vertices.floating(u, v); }
  static bool outside_lift_span(const Lift_basis& basis, const Site& s) { return lift_outside_span.floating(basis, s); }
  static bool outside_power_lift_span(const std::array<Site, 4>& basis, const Site& s) {
    return power_lift_outside_span.floating(basis, s);
  }
  static bool hidden(const Site& i, Site_index index_i, const Site& j, Site_index index_j) {
    return is_hidden.floating(i, index_i, j, index_j);
  }
  // The floating path's vertices hold no exact values.
  static void release_exact_values(Vertex&) {}
  // The point as computed in doubles.
  static std::array<double, 4> printed_coordinates(const Vertex& v) { return absolute_point<double>(v); }
};

}  // namespace apollonius
