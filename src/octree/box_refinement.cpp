#include "octree/box_refinement.h"

#include <algorithm>

#include "predicates/box_distance.h"
#include "predicates/kernels.h"
#include "predicates/rounding_guard.h"

namespace apollonius {
namespace {

// A box with at most this many candidates is decided (the paper: four; see box_refinement.h).
constexpr std::size_t kLeafCandidates = 6;
// The quadruple cache holds at most about this many quadruples (each up to two vertices, ~0.5 KB): about
// 1 MB, which stays in a core's cache; larger caches recompute less but run slower (docs/benchmarks.md).
constexpr std::size_t kCachedQuadruples = 2048;
// Each candidate is tested against this many of the best candidates at the box centre.
constexpr std::size_t kWitnesses = 4;
// Refining stops helping when the candidate count has not dropped for kStagnationLevels levels and the box
// is tiny against its distance to every candidate centre (kTinyBox half-diagonals): refining cannot
// separate candidates that tie at a point (a degenerate vertex) or along a curve. Boxes near site centres
// are never settled this way, nor boxes of more than kStagnantCandidates: nearly cospherical sites
// (vdrc Ext_I_Congruent_300: 300 of them) have many distinct vertices close together, which refining
// separates, where enumerating their quadruples would not end. kMaxDepth only bounds the recursion: the
// doubles span 2098 binades, so split() fails first, and a seed box 2^900 times larger than a cluster of
// sites inside it (sites spread over many orders of magnitude) still refines down to the cluster.
constexpr int kStagnationLevels = 4;
constexpr std::size_t kStagnantCandidates = 12;
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

}  // namespace

template <class Kernel>
void Box_refinement<Kernel>::find_vertices(const Axis_box& box, const std::vector<Site_index>& candidates,
                                   std::vector<Found_vertex>& out) {
  stack_.assign(candidates.begin(), candidates.end());
  cache_.limit(kCachedQuadruples);
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
  ++counts_.boxes;
  // A seed box's candidates were just filtered by the propagation, against the same kind of witnesses.
  if (depth == 0)
    stack_.insert(stack_.end(), stack_.begin() + static_cast<std::ptrdiff_t>(first), stack_.begin() + static_cast<std::ptrdiff_t>(end));
  else
    keep_undominated(box, first, end);
  const std::size_t kept = stack_.size() - end;
  const auto record = [&] {
    if (regions_ == nullptr || kept < 2) return;
    std::vector<Site_index> sites(stack_.begin() + static_cast<std::ptrdiff_t>(end), stack_.end());
    std::sort(sites.begin(), sites.end());
    regions_->push_back({box, std::move(sites)});
  };
  if (kept < 4) record();
  if (kept >= 4) {
    stagnant = kept == end - first ? stagnant + 1 : 0;
    const bool settled = kept <= kLeafCandidates || depth >= kMaxDepth ||
                         (stagnant >= kStagnationLevels && kept <= kStagnantCandidates &&
                          tiny_against_candidates(box, end));
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
  for (std::size_t k = 0; k < count; ++k) expansion[k] = expand_at_centre(sites[candidate[k]], frame);

  // The witnesses: the usable candidates of least d at the centre, ascending. Only a witness closer at
  // the centre can dominate a site on the box.
  std::array<std::size_t, kWitnesses> witness;
  std::size_t witnesses = 0;
  const auto nearer = [&](std::size_t k, std::size_t l) {
    return nearer_at_centre(sites[candidate[k]], expansion[k], sites[candidate[l]], expansion[l]);
  };
  for (std::size_t k = 0; k < count; ++k) {
    if (!expansion[k].usable) continue;
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
void Box_refinement<Kernel>::decide_leaf(const Axis_box& box, std::size_t first, std::vector<Found_vertex>& out) {
  const std::size_t k = stack_.size() - first, leaf_start = out.size();
  ++counts_.leaves;
  counts_.leaf_candidates += k;
  const std::array<bool, 3> closed_above = {box.hi[0] == root_.hi[0], box.hi[1] == root_.hi[1], box.hi[2] == root_.hi[2]};
  // Sorted once, so that every quadruple below comes out sorted.
  std::sort(stack_.begin() + static_cast<std::ptrdiff_t>(first), stack_.end());
  const Site_index* leaf = stack_.data() + first;
  for (std::size_t a = 0; a < k; ++a)
    for (std::size_t b = a + 1; b < k; ++b)
      for (std::size_t c = b + 1; c < k; ++c)
        for (std::size_t d = c + 1; d < k; ++d) {
          const std::array<Site_index, 4> quadruple = {leaf[a], leaf[b], leaf[c], leaf[d]};
          const auto keep_located = [&](const Quadruple_vertices& vertices) {
            for (const Vertex& v : vertices.vertices) {
              if (!Kernel::in_box(v, box, closed_above)) continue;
              // The candidates include every owner of the vertex: its tie set is among them.
              tie_.assign(quadruple.begin(), quadruple.end());
              bool closer = false;
              for (std::size_t o = 0; o < k && !closer; ++o) {
                if (o == a || o == b || o == c || o == d) continue;
                const Sign sign = Kernel::conflict(v, sites_[leaf[o]]);
                closer = sign == Sign::NEGATIVE;
                if (sign == Sign::ZERO) tie_.push_back(leaf[o]);
              }
              if (closer) continue;
              std::sort(tie_.begin(), tie_.end());
              append_unique<Kernel>(out, leaf_start, {tie_, v});
            }
          };
          // A leaf of many candidates (an exact tie of many sites, at the double resolution) is streamed:
          // caching its quadruples would hold them all.
          if (k > kStagnantCandidates)
            keep_located(Kernel::vertices_of_quadruple(make_quadruple(quadruple, sites_)));
          else
            keep_located(cache_.vertices_of_quadruple(quadruple, sites_));
        }
}

template class Box_refinement<Certified_kernel>;
template class Box_refinement<Floating_kernel>;

}  // namespace apollonius
