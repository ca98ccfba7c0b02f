// The exact decision at the end of every subdivision: enumerate the quadruples of a few candidate sites
// and keep their vertices that lie in the region and that no owner beats. Used by the octree's leaves and
// by the far field; the brute force keeps its own loop, so that the reference shares no code with them.
#pragma once

#include <functional>
#include <utility>
#include <vector>

#include "diagram/diagram.h"
#include "predicates/vertex.h"
#include "predicates/vertices_of.h"

namespace apollonius {

// A vertex with its tie set (ascending): the very element of the diagram it goes to.
using Found_vertex = Diagram_vertex;

// Appends every vertex of a quadruple of `candidates` for which `located` holds and no site of `owners` is
// strictly closer, with its tie set among `candidates` and `owners`. `owners` must contain every site that
// owns a point where `located` holds; a vertex equal to one already in out[first..] is not appended again.
// Kernel: kernels.h.
template <class Kernel>
void decide_quadruples(const std::vector<Site>& sites, const std::vector<Site_index>& candidates,
                       const std::vector<Site_index>& owners, const std::function<bool(const Vertex&)>& located,
                       std::vector<Found_vertex>& out, std::size_t first);

// Appends `found` to `out` unless an equal vertex is already in out[first..], and settles it (diagram.h):
// the list holds each vertex until the assembly, so it is rounded here, in parallel, and its exact values go.
template <class Kernel>
void append_unique(std::vector<Found_vertex>& out, std::size_t first, Found_vertex found);

// The index among `roots` of the root equal to u, given that u is a root whenever the roots are discrete
// (none when they are not); the intervals tell most apart, compare the rest. Kernel: kernels.h.
template <class Kernel>
std::size_t root_equal_to(const Vertex& u, const Quadruple_vertices& roots);

}  // namespace apollonius
