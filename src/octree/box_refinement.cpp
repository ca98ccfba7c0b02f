#include "octree/box_refinement.h"

#include <algorithm>
#include <limits>

#include "octree/lift_span.h"
#include "octree/lifted_triangulation.h"
#include "predicates/box_distance.h"
#include "predicates/kernels.h"
#include "predicates/rounding_guard.h"

namespace apollonius {
namespace {

// A box with at most this many candidates is decided (the paper: four; see box_refinement.h).
constexpr std::size_t kLeafCandidates = 6;
// The quadruple cache holds at most about this many quadruples before each leaf (each up to two vertices,
// ~0.5 KB, and a few KB more where they carry exact coordinates among subnormal sites), and
// C(kStagnantCandidates, 4) more within it. Larger caches recompute less but hold more and run no faster
// (docs/benchmarks.md, "Settled vertices, and a smaller quadruple cache").
constexpr std::size_t kCachedQuadruples = 1024;
// Each candidate is tested against this many of the best candidates at the box centre.
constexpr std::size_t kWitnesses = 4;
// Boxes filtered between two checks of the cancellation: about a millisecond.
constexpr std::size_t kBoxesPerCancellationCheck = 1024;
// Refining stops helping when the candidate count has not dropped for kStagnationLevels levels: it cannot
// separate candidates that tie at a point (a degenerate vertex) or along a curve, nor cells that repeat at
// every scale, as those of a cluster seen from a few dozen box sizes away do (a needle of cells along one
// axis, or a cluster cut by the sphere of a ball far larger than the box, which acts there as a plane:
// tests/data/regression/octree_boxes_explode_for_huge_sphere_near_cluster_*). A box of at most
// kStagnantCandidates is then settled, tiny or not, and its leaf decided exactly whatever its size: at
// most C(12, 4) = 495 quadruples. Boxes of more are never settled this way: nearly cospherical sites (vdrc
// Ext_I_Congruent_300: 300 of them) have many distinct vertices close together, which refining separates,
// where enumerating their quadruples would not end. Complexity: below the first box of at most
// kStagnantCandidates on a path, the count drops at most kStagnantCandidates - kLeafCandidates times, with
// fewer than kStagnationLevels levels between drops, so the path ends within (12 - 6 + 1) 2 = 14 levels,
// whatever the spread of scales. Two levels rather than four: along a surface where the candidates tie to
// first order every extra level quadruples the boxes (tests/data/regression/
// octree_stagnant_boxes_along_bisector_of_subnormal_cluster_*), and the families and proteins take the same
// time either way (docs/history.md, sixth stop of 2026-11-28). kMaxDepth only bounds the recursion: the
// doubles span 2098 binades, so split() fails first, and a seed box 2^900 times larger than a cluster of
// more than kStagnantCandidates sites inside it (sites spread over many orders of magnitude) still refines
// down to the cluster.
//
// A tiny box of more candidates that did not drop from its parent's is settled if they cannot be separated
// for a reason decided exactly (classify_tie): their lifts span at most a plane (sites tied along a curve,
// such as equal balls on one circle along its axis: no vertex), or every one of them ties at one point v
// (balls tangent to one sphere: a tie-point leaf, decided from the star about v). Termination: a box
// whose closure holds v keeps every site tied there, so it settles once tiny, log2(box size / distance to
// the centres) + 7 levels down, for any number of tied sites, instead of descending to the last binade
// (1,075 levels about v = 0). Along a curve of ties the same holds for the boxes that touch it.
constexpr int kStagnationLevels = 2;
// A tiny box of more than kLeafCandidates whose candidates' lifts span at most a plane is settled at
// once (no vertex among them, whatever the box). Along a line where many such sites tie (equal balls on a
// circle, along its axis) the boxes beside the line keep losing a candidate or two per level, so waiting
// for the count to stop dropping refined them all the way down: 1.8 million boxes for 51 balls, now
// 56,000. A tie at one point, or on one line, is tried only once the candidates did not drop from the
// parent's: not waiting for kStagnationLevels matters along a curve of ties near a tie point, where the
// candidates drop by one every few levels (second-order separation) and the boxes along the curve double
// at every level; trying a point earlier gave the star (tie_point_star.h) boxes it separates worse (balls
// tangent to one sphere, 1,000 of them: 1.4 s became 41 s), and a line cost its exact tests (below).
constexpr int kStagnationToClassify = 1;
// The converse of a tiny box: a box huge against its candidates (kTinyBox times the diameter of their
// lifts (x, y, z, w), bounded by the per-coordinate ranges, shorter than its shortest side) is settled
// once its count did not drop from its parent's (at most kStagnantCandidates; the leaf is decided exactly
// whatever its size). At scales far above that diameter d_i - d_j tends to u.(x_j - x_i) - (w_i - w_j)
// along each direction u from the cluster: the cells are nearly cones, and what halving separates is the
// same pattern at every level, so refining repeats it once per binade down to the cluster. Candidates
// tied to first order along one direction (z_i - w_i equal, seen along -z) keep their cells side by side
// down that axis at every scale, and a box holding the cluster keeps all of it: a ball 4e266 away made
// 885 levels of about 1,800 boxes (1.6 million; tests/data/regression/octree_depth_*). Complexity: below
// the first box of at most kStagnantCandidates on a path, a huge box is refined only if its count
// dropped, so at most kStagnantCandidates - kLeafCandidates huge levels are refined there, whatever the
// spread of scales. A huge box of more candidates, up to kLiftedLeafCandidates, is settled once its count
// did not drop for kStagnationLevels, its leaf decided from the 3-faces of their lifted triangulation
// (decide_lifted_leaf: O(k) to O(k^2) quadruples, where C(k, 4) would not end): about a cluster 1e265
// times smaller than the root, 8 boxes kept the same 37 candidates for 880 levels of about 500 boxes each
// (tests/data/regression/octree_440k_boxes_about_cluster_of_37_to_3e266.balls). So below the first box of
// at most kLiftedLeafCandidates on a path, at most 2 (64 - 6) huge levels are refined. A cluster of more
// still descends one level per binade (docs/design.md).
constexpr int kStagnationToSettleHuge = 1;
constexpr std::size_t kStagnantCandidates = 12;
constexpr std::size_t kLiftedLeafCandidates = 64;
// Neighbouring huge boxes about one cluster keep the same candidates: their 3-faces are remembered.
constexpr std::size_t kRememberedLiftedLeaves = 64;
constexpr double kTinyBox = 64;
constexpr int kMaxDepth = 2200;

// The children of a box: its axes at least half as long as the longest are halved. None if some such axis
// has no double strictly inside it.
struct Children {
  std::array<Axis_box, 8> box;
  int count = 0;
};

Children split(const Axis_box& box) {
  double longest = 0;
  for (int a = 0; a < 3; ++a) longest = std::max(longest, box.hi[a] - box.lo[a]);
  std::array<double, 3> middle;
  std::array<bool, 3> halve{};
  for (int a = 0; a < 3; ++a) {
    halve[a] = box.hi[a] - box.lo[a] >= longest / 2;
    middle[a] = box.lo[a] + (box.hi[a] - box.lo[a]) / 2;
    if (halve[a] && !(box.lo[a] < middle[a] && middle[a] < box.hi[a])) return {};
  }
  Children children;
  for (int corner = 0; corner < 8; ++corner) {
    Axis_box child = box;
    bool valid = true;
    for (int a = 0; a < 3; ++a) {
      const bool upper = corner >> a & 1;
      if (!halve[a])
        valid = valid && !upper;
      else
        (upper ? child.lo[a] : child.hi[a]) = middle[a];
    }
    if (valid) children.box[children.count++] = child;
  }
  return children;
}

// Whether the vertex is known to lie exactly on a bound of the box (on a plane x_a = bound).
bool known_on_bound(const Vertex& v, const Axis_box& box) {
  const std::array<double, 4>* rounded = v.rounded_if_computed();
  const std::array<Sign, 3>* sides = v.rounding_sides_if_computed();
  if (rounded == nullptr || sides == nullptr) return false;
  for (int a = 0; a < 3; ++a)
    if (((*rounded)[a] == box.lo[a] || (*rounded)[a] == box.hi[a]) && (*sides)[a] == Sign::ZERO) return true;
  return false;
}

}  // namespace

template <class Kernel>
void Box_refinement<Kernel>::find_vertices(const Axis_box& box, const std::vector<Site_index>& candidates,
                                   std::vector<Found_vertex>& out) {
  stack_.assign(candidates.begin(), candidates.end());
  refine(box, 0, 0, 0, out);
}

template <class Kernel>
Refinement_counts Box_refinement<Kernel>::counts() const {
  Refinement_counts counts = counts_;
  counts.quadruples = cache_.lookups();
  counts.distinct_quadruples = cache_.misses();
  return counts;
}

template <class Kernel>
void Box_refinement<Kernel>::refine(const Axis_box& box, std::size_t first, int depth, int stagnant,
                            std::vector<Found_vertex>& out) {
  const std::size_t end = stack_.size();
  counts_.box_candidates += end - first;
  if (++counts_.boxes % kBoxesPerCancellationCheck == 0) {
    throw_if_cancelled(cancellation_);
    if (budget_ != nullptr) budget_->spend(kBoxesPerCancellationCheck);
  }
  // A seed box's candidates were just filtered by the propagation, against the same kind of witnesses.
  if (depth == 0)
    stack_.insert(stack_.end(), stack_.begin() + static_cast<std::ptrdiff_t>(first), stack_.begin() + static_cast<std::ptrdiff_t>(end));
  else
    keep_undominated(box, first, end);
  const std::size_t kept = stack_.size() - end;
  const auto record = [&] {
    if (regions_ == nullptr || kept < 2 ||
        !region_box_needed(sites_, stack_.data() + end, stack_.data() + stack_.size(), *escapes_))
      return;
    regions_->emplace_back();
    regions_->back().box = box;
    Octree_regions::Sites& sites = regions_->back().sites;
    sites.assign(stack_.begin() + static_cast<std::ptrdiff_t>(end), stack_.end());
    std::sort(sites.begin(), sites.end());
  };
  if (kept < 4) record();
  if (kept >= 4) {
    stagnant = kept == end - first ? stagnant + 1 : 0;
    const bool settled = kept <= kLeafCandidates || depth >= kMaxDepth ||
                         (kept <= kStagnantCandidates &&
                          (stagnant >= kStagnationLevels ||
                           (stagnant >= kStagnationToSettleHuge && huge_against_candidates(box, end))));
    if (!settled && kept > kStagnantCandidates && kept <= kLiftedLeafCandidates && stagnant >= kStagnationLevels &&
        huge_against_candidates(box, end)) {
      record();
      decide_lifted_leaf(box, end, out);
      stack_.resize(end);
      return;
    }
    if (!settled && kept > kLeafCandidates && tiny_against_candidates(box, end)) {
      const Tie tie = classify_tie(end, stagnant >= kStagnationToClassify);
      if (tie != Tie::none) {
        record();
        if (tie == Tie::at_point) decide_tie_point_leaf(box, end, out);
        if (tie == Tie::on_one_line) decide_line_leaf(box, end, out);
        stack_.resize(end);
        return;
      }
    }
    const Children children = settled ? Children{} : split(box);
    if (children.count == 0) {
      record();
      decide_leaf(box, end, out);
    }
    else
      for (int c = 0; c < children.count; ++c) refine(children.box[c], end, depth + 1, stagnant, out);
  }
  stack_.resize(end);
}

template <class Kernel>
void Box_refinement<Kernel>::keep_undominated(const Axis_box& box, std::size_t first, std::size_t end) {
  const Box_frame frame = frame_of(box);
  const std::size_t count = end - first;
  stack_.reserve(end + count);  // the kept candidates are appended while `candidate` is read
  const Site_index* candidate = stack_.data() + first;
  const Site* sites = sites_.data();
  expansion_.resize(count);
  Centre_expansion* expansion = expansion_.data();
  for (std::size_t k = 0; k < count; ++k) expand_at_centre(sites[candidate[k]], frame, expansion[k]);

  // The witnesses: the candidates of least known d at the centre, ascending. Only a witness closer at
  // the centre can dominate a site on the box.
  std::array<std::size_t, kWitnesses> witness;
  std::size_t witnesses = 0;
  const auto nearer = [&](std::size_t k, std::size_t l) {
    return nearer_at_centre(sites[candidate[k]], expansion[k], sites[candidate[l]], expansion[l]);
  };
  for (std::size_t k = 0; k < count; ++k) {
    if (!expansion[k].weighted_known) continue;
    std::size_t at = std::min(witnesses, kWitnesses);
    for (; at > 0 && nearer(k, witness[at - 1]); --at)
      if (at < kWitnesses) witness[at] = witness[at - 1];
    if (at < kWitnesses) witness[at] = k, witnesses = std::min(witnesses + 1, kWitnesses);
  }
  std::array<Witness_expansion, kWitnesses> at_witness;
  for (std::size_t w = 0; w < witnesses; ++w) at_witness[w] = expand_witness(expansion[witness[w]]);

  Candidate_on_box on_box;  // reset for each candidate: constructing it showed in profiles
  for (std::size_t k = 0; k < count; ++k) {
    const Site& s = sites[candidate[k]];
    bool dominated = false;
    on_box.reset();
    // The witnesses before k in that order.
    for (std::size_t w = 0; w < witnesses && !dominated && witness[w] != k; ++w) {
      const Site& j = sites[candidate[witness[w]]];
      const Centre_outcome outcome = centre_tests(at_witness[w], expansion[k], frame, Kernel::filter_slack);
      if (outcome != Centre_outcome::undecided) {
        dominated = outcome == Centre_outcome::dominated;
        continue;
      }
      // Test (A) needs the witness's corner distances against a candidate no smaller than it: computed only
      // now, as most pairs are decided at the centre.
      if (!at_witness[w].has_corners && j.w <= s.w) add_corners(at_witness[w], j, frame);
      dominated = corners_or_far_dominate(j, at_witness[w], s, expansion[k], on_box, frame, Kernel::filter_slack);
    }
    if (!dominated) stack_.push_back(candidate[k]);
  }
}

template <class Kernel>
bool Box_refinement<Kernel>::tiny_against_candidates(const Axis_box& box, std::size_t first) const {
  Rounding_guard guard;
  // In box units (times a power of two): in input units the squared kTinyBox half-diagonals of a box wider
  // than about 1e152 overflowed, inf - inf settled nothing, and such boxes refined without end
  // (tests/data/regression/octree_tiny_box_test_overflowed_beyond_1e152.balls). A site so far that its
  // square overflows gets an infinite lower bound: it is far.
  const Interval unit(frame_of(box).unit);
  Interval scaled_half_diagonal_squared(0);
  for (int a = 0; a < 3; ++a)
    scaled_half_diagonal_squared += CGAL::square((Interval(box.hi[a]) - Interval(box.lo[a])) * unit * Interval(kTinyBox / 2));
  return std::all_of(stack_.begin() + static_cast<std::ptrdiff_t>(first), stack_.end(), [&](Site_index s) {
    return (squared_distance_to_box<Interval>(sites_[s], box, unit) - scaled_half_diagonal_squared).inf() > 0;
  });
}

template <class Kernel>
bool Box_refinement<Kernel>::huge_against_candidates(const Axis_box& box, std::size_t first) const {
  Rounding_guard guard;
  const Interval unit(frame_of(box).unit);
  const Site& some = sites_[stack_[first]];
  std::array<double, 4> lo = {some.x, some.y, some.z, some.w}, hi = lo;
  for (auto s = stack_.begin() + static_cast<std::ptrdiff_t>(first); s != stack_.end(); ++s) {
    const std::array<double, 4> lifted = {sites_[*s].x, sites_[*s].y, sites_[*s].z, sites_[*s].w};
    for (int a = 0; a < 4; ++a) lo[a] = std::min(lo[a], lifted[a]), hi[a] = std::max(hi[a], lifted[a]);
  }
  // kTinyBox times the lifts' diameter, squared, against the box's shortest extent, squared, in box units;
  // an overflow to inf settles nothing.
  Interval scaled_spread_squared(0);
  for (int a = 0; a < 4; ++a) scaled_spread_squared += CGAL::square((Interval(hi[a]) - Interval(lo[a])) * unit * Interval(kTinyBox));
  double scaled_shortest = std::numeric_limits<double>::infinity();  // a lower bound
  for (int a = 0; a < 3; ++a) scaled_shortest = std::min(scaled_shortest, ((Interval(box.hi[a]) - Interval(box.lo[a])) * unit).inf());
  return (CGAL::square(Interval(scaled_shortest)) - scaled_spread_squared).inf() > 0;
}

// A point equidistant from five or more candidates is a root of each of their C(t, 4) quadruples (70 for a
// lattice point). Once one of them has decided it here (located, or on the boundary and not), each later
// quadruple among those candidates has it as a root whenever its roots are discrete, so root_equal_to names
// that root (by intervals unless the two roots nearly meet) and only the other one is decided. This skips
// only what append_unique would discard or in_box reject again: the same vertices, in the same order.
// Cost: a quadruple with a remembered point as a root lies in that point's equidistant set, so each point
// is remembered once, and each quadruple scans the leaf's distinct remembered points.
template <class Kernel>
void Box_refinement<Kernel>::decide_leaf(const Axis_box& box, std::size_t first, std::vector<Found_vertex>& out) {
  const std::size_t k = stack_.size() - first, leaf_start = out.size();
  ++counts_.leaves;
  counts_.leaf_candidates += k;
  // The bound holds within a seed box too: one around a tie of many sites meets millions of quadruples.
  cache_.limit(kCachedQuadruples);
  // Sorted once, so that every quadruple below comes out sorted.
  std::sort(stack_.begin() + static_cast<std::ptrdiff_t>(first), stack_.end());
  const Site_index* leaf = stack_.data() + first;
  decided_here_.clear();
  const auto decide = [&](const std::array<Site_index, 4>& quadruple, const Quadruple_vertices& roots) {
    unsigned skipped = 0;
    for (const Found_vertex& decided : decided_here_)
      if (std::includes(decided.tie_set.begin(), decided.tie_set.end(), quadruple.begin(), quadruple.end()))
        skipped |= 1u << root_equal_to<Kernel>(decided.vertex, roots);
    keep_roots_in_box(quadruple, roots, skipped, box, leaf, k, leaf_start, out, true);
  };
  for (std::size_t a = 0; a < k; ++a)
    for (std::size_t b = a + 1; b < k; ++b)
      for (std::size_t c = b + 1; c < k; ++c)
        for (std::size_t d = c + 1; d < k; ++d) {
          const std::array<Site_index, 4> quadruple = {leaf[a], leaf[b], leaf[c], leaf[d]};
          // A leaf of many candidates (an exact tie of many sites, at the double resolution) is streamed:
          // caching its quadruples would hold them all.
          if (k > kStagnantCandidates)
            decide(quadruple, Kernel::vertices_of_quadruple(make_quadruple(quadruple, sites_)));
          else
            decide(quadruple, cache_.vertices_of_quadruple(quadruple, sites_));
        }
}

// Every vertex in the box is a vertex of the candidates' own diagram (they contain every site owning a
// point of the closed box, and none is hidden), so it is a root of a 3-face of their lifted triangulation
// (lifted_triangulation.h), located and given its tie set as in decide_leaf. Cost: the triangulation of k
// lifts, O(k log k) in general position, and O(k) conflict tests per root in the box.
template <class Kernel>
void Box_refinement<Kernel>::decide_lifted_leaf(const Axis_box& box, std::size_t first, std::vector<Found_vertex>& out) {
  const std::size_t k = stack_.size() - first, leaf_start = out.size();
  ++counts_.leaves;
  counts_.leaf_candidates += k;
  std::sort(stack_.begin() + static_cast<std::ptrdiff_t>(first), stack_.end());
  ++counts_.lifted_leaves;
  const std::vector<Site_index> leaf(stack_.begin() + static_cast<std::ptrdiff_t>(first), stack_.end());
  for (const std::array<Site_index, 4>& quadruple : lifted_faces_of(leaf))
    keep_roots_in_box(quadruple, Kernel::vertices_of_quadruple(make_quadruple(quadruple, sites_)), 0, box, leaf.data(),
                      k, leaf_start, out, false);
}

template <class Kernel>
const std::vector<std::array<Site_index, 4>>& Box_refinement<Kernel>::lifted_faces_of(
    const std::vector<Site_index>& leaf) {
  auto faces = lifted_faces_.find(leaf);
  if (faces == lifted_faces_.end()) {
    if (lifted_faces_.size() >= kRememberedLiftedLeaves) lifted_faces_.clear();
    faces = lifted_faces_.emplace(leaf, lifted_triangulation(sites_, leaf, cancellation_).quadruples).first;
  }
  return faces->second;
}

// Tried on a tiny box of more than kLeafCandidates candidates K that did not drop. The lifts' span is
// grown over K by descending weight (early exit at five sites: O(k) lift_outside_span calls only when K
// is degenerate), after an O(k log k) sort. A
// span of dimension 3 or more gives four sites whose quadruple has at most two roots; if K ties at one
// point, it is one of them (equidistant from the four, with r + w >= 0), and its k - 4 conflict tests
// confirm it. A point found before is reused while K stays among its tie set.
template <class Kernel>
typename Box_refinement<Kernel>::Tie Box_refinement<Kernel>::classify_tie(std::size_t first, bool at_point_too) {
  const auto kept = stack_.begin() + static_cast<std::ptrdiff_t>(first);
  if (at_point_too && !tie_point_.empty() && std::all_of(kept, stack_.end(), [&](Site_index s) {
        return std::binary_search(tied_at_point_.begin(), tied_at_point_.end(), s);
      }))
    return Tie::at_point;
  std::array<Site_index, 4> basis;
  const int dimension = heaviest_lift_basis<Kernel>(sites_, kept, stack_.end(), basis);
  if (dimension <= 2) return Tie::vertex_free;
  if (!at_point_too) return Tie::none;
  // Only on a box whose count stopped dropping: the power lifts of sites inside the span (the case that
  // settles the box) are decided exactly, one by one, which cost more than the boxes it saved on 1,000
  // balls of the circle family (0.7 s -> 2.1 s) when tried on every tiny box.
  if (dimension == 3) {
    const std::array<Site, 4> lifted = {sites_[basis[0]], sites_[basis[1]], sites_[basis[2]], sites_[basis[3]]};
    if (std::none_of(kept, stack_.end(), [&](Site_index s) { return Kernel::outside_power_lift_span(lifted, sites_[s]); })) {
      line_basis_ = basis;
      return Tie::on_one_line;
    }
  }
  const Quadruple_vertices roots = Kernel::vertices_of_quadruple(make_quadruple(basis, sites_));
  for (const Vertex& v : roots.vertices) {
    const bool all_tie = std::all_of(kept, stack_.end(), [&](Site_index s) {
      return std::binary_search(basis.begin(), basis.end(), s) || Kernel::conflict(v, sites_[s]) == Sign::ZERO;
    });
    if (!all_tie) continue;
    tie_point_.assign(1, v);
    tied_at_point_.assign(kept, stack_.end());
    std::sort(tied_at_point_.begin(), tied_at_point_.end());
    return Tie::at_point;
  }
  return Tie::none;
}

template <class Kernel>
void Box_refinement<Kernel>::keep_roots_in_box(const std::array<Site_index, 4>& quadruple, const Quadruple_vertices& roots,
                                               unsigned skipped, const Axis_box& box, const Site_index* leaf,
                                               std::size_t k, std::size_t leaf_start, std::vector<Found_vertex>& out,
                                               bool remember) {
  const std::array<bool, 3> closed_above = {box.hi[0] == root_.hi[0], box.hi[1] == root_.hi[1], box.hi[2] == root_.hi[2]};
  for (std::size_t r = 0; r < roots.vertices.size(); ++r) {
    const Vertex& v = roots.vertices[r];
    if (skipped >> r & 1) continue;
    const bool located = Kernel::in_box(v, box, closed_above);
    // A point exactly on the box's boundary (as lattice points are) was located exactly: worth its
    // equidistant set, so that the other quadruples of it here skip it rather than locate it again.
    if (!located && !(remember && known_on_bound(v, box))) continue;
    tie_.assign(quadruple.begin(), quadruple.end());
    bool closer = false;
    for (std::size_t o = 0; o < k && !(closer && located); ++o) {
      if (std::find(quadruple.begin(), quadruple.end(), leaf[o]) != quadruple.end()) continue;
      const Sign sign = Kernel::conflict(v, sites_[leaf[o]]);
      closer = closer || sign == Sign::NEGATIVE;
      if (sign == Sign::ZERO) tie_.push_back(leaf[o]);
    }
    std::sort(tie_.begin(), tie_.end());
    const bool complete = !(closer && located);  // every candidate tested: tie_ is the equidistant set
    if (remember && complete && tie_.size() > 4) decided_here_.push_back({tie_, v});
    if (located && !closer) append_unique<Kernel>(out, leaf_start, {tie_, v});
  }
}

// The candidates' lifts and power lifts span a 3-space (classify_tie): every quadruple of them with roots
// has the same line and polynomial (lift_span.h), so the roots of the heaviest basis are every vertex
// among them. O(k) conflict tests for each root in the box.
template <class Kernel>
void Box_refinement<Kernel>::decide_line_leaf(const Axis_box& box, std::size_t first, std::vector<Found_vertex>& out) {
  const std::size_t k = stack_.size() - first, leaf_start = out.size();
  ++counts_.leaves;
  counts_.leaf_candidates += k;
  const std::array<Site_index, 4> basis = line_basis_;
  keep_roots_in_box(basis, Kernel::vertices_of_quadruple(make_quadruple(basis, sites_)), 0, box,
                    stack_.data() + first, k, leaf_start, out, false);
}

// Every candidate ties at v = tie_point_, so every quadruple of them with a discrete set of roots has v as
// a root: v is decided once (its tie set is K: a site outside K owns no point of the closed box), and of
// each quadruple only the other root is located. Which quadruples: if the lifts of K span a 3-space, every
// such quadruple has the same line through (v, r) and the same polynomial on it (tie_point_star.h), so the
// heaviest basis gives the only other point that is a valid root of any of them (lift_span.h); otherwise
// the star about v picks the quadruples near the box, O(k) in general position. If the star gives up,
// the 3-faces of the candidates' lifted triangulation hold every vertex in the box (decide_lifted_leaf),
// O(k log k) expected for the triangulation and its size in quadruples, where all C(k, 4) quadruples
// (concentric shells of 1,000 balls: hundreds tied at the centre) would not end.
template <class Kernel>
void Box_refinement<Kernel>::decide_tie_point_leaf(const Axis_box& box, std::size_t first, std::vector<Found_vertex>& out) {
  const std::size_t k = stack_.size() - first, leaf_start = out.size();
  ++counts_.leaves;
  counts_.leaf_candidates += k;
  const std::array<bool, 3> closed_above = {box.hi[0] == root_.hi[0], box.hi[1] == root_.hi[1], box.hi[2] == root_.hi[2]};
  std::sort(stack_.begin() + static_cast<std::ptrdiff_t>(first), stack_.end());
  const Site_index* leaf = stack_.data() + first;
  const Vertex& tie_point = tie_point_.front();

  std::array<Site_index, 4> basis;
  const int dimension = heaviest_lift_basis<Kernel>(sites_, leaf, leaf + k, basis);
  if (dimension <= 2) return;  // no quadruple of K has a discrete set of roots
  if (Kernel::in_box(tie_point, box, closed_above)) append_unique<Kernel>(out, leaf_start, {std::vector<Site_index>(leaf, leaf + k), tie_point});

  // Each quadruple costs about what a box does: they are counted like boxes, for the cancellation and the
  // budget (a leaf can hold O(k^2) of them).
  std::size_t decided = 0;
  const auto decide = [&](const std::array<Site_index, 4>& quadruple, const Quadruple_vertices& roots) {
    if (++decided % kBoxesPerCancellationCheck == 0) {
      throw_if_cancelled(cancellation_);
      if (budget_ != nullptr) budget_->spend(kBoxesPerCancellationCheck);
    }
    keep_roots_in_box(quadruple, roots, 1u << root_equal_to<Kernel>(tie_point, roots), box, leaf, k, leaf_start, out, false);
  };
  if (dimension == 3) {
    decide(basis, Kernel::vertices_of_quadruple(make_quadruple(basis, sites_)));
    return;
  }
  if (tie_point_stars_ && star_.quadruples_near(tie_point, box, leaf, k, near_quadruples_)) {
    for (const std::array<Site_index, 4>& quadruple : near_quadruples_)
      decide(quadruple, Kernel::vertices_of_quadruple(make_quadruple(quadruple, sites_)));
    return;
  }
  ++counts_.lifted_leaves;
  const std::vector<Site_index> candidates(leaf, leaf + k);
  for (const std::array<Site_index, 4>& quadruple : lifted_faces_of(candidates))
    decide(quadruple, Kernel::vertices_of_quadruple(make_quadruple(quadruple, sites_)));
}

template class Box_refinement<Certified_kernel>;
template class Box_refinement<Floating_kernel>;

}  // namespace apollonius
