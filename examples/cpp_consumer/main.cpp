// The exact vertices of five balls through the installed library: find_package(apollonius3d).
#include <iostream>

#include "io/write_vertices.h"
#include "octree/octree_diagram.h"

int main() {
  const std::vector<apollonius::Site> balls{{1, 1, 1, 1}, {1, -1, -1, 1}, {-1, 1, -1, 1}, {-1, -1, 1, 1}, {0, 0, 3, 0.5}};
  const apollonius::Diagram diagram = apollonius::octree_diagram(balls);
  apollonius::write_vertices_text(std::cout, diagram);  // tie-set indices, then x y z r
}
