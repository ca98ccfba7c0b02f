// The vertex set of an Apollonius diagram, as every algorithm reports it and every writer prints it.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "diagram/cancellation.h"
#include "predicates/axis_box.h"
#include "predicates/site.h"
#include "predicates/vertex.h"

namespace apollonius {

// Invariant: tie_set is ascending, has 4 or more sites, and contains vertex.sites(). The algorithms make
// these without `rounded`, and assemble_diagram sorts them where they lie: one copy of them at a time.
struct Diagram_vertex {
  std::vector<Site_index> tie_set;   // every site at the minimum weighted distance
  Vertex vertex;                     // one defining quadruple of the tie set, and its root
  std::array<double, 4> rounded{};  // x, y, z, r: the correctly rounded doubles, for output only (set by assemble_diagram)
};

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
