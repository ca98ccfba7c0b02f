// The vertex algorithms that the command line's `vertices --algorithm` and Python's `vertices(algorithm=)`
// name, the brute force aside, as Octree_options (octree_diagram.h, step 5).
#pragma once

#include <string>

#include "octree/octree_diagram.h"

namespace apollonius {

inline constexpr const char* kVertexAlgorithms[] = {"auto", "octree", "lifted"};

// auto: the defaults (the lifted triangulation at once for small inputs and for sites of one weight, else
// the octree and its budget); octree: never straight to step 5, only past the budget; lifted: step 5 at
// once. False for another name.
inline bool use_vertex_algorithm(const std::string& name, Octree_options& options) {
  if (name == "octree") {
    options.never_lifted_at_once();
  } else if (name == "lifted") {
    options.box_budget = 0;
  } else if (name != "auto") {
    return false;
  }
  return true;
}

}  // namespace apollonius
