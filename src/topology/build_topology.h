// The whole diagram from its vertices (paper sections 5.3-5.5): the edges that leave every vertex, paired
// along their curves, then the faces they bound and the cells.
#pragma once

#include <utility>

#include "diagram/cancellation.h"
#include "octree/octree_diagram.h"
#include "topology/topology.h"

namespace apollonius {

struct Topology_options {
  int threads = 1;
  // When given, another thread may request it: every phase then throws Cancelled soon after (where each
  // checks it: cancellation.h) and nothing is returned. It changes no output otherwise.
  const Cancellation* cancellation = nullptr;
};

// The whole diagram of `sites` from its complete vertex diagram and the regions of the same octree run
// (octree_diagram with Octree_options::regions), or from brute_force_diagram and
// regions_for_every_site. Throws std::logic_error for what this version does not decide: at a vertex of
// 5 or more tied sites, a face whose side of every edge there is undecided at first order (never seen).
Diagram_topology build_topology(const std::vector<Site>& sites, Diagram diagram, const Octree_regions& regions,
                                const Topology_options& options = {});

// Regions that make every active site a candidate of everything (no box; one far set): O(n^3) candidate
// triples, for small inputs and references.
Octree_regions regions_for_every_site(const Diagram& diagram);

// The steps of build_topology, for tests: the edges that have a vertex (faces and cells left empty), and
// the faces and cells from all the edges and the whole-sheet faces.
Diagram_topology build_edges(const std::vector<Site>& sites, Diagram diagram, const Topology_options& options = {});
// `far_sets` (each ascending) must cover the points outside some bounded region: each such point's owners
// all in one of them (the octree's far sets, or one set of every site). A face of two sites that no far
// set holds together is bounded.
void add_faces_and_cells(const std::vector<Site>& sites, Diagram_topology& topology,
                         const std::vector<std::pair<Site_index, Site_index>>& whole_sheets,
                         const std::vector<std::vector<Site_index>>& far_sets, int threads = 1,
                         const Cancellation* cancellation = nullptr);

}  // namespace apollonius
