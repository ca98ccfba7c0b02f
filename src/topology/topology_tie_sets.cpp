#include "topology/topology_tie_sets.h"

#include <algorithm>

namespace apollonius {
namespace {

void sort_unique(std::vector<std::vector<Site_index>>& sets) {
  std::sort(sets.begin(), sets.end());
  sets.erase(std::unique(sets.begin(), sets.end()), sets.end());
}

}  // namespace

Topology_tie_sets topology_tie_sets(const Diagram_topology& topology) {
  Topology_tie_sets sets;
  for (const Diagram_face& f : topology.faces) sets.bisectors.push_back({f.a, f.b});
  for (const Diagram_edge& e : topology.edges) sets.trisectors.push_back(e.tie_set);
  for (const Diagram_vertex& v : topology.vertices.vertices) sets.quadrisectors.push_back(v.tie_set);
  sort_unique(sets.bisectors);
  sort_unique(sets.trisectors);
  sort_unique(sets.quadrisectors);
  return sets;
}

}  // namespace apollonius
