// The octree's --stats lines (phase times, counts, and the lifted fallback when it ran), shared by the
// commands that run it.
#pragma once

#include <ostream>

#include "octree/octree_diagram.h"

namespace apollonius {

void print_octree_statistics(std::ostream& err, const Octree_statistics& s);

}  // namespace apollonius
