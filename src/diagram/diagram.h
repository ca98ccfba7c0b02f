// The vertex set of an Apollonius diagram, as every algorithm reports it and every writer prints it.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "diagram/cancellation.h"
#include "predicates/axis_box.h"
#include "predicates/site.h"
#include "predicates/vertex.h"

namespace apollonius {

// Invariant: tie_set is ascending, has 4 or more sites, and contains vertex.sites(). The algorithms make
// these, settled or not, and assemble_diagram sorts them where they lie: one copy of them at a time.
struct Diagram_vertex {
  std::vector<Site_index> tie_set;  // every site at the minimum weighted distance
  Vertex vertex;                    // one defining quadruple of the tie set, and its root
  // x, y, z, r: the correctly rounded doubles, for output only; NaN until settled or assembled.
  std::array<double, 4> rounded{kNaN, kNaN, kNaN, kNaN};

  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  bool is_rounded() const { return !std::isnan(rounded[0]); }
};

// Rounds v unless it is rounded, then releases its vertex's exact values (Vertex::release_exact_values):
// for the lists that hold vertices until the assembly, where the exact values of a near-degenerate input
// would otherwise pile up.
template <class Kernel>
void settle(Diagram_vertex& v) {
  if (!v.is_rounded()) v.rounded = Kernel::printed_coordinates(v.vertex);
  Kernel::release_exact_values(v.vertex);
}

// A site whose cell has no interior: inside (or tangent inside) the ball of hidden_by, or an exact
// duplicate of the earlier site hidden_by.
struct Hidden_site {
  Site_index site;
  Site_index hidden_by;
  bool duplicate;
};

// Invariants: vertices sorted by tie set, then by printed x, y, z, r, then exactly; each point once;
// hidden ascending by site; sites_without_vertex ascending, disjoint from hidden.
struct Diagram {
  std::size_t site_count = 0;
  std::vector<Diagram_vertex> vertices;
  std::vector<Hidden_site> hidden;
  std::vector<Site_index> sites_without_vertex;
};

// Keeps only the vertices whose centre lies in the closed box (exact).
void restrict_to_box(Diagram& diagram, const Axis_box& box);

// Rounds, sorts and classifies raw vertices (each point once, with its full tie set) into a Diagram.
// Kernel: kernels.h (the certified one, unless for the floating path). Checks cancellation
// (cancellation.h) while rounding.
template <class Kernel>
Diagram assemble_diagram(std::size_t site_count, std::vector<Hidden_site> hidden, std::vector<Diagram_vertex> vertices,
                         const Cancellation* cancellation = nullptr);

// The same from several lists (one per thread), gathered onto one with room for all if there is one (else
// into a new one), then sorted in place.
template <class Kernel>
Diagram assemble_diagram(std::size_t site_count, std::vector<Hidden_site> hidden,
                         std::vector<std::vector<Diagram_vertex>> lists, const Cancellation* cancellation = nullptr);

}  // namespace apollonius
