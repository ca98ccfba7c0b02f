// Vertex location by adaptive octree subdivision (paper section 5.2), with every decision exact.
//
//  0. Sites whose extent is far from 1 are first scaled by a power of two (scale_normalization.h).
//  1. Seed boxes (seed_partition.h): cubes of side 2^e over the box G of the site centres, and graded
//     shells of doubling cubes around G out to the root box R, 32 times G's size.
//  2. Candidates (candidate_propagation.h): the four nearest sites at each seed box's centre are its
//     witnesses; every site then floods through face neighbours into the boxes where none of those
//     certainly dominates it.
//  3. Refinement (box_refinement.h): each seed box and its candidates are split into 8 until at most six
//     candidates remain (or refining stops helping, on degenerate input); each leaf decides the
//     quadruples of its candidates exactly, keeping the vertices that lie in it (half-open).
//  4. Far field (far_field.h): the vertices beyond R, by directions.
//  5. The lifted fallback: when the refinement passes a budget of boxes (512 per active site, plus
//     16,384; 1,024 per site when regions are asked for), it stops and every vertex is taken from the 3-faces of the active sites' lifted
//     triangulation (lifted_vertices.h); regions asked for (the whole diagram) then have no box
//     (Octree_regions::lifted_fallback). Some degenerate inputs make
//     the octree's box count grow far faster than the sites while the triangulation stays small: 1,000
//     balls tangent to one circle, all tied at its centre, took over 120 s and 8 million boxes beside the
//     circle; the triangulation of their lifts has 9,583 3-faces. On the benchmark inputs the octree uses
//     8 to 60 boxes per site and never reaches the budget; there it is about twice as fast as the
//     triangulation at thousands of sites. So does the propagation, past a budget of seed candidates (128
//     per active site, plus 16,384), a bound on the candidates that every box below a seed box tests
//     again; with each seed box's nearest sites as witnesses, no input measured comes near it.
//     Cost: at most the budgets' boxes and seed candidates plus the triangulation,
//     O(n log n) expected for n lifts in general position. Both decide every vertex exactly, so the
//     output is the same whichever ran, for every thread count.
//     Small inputs (at most 256 active sites, certified arithmetic) go to step 5 at once: there the
//     triangulation is as fast or faster on all but one generated family and protein fragments measured
//     (balls tangent to one sphere: 0.86), by up to 5 times where the octree's depth or exact stages
//     dominate (docs/benchmarks.md, "Small inputs"). So do sites of one weight (equal_weight_lifts.h)
//     and inputs whose octree would refine through many binades more than their sites' spacing needs
//     (deep_clusters.h), where the triangulation was 2 to 9 times faster.
//
// Completeness. Removing a candidate is certified (centre_expansion.h): the site is strictly farther than
// another at every point of the box. So every box's candidates include every site that owns a point of
// it: the seed boxes by the star-shaped argument of candidate_propagation.h, their sub-boxes because
// removal is certified. A vertex of R lies in exactly one half-open leaf (the upper faces of R are
// closed), whose candidates include its whole tie set; a vertex outside R is found by far_field.h, from the
// candidates of the boxes on R's boundary, which include every site owning a point outside R.
#pragma once

#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include <boost/container/small_vector.hpp>

#include "predicates/axis_box.h"
#include "diagram/cancellation.h"
#include "diagram/diagram.h"

namespace apollonius {

struct Lifted_triangulation;  // octree/lifted_triangulation.h

// What the computation did, for --stats: wall times of the phases (the far field runs beside the
// refinement, so with more than one thread its time overlaps) and the sizes they worked on.
struct Octree_statistics {
  double partition_seconds = 0, propagation_seconds = 0, refinement_seconds = 0, far_field_seconds = 0,
         assembly_seconds = 0;
  std::size_t seed_boxes = 0, seed_candidates = 0, escaping_sites = 0, boxes = 0, leaves = 0, leaf_candidates = 0,
              quadruples = 0, distinct_quadruples = 0, far_field_quadruples = 0;
  std::size_t box_candidates = 0;  // the candidates of every box refined, summed (seed boxes included)
  // Leaves decided from their candidates' lifted triangulation: huge ones, and tie points whose star gave up.
  std::size_t lifted_leaves = 0;
  // The lifted fallback (step 5): its time and its 3-faces. The counts above then stay 0, but boxes: those
  // the refinement had reported to the budget when it stopped.
  bool lifted_fallback = false;
  bool lifted_small_input = false;  // it ran because of Octree_options::lifted_at_most_sites, not the budget
  bool lifted_one_weight = false;   // it ran because of Octree_options::lifted_for_one_weight
  bool lifted_deep_input = false;   // it ran because of Octree_options::lifted_for_deep_inputs
  bool lifted_seed_candidates = false;  // it ran because the propagation spent its budget, not the refinement
  double lifted_seconds = 0;
  std::size_t lifted_quadruples = 0;
};

// Certified: every decision exact (the default). Floating: the same algorithm in plain doubles, no filter
// and no exact stage (kernels.h), for crosscheck and to measure what exactness costs.
enum class Arithmetic { certified, floating };

// The regions the octree settled and the sites that may own their points: where the whole diagram looks
// for the curves and sheets with no vertex (topology/vertex_free.h). Every point of the root box R lies in
// some box of the octree, whose sites include its owners (the completeness argument above); every point
// outside R is owned by escaping sites. Only the boxes where such a part may be found are kept: those
// with two escaping sites or three whose trisector may be closed (predicates/trisector_rows.h), a sixth
// of them on a protein.
struct Octree_regions {
  // Inline up to a leaf's candidates: a large input has millions of boxes, and allocating (and, on Ctrl-C,
  // freeing) a vector for each took a large part of the whole diagram's time.
  using Sites = boost::container::small_vector<Site_index, 6>;
  struct Box {
    Axis_box box;
    Sites sites;  // ascending, 2 or more
  };
  // Of the boxes of the octree with 2 or more sites (which tile R with those of 0 or 1), those whose sites
  // hold two escaping ones or three that may have a closed trisector; in an order that does not depend
  // on the thread count (the seed boxes', each refined depth first).
  std::vector<Box> boxes;
  bool has_octree = false;  // false: no box at all, every active site escapes (fewer than 4 active sites)
  Axis_box root;
  std::vector<Site_index> escaping;               // ascending
  std::vector<std::vector<Site_index>> far_sets;  // the far field's patches' sites (far_field.h), 2 or more
  // No box because the refinement passed its budget (step 5): every active site escapes and they are one far
  // set, which offers its lifted triangulation's triples (topology/vertex_free.h), not all of them as the
  // reference's does.
  bool lifted_fallback = false;
  // The lifted fallback's triangulation of the active sites, which the vertex-free search takes instead of
  // building it again (seconds at 4,000 tied sites); null otherwise. Of the sites scaled by a power of two
  // when they were: a triangulation of theirs too, since the regular triangulation commutes with exact
  // scaling (scale_normalization.h).
  std::shared_ptr<const Lifted_triangulation> lifts;
};

// Whether a box of the octree with the sites [first, last) (2 or more) is kept in Octree_regions::boxes:
// two of them escape, or three may have a closed trisector (decided in intervals; certain when it says no).
bool region_box_needed(const std::vector<Site>& sites, const Site_index* first, const Site_index* last,
                       const std::vector<bool>& escapes);

struct Octree_options {
  int threads = 1;
  Octree_statistics* statistics = nullptr;  // filled in when not null
  Arithmetic arithmetic = Arithmetic::certified;
  Octree_regions* regions = nullptr;  // filled in when not null
  // When given, another thread may request it: the computation then throws Cancelled within a small
  // fraction of a second (cancellation.h says where it checks) and returns nothing. The output of a
  // computation that is not cancelled is the same as without it.
  const Cancellation* cancellation = nullptr;
  // The boxes the refinement may spend before step 5 takes over; automatic (512 per active site, plus
  // 16,384; 1,024 per site with regions) when not given, and 0 goes to step 5 at once. Regions asked for are then those of
  // Octree_regions::lifted_fallback.
  std::optional<std::size_t> box_budget{};
  // The (seed box, site) pairs the propagation may enter before step 5 takes over; automatic (128 per
  // active site, plus 16,384) when not given. The same for regions.
  std::optional<std::size_t> seed_candidate_budget{};
  // Inputs of at most this many active sites go to step 5 at once, when only the vertices are asked for and
  // the arithmetic is certified (the floating path is the octree's, for comparison); 0: never.
  std::size_t lifted_at_most_sites = 256;
  // Inputs whose active sites all have one weight go to step 5 at once too, at any size, under the same
  // conditions: their lifted triangulation is the Delaunay triangulation of the centres (equal_weight_lifts.h).
  bool lifted_for_one_weight = true;
  // Inputs whose octree would refine through more binades than their sites need (deep_clusters.h: a
  // cluster beside a ball 2^32 times farther than its spacing, sites from 1e-260 to 1e265) go to step 5 at
  // once too, under the same conditions.
  bool lifted_for_deep_inputs = true;
  // A leaf where every candidate ties at one point takes the quadruples of that point's star
  // (tie_point_star.h), and its candidates' lifted triangulation only where the star gives up; false: the
  // triangulation at once (for the tests that compare the two).
  bool tie_point_stars = true;

  // Never step 5 at once, whatever the input: the octree, and step 5 only past its budget (`--algorithm
  // octree`, and the tests of the octree).
  void never_lifted_at_once() {
    lifted_at_most_sites = 0;
    lifted_for_one_weight = false;
    lifted_for_deep_inputs = false;
  }
  // The octree alone, whatever it costs: never step 5, at once or past a budget (the tests that compare
  // the octree itself).
  void octree_alone() {
    never_lifted_at_once();
    box_budget = std::numeric_limits<std::size_t>::max();
    seed_candidate_budget = std::numeric_limits<std::size_t>::max();
  }
};

Diagram octree_diagram(const std::vector<Site>& sites, const Octree_options& options = {});

}  // namespace apollonius
