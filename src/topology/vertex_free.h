// The parts of the diagram with no vertex (paper section 5.5: humps, and vertex-free cells): closed edges
// (an ellipse or circle that no site cuts), edges infinite both ways, and faces that are a whole bisector
// sheet. Exact, and complete in R^3 by the octree's regions (octree_diagram.h):
//  - a trisector with no vertex of the diagram on it is in the diagram everywhere or nowhere (a tie with
//    a fourth site that changes this is a vertex), so one point W of it decides: its canonical point
//    (arc_witness). If the curve is an edge, W's owners are its tie set; W lies in a box of the octree
//    whose sites include them, or outside the root box, where the escaping sites include them. So the
//    candidates are the triples of the boxes' and the far field patches' site sets, and W is tested
//    against the sites of a box that contains it, or against the escaping sites;
//  - likewise a pair with no edge has a face only as a whole sheet, decided at the sheet's point on the
//    segment between the two centres (sheet_point.h), which lies in the sites' bounding box, inside R.
//  - an unbounded part (a whole sheet, a hyperbola branch, a parabola) has points of its sites' cells
//    arbitrarily far, so all its sites escape: only pairs of escaping sites, and only ellipses or triples
//    of escaping sites, are tested. A triple that does not all escape is left out as soon as its
//    trisector is certainly no ellipse (trisector_rows.h: the rows' Gram determinant, in intervals, is
//    positive); the others go on to the exact classification.
// The octree keeps only the boxes that hold two escaping sites or three that may have a closed trisector
// (Octree_regions): a box that holds the tie set of a vertex-free part is among them, by the last point
// (its sites are escaping, or an ellipse's), so the candidates and the box that contains W are unchanged.
// A set of more than all_triples_up_to sites, a large set (a far field patch of hundreds of escaping sites
// on a deep input made 83 million triples), offers only the triples whose three edges are edges of the
// triangulation of the lifts (lifted_triangulation.h) of U, the union of all large sets, and those with a
// site whose lift is no vertex of it; and only the pairs that are edges of it, or have such a site. That
// loses no candidate: where W is a point of an edge of the triple T, T owns W and every other site is
// strictly farther, those of U among them, so, by the argument of lifted_triangulation.h for three sites
// instead of four, the lifts of T span a cell of the regular subdivision of U's lifts (three collinear lifts
// tie on a whole sheet, never on a curve alone), which the triangulation refines: a triangle whose edges are
// edges of it, offered by a large set holding T and W (a box containing W, or the patch whose cone does);
// for a whole sheet of a and b, at its point between them, the same for two sites (two lifts of sites
// that are not hidden differ). A curve of k > 3 tied sites is every one of its triples' whole trisector:
// it is found from any triple offered, kept once, and the triples within its tie set are not tested again. One triangulation serves every large set: on balls
// tied along an axis, thousands of boxes of a hundred sites each took one apiece. The reference (no octree)
// offers every triple and pair, so that it stays the simple computation the tests trust.
// The lifted fallback (octree_diagram.h, step 5: the octree passed its box budget) leaves no box: every
// active site escapes and they are one far set, a large set like the others. Its witnesses are tested
// against the sites that may reach them (reaching_sites.h: a site left out is strictly farther than the
// triple at every point of W's enclosure), found in a kd-tree instead of a box.
// Boxes with the same sites offer the same candidates, so each distinct set of the boxes (region_site_sets.h)
// is listed once, and a candidate's boxes are those of its sets.
// Cost: O(b k) to group b boxes of at most k sites; O(k^3) triples per distinct set of k <= all_triples_up_to
// sites, each one interval test unless its sites all escape; O(u log u) expected for the triangulation of U's u sites, plus, per large set, its triangles and
// edges within the set (O(k) to O(k^2)) and k^2 per site whose lift is no vertex; those kept are sorted and
// grouped; each candidate with no vertex costs one classification, and those that pass the escaping test
// one witness, filtered (in intervals, then in wide intervals where those leave the double range), tested
// in parallel with `threads`, except those within the tie set of a curve of more than three sites found
// already (k tied sites: k tests, not k^2). For the lifted fallback, O(u log u) for the kd-tree, and per witness the
// tree's nodes that its enclosure does not exclude (all u where the enclosure leaves the double range).
#pragma once

#include <utility>
#include <vector>

#include "diagram/cancellation.h"
#include "octree/octree_diagram.h"
#include "topology/topology.h"
#include "topology/vertex_triples.h"

namespace apollonius {

struct Vertex_free_parts {
  std::vector<Diagram_edge> edges;                           // closed, or infinite both ways
  std::vector<std::pair<Site_index, Site_index>> sheets;     // faces that are a whole sheet, a < b
  std::size_t candidate_triples = 0, candidate_pairs = 0;   // those with no vertex, resp. no edge
};

// `edges` are the edges with a vertex. `regions` from the same octree run as `diagram` (or, for a
// reference, no box and every active site in one far set). Checks cancellation (cancellation.h) once per
// site set or far set whose candidates it lists, per 4096 boxes grouped and candidates grouped, and per
// candidate tested.
// `all_triples_up_to`: the largest set of an octree whose triples are all offered (tests lower it to compare).
// Eight: C(8, 3) = 56 triples, about as many as a triangulation's triangles there. Proteins and random balls
// have no larger set, or a few; boxes of 13 to 64 tied sites (lattices, balls on one circle) gave tens of
// millions of triples at 64 (lattice 4,000: 9.5 s and 1.6 GB for the diagram, 0.9 s and 47 MB at eight).
inline constexpr std::size_t kAllTriplesUpTo = 8;
Vertex_free_parts vertex_free_parts(const std::vector<Site>& sites, const Diagram& diagram,
                                    const std::vector<Diagram_edge>& edges, const Octree_regions& regions,
                                    int threads = 1, const Cancellation* cancellation = nullptr,
                                    std::size_t all_triples_up_to = kAllTriplesUpTo);
// The same, with the vertices' triples (vertex_triples.h) of the diagram, built once for the edges too.
Vertex_free_parts vertex_free_parts(const std::vector<Site>& sites, const Vertex_triples& vertex_triples,
                                    const std::vector<Diagram_edge>& edges,
                                    const Octree_regions& regions, int threads = 1,
                                    const Cancellation* cancellation = nullptr,
                                    std::size_t all_triples_up_to = kAllTriplesUpTo);

}  // namespace apollonius
