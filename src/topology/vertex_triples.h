// The triples of the vertices' tie sets, each with its vertex: the curves through vertices
// (trisector_edges.h), and the triples whose curves need no search for a vertex-free part (vertex_free.h).
// Built once for both. A tie set of k <= kEveryTripleUpTo sites lists every triple (4 for a generic
// vertex); a larger one only those that its star offers (departure_star.h), at most 64 k, unless the star
// gives up. contains() still answers for every triple of every tie set. Cost: O(sum of k^3) over the small
// tie sets, the stars of the large ones, placed by smallest site in linear time, then each site's list
// sorted.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "diagram/cancellation.h"
#include "diagram/flat_lists.h"
#include "topology/topology.h"

namespace apollonius {

// C(12, 3) = 220 triples, each decided with up to 9 predicates (vertex_fan.h), against a star of about a
// hundred patches.
inline constexpr std::size_t kEveryTripleUpTo = 12;

struct Vertex_triple {
  std::array<Site_index, 3> triple;  // ascending
  std::uint32_t vertex;
};

class Vertex_triples {
 public:
  // Throws std::length_error with 2^32 vertices or more. Checks cancellation per 4096 triples and sites, and
  // per star.
  // `every_triple_up_to`: the largest tie set listed in full (tests lower it to compare).
  Vertex_triples(const std::vector<Site>& sites, const Diagram& diagram, const Cancellation* cancellation = nullptr,
                 std::size_t every_triple_up_to = kEveryTripleUpTo);

  // Invariant: sorted by (triple, vertex), so grouped by triple, and by smallest site; every triple along
  // which an edge leaves a vertex is listed with it.
  const std::vector<Vertex_triple>& all() const { return by_first_site_.values(); }
  // Tie sets of more sites are listed by their star, unless it gave up.
  std::size_t every_triple_up_to() const { return every_triple_up_to_; }
  // Whether the ascending triple is one of some vertex's tie set (its three sites have a common vertex).
  bool contains(const std::array<Site_index, 3>& triple) const;

 private:
  std::size_t every_triple_up_to_;
  // Per site, ascending: the large tie sets listed by their star that hold it.
  Flat_lists<std::uint32_t> starred_by_site_;
  Flat_lists<Vertex_triple> by_first_site_;
};

}  // namespace apollonius
