// Step 3 of the octree (paper sections 5.2.1-5.2.2): a seed box and its candidates are split into 8
// until few candidates remain, and every leaf is decided exactly.
//
// At every box, each candidate is tested against the box's best candidates (least d at the centre) with
// the certified tests of centre_expansion.h. A removed site is strictly farther than another site at every
// point of the box, so the candidates stay a superset of the owners of every point of the box. A leaf
// enumerates the quadruples of its candidates (cached per thread: neighbouring leaves share them) and
// keeps the vertices that lie in it; their tie sets are among its candidates. The paper stops at four
// candidates; a leaf of up to six (fifteen quadruples, mostly cached) costs less than the levels of
// refinement that separating the fifth and sixth would take.
//
// Degenerate input (five or more sites tangent to one sphere, lattices, balls on a circle) can keep more
// candidates in arbitrarily small boxes; such a box becomes a leaf once refining stops helping. No vertex is
// dropped: every leaf is decided exactly. A stagnant box of more than a dozen candidates is settled only if
// they tie along a curve (their lifts span a plane: no vertex; or with their power lifts a 3-space: every
// tie on one line) or at one point (a tie-point leaf).
#pragma once

#include <array>
#include <map>
#include <vector>

#include "diagram/cancellation.h"
#include "predicates/axis_box.h"
#include "predicates/centre_expansion.h"
#include "octree/work_budget.h"
#include "octree/leaf_decision.h"
#include "octree/octree_diagram.h"
#include "octree/quadruple_cache.h"
#include "octree/tie_point_star.h"

namespace apollonius {

// How much refining was done: boxes filtered, leaves decided, and candidates in those leaves.
struct Refinement_counts {
  std::size_t boxes = 0, leaves = 0, leaf_candidates = 0, quadruples = 0, distinct_quadruples = 0;
  std::size_t box_candidates = 0;  // the candidates of every box refined, summed: the refinement's work
  std::size_t lifted_leaves = 0;   // leaves decided from their candidates' lifted triangulation
};

// Work space for refining boxes, one per thread. Kernel: kernels.h.
template <class Kernel>
class Box_refinement {
 public:
  // `root`: the box whose upper faces are closed; every other box is half-open [lo, hi) on each axis.
  // `cancellation` is checked every thousand boxes or so (one seed box can take a second), and as often
  // the boxes are spent from `budget` when given (work_budget.h). `tie_point_stars`: Octree_options's.
  Box_refinement(const std::vector<Site>& sites, const Axis_box& root, const Cancellation* cancellation = nullptr,
                 Work_budget* budget = nullptr, bool tie_point_stars = true)
      : sites_(sites), root_(root), cancellation_(cancellation), budget_(budget), tie_point_stars_(tie_point_stars),
        star_(sites) {}

  // Appends every vertex located in the box (half-open, closed on the root's upper faces), with its tie set.
  // Precondition: `candidates` contains every site that owns a point of the closed box.
  void find_vertices(const Axis_box& box, const std::vector<Site_index>& candidates, std::vector<Found_vertex>& out);

  Refinement_counts counts() const;

  // Records every box that ends refinement with 2 or more candidates, with them, when they hold two sites
  // that `escapes` marks or three whose trisector may be closed (octree_diagram.h, Octree_regions).
  void record_regions(std::vector<Octree_regions::Box>* regions, const std::vector<bool>* escapes) {
    regions_ = regions;
    escapes_ = escapes;
  }

 private:
  // Refines the box whose candidates are stack_[first, stack_.size()).
  void refine(const Axis_box& box, std::size_t first, int depth, int stagnant, std::vector<Found_vertex>& out);
  // Moves the candidates that no witness dominates on the box to the end of stack_.
  void keep_undominated(const Axis_box& box, std::size_t first, std::size_t end);
  bool tiny_against_candidates(const Axis_box& box, std::size_t first) const;
  bool huge_against_candidates(const Axis_box& box, std::size_t first) const;
  void decide_leaf(const Axis_box& box, std::size_t first, std::vector<Found_vertex>& out);
  // The same, for a box of many candidates, from their lifted triangulation's 3-faces.
  void decide_lifted_leaf(const Axis_box& box, std::size_t first, std::vector<Found_vertex>& out);
  // The 3-faces of the lifted triangulation of `leaf` (ascending), remembered in lifted_faces_.
  const std::vector<std::array<Site_index, 4>>& lifted_faces_of(const std::vector<Site_index>& leaf);
  // For a tiny box of many candidates: whether their lifts span at most a plane (`vertex_free`), or, if
  // at_point_too, their lifts and power lifts a 3-space (`on_one_line`: every tie among them lies on one
  // line, the heaviest basis's, which line_basis_ then holds), or all of them tie at one point, which
  // tie_point_ then holds.
  enum class Tie { none, vertex_free, on_one_line, at_point };
  Tie classify_tie(std::size_t first, bool at_point_too);
  void decide_line_leaf(const Axis_box& box, std::size_t first, std::vector<Found_vertex>& out);
  // Appends each root of `quadruple` not in the bit set `skipped` that lies in the box and to which no site
  // of leaf[0, k) is closer, with its tie set among them. If `remember`, each such root, or root located
  // on the box's boundary outside it, that is equidistant from five or more of leaf[0, k) goes into
  // decided_here_ with them.
  void keep_roots_in_box(const std::array<Site_index, 4>& quadruple, const Quadruple_vertices& roots, unsigned skipped,
                         const Axis_box& box, const Site_index* leaf, std::size_t k, std::size_t leaf_start,
                         std::vector<Found_vertex>& out, bool remember);
  void decide_tie_point_leaf(const Axis_box& box, std::size_t first, std::vector<Found_vertex>& out);

  const std::vector<Site>& sites_;
  Axis_box root_;
  const Cancellation* cancellation_;
  Work_budget* budget_;
  bool tie_point_stars_;
  std::vector<Site_index> stack_;            // candidate lists of the boxes on the current path
  std::vector<Centre_expansion> expansion_;  // of the candidates of the box being filtered
  std::vector<Site_index> tie_;
  Quadruple_cache<Kernel> cache_;
  Refinement_counts counts_;
  std::vector<Octree_regions::Box>* regions_ = nullptr;
  const std::vector<bool>* escapes_ = nullptr;
  // The last point found by classify_tie, with every site known to tie there (ascending).
  std::vector<Vertex> tie_point_;  // empty or one
  std::vector<Site_index> tied_at_point_;
  std::array<Site_index, 4> line_basis_{};
  Tie_point_star<Kernel> star_;
  std::vector<std::array<Site_index, 4>> near_quadruples_;
  // The points decide_leaf has decided in its leaf that are equidistant from five or more of its candidates,
  // with those candidates (ascending): each is a root of every quadruple among them.
  std::vector<Found_vertex> decided_here_;
  // The lifted triangulation's 3-faces of each candidate set lifted_faces_of met, a bounded number.
  std::map<std::vector<Site_index>, std::vector<std::array<Site_index, 4>>> lifted_faces_;
};

}  // namespace apollonius
