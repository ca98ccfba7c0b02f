#include "topology/euler_characteristic.h"

namespace apollonius {

long euler_defect(const Diagram_topology& t) {
  long sum = 1 + static_cast<long>(t.vertices.vertices.size()) - static_cast<long>(t.cells.size());
  for (const Diagram_edge& e : t.edges)
    if (!e.closed) --sum;
  for (const Diagram_face& f : t.faces) {
    long closed = 0;
    for (const std::vector<std::size_t>& component : f.boundary) {
      bool open = false;  // a chain between two ends at infinity
      for (std::size_t e : component) open = open || (!t.edges[e].closed && !(t.edges[e].start && t.edges[e].end));
      if (!open) ++closed;
    }
    const long holes = closed - (f.bounded ? 1 : 0);
    sum += 1 - holes;
  }
  return sum;
}

}  // namespace apollonius
