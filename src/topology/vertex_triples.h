// The triples of the vertices' tie sets, each with its vertex: the curves through vertices
// (trisector_edges.h), and the triples whose curves need no search for a vertex-free part (vertex_free.h).
// Built once for both. Cost: O(sum of k^3) for tie sets of k sites (4 triples for a generic vertex), placed
// by smallest site in linear time, then each site's list sorted.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "diagram/cancellation.h"
#include "diagram/flat_lists.h"
#include "topology/topology.h"

namespace apollonius {

struct Vertex_triple {
  std::array<Site_index, 3> triple;  // ascending
  std::uint32_t vertex;
};

class Vertex_triples {
 public:
  // Throws std::length_error with 2^32 vertices or more. Checks cancellation per 4096 triples and sites.
  Vertex_triples(std::size_t site_count, const Diagram& diagram, const Cancellation* cancellation = nullptr);

  // Invariant: sorted by (triple, vertex), so grouped by triple, and by smallest site.
  const std::vector<Vertex_triple>& all() const { return by_first_site_.values(); }
  // Whether the ascending triple is one of some vertex's tie set (its three sites have a common vertex).
  bool contains(const std::array<Site_index, 3>& triple) const;

 private:
  Flat_lists<Vertex_triple> by_first_site_;
};

}  // namespace apollonius
