#include "topology/vertex_free.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <shared_mutex>
#include <stdexcept>

#include <boost/container/small_vector.hpp>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "diagram/threads.h"
#include "diagram/cancellable_steps.h"
#include "diagram/flat_lists.h"
#include "octree/lifted_triangulation.h"
#include "predicates/arc_witness.h"
#include "predicates/rational_between.h"
#include "predicates/rounding_guard.h"
#include "predicates/curve_point_in_box.h"
#include "predicates/sheet_point.h"
#include "predicates/trisector_predicates.h"
#include "predicates/trisector_rows.h"
#include "topology/reaching_sites.h"
#include "topology/region_site_sets.h"

namespace apollonius {
namespace {

using Triple = std::array<Site_index, 3>;
using Pair = std::pair<Site_index, Site_index>;

// For each site, the ids (ascending) of the items whose site sets hold it.
using Items_by_site = Flat_lists<std::size_t>;
using Items = Items_by_site::Range<const std::size_t*>;

template <class Set_of>
Items_by_site items_by_site(std::size_t site_count, std::size_t count, Set_of set_of, const Cancellation* cancellation) {
  return Items_by_site(
      site_count,
      [&](auto emit) {
        for (std::size_t i = 0; i < count; ++i)
          for (Site_index s : set_of(i)) emit(s, i);
      },
      cancellation);
}

bool share(Items x, Items y) {
  while (x.first != x.last && y.first != y.last) {
    if (*x.first == *y.first) return true;
    *x.first < *y.first ? ++x.first : ++y.first;
  }
  return false;
}

// Where the candidates were seen: the region boxes' site sets (Region_site_sets); far: in a far field patch.
// Inline: most candidates are seen in a few sets, and there are a million candidates on a large input.
struct Occurrences {
  boost::container::small_vector<std::uint32_t, 4> sets;
  bool far = false;
};

// Calls visit(b) for each region box b of the sets where a candidate was seen, until it returns true.
template <class Visit>
void for_boxes(const Region_site_sets& region_sets, const Occurrences& seen, Visit visit) {
  for (std::uint32_t set : seen.sets)
    for (std::uint32_t b : region_sets.boxes(set))
      if (visit(b)) return;
}

// The sites of a region box or the escaping sites, ascending; or those that may reach a witness, in any order
// (a witness's tests do not depend on it).
struct Site_range {
  const Site_index* first;
  const Site_index* last;
  const Site_index* begin() const { return first; }
  const Site_index* end() const { return last; }
};
template <class Sites>
Site_range range_of(const Sites& sites) {
  return {sites.data(), sites.data() + sites.size()};
}

// The owners' test at a witness against `sites_to_test`: nothing when a site is closer, else the tie set.
template <class Conflict>
std::optional<std::vector<Site_index>> tie_at(const std::vector<Site_index>& base, Site_range sites_to_test, Conflict conflict) {
  std::vector<Site_index> tie = base;
  for (Site_index s : sites_to_test) {
    if (std::find(base.begin(), base.end(), s) != base.end()) continue;
    const Sign c = conflict(s);
    if (c == Sign::NEGATIVE) return std::nullopt;
    if (c == Sign::ZERO) tie.push_back(s);
  }
  std::sort(tie.begin(), tie.end());
  return tie;
}

// The filter of the curve's test: decides from an enclosure X of its canonical point W (which holds the exact
// W), relative to the trisector's site o, when the enclosure's signs are certain: nothing = no edge; a tie
// set = the triple alone. Else undecided (the exact test follows). NT: Interval, then Wide_interval and
// Mpfr_interval where the intervals did not decide (a deep input, a lattice one ulp off), whose exact W costs
// a Gmpq geometry (about half a millisecond, and thousands of bits on a deep input).
enum class Filtered_outcome { no_edge, edge, undecided };

// The sites to test a witness W against, where W lies in no box: the escaping ones, or, for the lifted
// fallback's regions, those of its one far set (every active site) that may reach W (reaching_sites.h):
// W lies within `box`, and a site that beats or ties `owner` (a site of the candidate) at W is within
// owner's distance. The range lives until the thread's next call.
Site_range witness_sites(const Octree_regions& regions, const Reaching_sites* reaching,
                         const std::array<Interval, 3>& box, const Site& owner) {
  if (reaching == nullptr) return range_of(regions.escaping);
  thread_local std::vector<Site_index> near;
  Rounding_guard guard;
  reaching->find(box, weighted_distance_upper_bound(box, owner), near);
  return range_of(near);
}

Interval in_double_range(const Interval& x) { return x; }
template <class NT>
Interval in_double_range(const NT& x) {  // Wide_interval, Mpfr_interval: infinite bounds beyond the range
  return x.to_interval();
}

template <class NT>
Filtered_outcome filtered_curve_test(const Trisector& t, const Vector4<NT>& X, const Site& o,
                                     const std::vector<Site>& sites, const Octree_regions& regions,
                                     const Region_site_sets& region_sets, const Occurrences& seen,
                                     const Reaching_sites* reaching) {
  const NT half(0.5);
  const std::array<Interval, 3> v{in_double_range(NT(o.x) + X[0] * half), in_double_range(NT(o.y) + X[1] * half),
                                  in_double_range(NT(o.z) + X[2] * half)};
  const auto inside = [&](const Axis_box& b) {  // certainly inside, certainly not, or unsure
    bool in = true, out = false;
    for (int k = 0; k < 3; ++k) {
      in = in && v[k].inf() >= b.lo[k] && v[k].sup() <= b.hi[k];
      out = out || v[k].sup() < b.lo[k] || v[k].inf() > b.hi[k];
    }
    return in ? 1 : out ? 0 : -1;
  };
  std::optional<Site_range> test;
  const int in_root = regions.has_octree ? inside(regions.root) : 0;
  if (in_root < 0) return Filtered_outcome::undecided;
  if (in_root == 1) {
    bool unsure = false;
    for_boxes(region_sets, seen, [&](std::uint32_t b) {
      const int in = inside(regions.boxes[b].box);
      if (in == 1) test = range_of(regions.boxes[b].sites);
      unsure = in < 0;
      return in != 0;
    });
    if (unsure) return Filtered_outcome::undecided;
    // W in no box that holds the triple: the curve is no edge.
    if (!test) return Filtered_outcome::no_edge;
  } else {
    if (!seen.far) return Filtered_outcome::undecided;
    test = witness_sites(regions, reaching, v, sites[t.indices()[0]]);
  }
  bool all_farther = true;
  for (Site_index s : *test) {
    if (s == t.indices()[0] || s == t.indices()[1] || s == t.indices()[2]) continue;
    // d_s - r at W (curve_point_conflict): POSITIVE if r + w_s < 0, else the sign of h_s - R_s . X.
    Sign c;
    try {
      const Relative_site<NT> r = relative_site<NT>(o, sites[s]);
      const NT reach = X[3] + NT(2) * r.row[3];
      if (certain_sign(reach) == Sign::NEGATIVE) {
        c = Sign::POSITIVE;
      } else {
        c = certain_sign(r.rhs - (r.row[0] * X[0] + r.row[1] * X[1] + r.row[2] * X[2] + r.row[3] * X[3]));
      }
    } catch (const Uncertain_sign&) {
      all_farther = false;
      continue;
    }
    if (c == Sign::NEGATIVE) return Filtered_outcome::no_edge;
    if (c != Sign::POSITIVE) all_farther = false;
  }
  return all_farther ? Filtered_outcome::edge : Filtered_outcome::undecided;
}

// A witness's coordinates enclosed once by rationals (rational_between.h), so that finding a box that
// holds it costs comparisons of rationals, and the exact test (curve_point_in_box) runs only for a box
// whose bound falls inside an enclosure. The octree may list thousands of boxes for one candidate (one
// per binade of a deep input), which one exact test each made slow.
class Located_witness {
 public:
  explicit Located_witness(const Curve_point& w) : w_(w) {
    const Field_point<Rational> X = w.coordinates<Rational>();
    const Site& o = w.trisector().origin();
    const double origin[3] = {o.x, o.y, o.z};
    for (int k = 0; k < 3; ++k) {
      Vector4<Rational> unit{Rational(0), Rational(0), Rational(0), Rational(0)};
      unit[k] = Rational(1) / 2;
      bounds_[k] = rational_bounds(euclidean_value(X, unit, Rational(origin[k])), 64);
    }
  }

  bool in(const Axis_box& box) const {
    bool certain = true;
    for (int k = 0; k < 3; ++k) {
      const Rational lo(box.lo[k]), hi(box.hi[k]);
      if (bounds_[k].second < lo || bounds_[k].first > hi) return false;
      certain = certain && lo <= bounds_[k].first && bounds_[k].second <= hi;
    }
    return certain || curve_point_in_box(w_, box);
  }

  // The coordinates' enclosure in doubles, rounded outwards.
  std::array<Interval, 3> enclosure() const {
    std::array<Interval, 3> box;
    for (int k = 0; k < 3; ++k)
      box[k] = Interval(CGAL::to_interval(bounds_[k].first).first, CGAL::to_interval(bounds_[k].second).second);
    return box;
  }

 private:
  const Curve_point& w_;
  std::array<std::pair<Rational, Rational>, 3> bounds_;
};

// The vertex-free curves of more than three tied sites found so far. Each is the whole trisector of every
// triple of its tie set (a trisector is one connected curve, and a vertex-free edge is all of it), so such a
// triple would find the same edge again: it is skipped. Without this, balls of one weight on one circle, k
// of them tied along its axis, cost k triples times k exact tests (circle-mixed 4,000: 1.7 million, 15 s).
// Shared by the threads; which triple finds a curve first does not change the edges kept.
class Found_curves {
 public:
  explicit Found_curves(std::size_t site_count) : site_count_(site_count) {}

  bool covers(const Triple& t) const {
    if (!any_.load(std::memory_order_acquire)) return false;
    std::shared_lock lock(mutex_);
    for (std::uint32_t curve : curves_of_site_[t[0]]) {
      const std::vector<Site_index>& tie = tie_sets_[curve];
      if (std::binary_search(tie.begin(), tie.end(), t[1]) && std::binary_search(tie.begin(), tie.end(), t[2]))
        return true;
    }
    return false;
  }

  void add(const std::vector<Site_index>& tie_set) {  // ascending, more than three sites
    std::unique_lock lock(mutex_);
    if (curves_of_site_.empty()) curves_of_site_.resize(site_count_);
    const auto curve = static_cast<std::uint32_t>(tie_sets_.size());
    tie_sets_.push_back(tie_set);
    for (Site_index s : tie_set) curves_of_site_[s].push_back(curve);
    any_.store(true, std::memory_order_release);
  }

 private:
  std::size_t site_count_;
  std::atomic<bool> any_{false};
  mutable std::shared_mutex mutex_;
  std::vector<std::vector<Site_index>> tie_sets_;
  std::vector<std::vector<std::uint32_t>> curves_of_site_;  // empty until the first curve; ids into tie_sets_
};

}  // namespace

Vertex_free_parts vertex_free_parts(const std::vector<Site>& sites, const Diagram& diagram,
                                    const std::vector<Diagram_edge>& edges, const Octree_regions& regions, int threads,
                                    const Cancellation* cancellation, std::size_t all_triples_up_to) {
  return vertex_free_parts(sites, Vertex_triples(sites, diagram, cancellation), edges, regions, threads,
                           cancellation, all_triples_up_to);
}

Vertex_free_parts vertex_free_parts(const std::vector<Site>& sites, const Vertex_triples& vertex_triples,
                                    const std::vector<Diagram_edge>& edges,
                                    const Octree_regions& regions, int threads, const Cancellation* cancellation,
                                    std::size_t all_triples_up_to) {
  // A triple of three sites with a common vertex has its edges through that vertex already, and a pair with
  // a common edge has a face with a boundary: left out as they are seen, before the occurrences are sorted
  // (on BALL_SMALL_10000, 95% of the triples' occurrences and 99% of the pairs'). The pairs of escaping sites
  // on the edges through vertices, under their smaller site, sorted:
  std::vector<bool> escapes(sites.size(), false);
  for (Site_index s : regions.escaping) escapes[s] = true;
  Flat_lists<Site_index> escaping_pairs_on_edges(
      sites.size(),
      [&](auto emit) {
        for (const Diagram_edge& e : edges)
          for (std::size_t i = 0; i < e.tie_set.size(); ++i)
            if (escapes[e.tie_set[i]])
              for (std::size_t j = i + 1; j < e.tie_set.size(); ++j)
                if (escapes[e.tie_set[j]]) emit(e.tie_set[i], e.tie_set[j]);
      },
      cancellation);
  for (Site_index s : regions.escaping) std::sort(escaping_pairs_on_edges[s].begin(), escaping_pairs_on_edges[s].end());
  const auto on_an_edge = [&](Site_index a, Site_index b) {  // a < b, both escaping
    const auto others = escaping_pairs_on_edges[a];
    return std::binary_search(others.begin(), others.end(), b);
  };

  // Candidate triples and pairs, where each was seen: (candidate, site set) occurrences, sorted and grouped.
  // Set numbers in 32 bits: the occurrence lists are the largest memory of this phase.
  using Set_number = std::uint32_t;
  constexpr Set_number kFar = std::numeric_limits<Set_number>::max();
  if (regions.boxes.size() >= kFar) throw std::length_error("vertex_free_parts: 2^32 region boxes or more");
  // Boxes with the same sites offer the same candidates: each set is noted once.
  const Region_site_sets region_sets(regions, cancellation);
  std::vector<std::pair<Triple, Set_number>> triple_seen;
  std::vector<std::pair<Pair, Set_number>> pair_seen;
  // A vertex-free part that is unbounded has points of its sites' cells arbitrarily far: its sites all
  // escape (regions.escaping holds every site owning a point outside the root box). A bisector sheet is
  // unbounded, so an edge-free face (the whole sheet) has two escaping sites; so has a vertex-free
  // hyperbola branch or parabola (a whole component of the curve) three. On proteins 4% of the candidate
  // triples and 16% of the pair occurrences pass this filter: only ellipses need more.
  // So a triple that does not all escape can only be an ellipse, which it is not when its rows' Gram
  // determinant is certainly positive (trisector_rows.h, in intervals from the box's pairwise power gaps):
  // such a triple is left out before the occurrences are sorted. On 1j3h 95% of the occurrences go.
  Pairwise_gaps gaps;
  // The triples of a set of more than all_triples_up_to sites (a large set): the triangles of the lifted
  // triangulation of the union of all large sets, within the set, and those with a site whose lift is no
  // vertex of it; its pairs likewise, the edges and those with such a site (vertex_free.h). One triangulation
  // for all: thousands of boxes of a hundred sites tied along an axis took one each. Without an octree, the
  // reference offers every triple and pair; the lifted fallback's one far set is a large set like the others.
  const std::size_t largest_with_all_triples = regions.has_octree || regions.lifted_fallback
                                                   ? all_triples_up_to
                                                   : std::numeric_limits<std::size_t>::max();
  std::vector<Site_index> in_large_sets;
  const auto gather_if_large = [&](const auto& set) {
    if (set.size() > largest_with_all_triples) in_large_sets.insert(in_large_sets.end(), set.begin(), set.end());
  };
  for (std::size_t s = 0; s < region_sets.size(); ++s) gather_if_large(region_sets.sites(s));
  for (const std::vector<Site_index>& set : regions.far_sets) gather_if_large(set);
  std::sort(in_large_sets.begin(), in_large_sets.end());
  in_large_sets.erase(std::unique(in_large_sets.begin(), in_large_sets.end()), in_large_sets.end());
  std::shared_ptr<const Lifted_triangulation> lifts_storage = regions.lifts;  // the lifted fallback's, if of U
  if (in_large_sets.empty())
    lifts_storage = std::make_shared<const Lifted_triangulation>();
  else if (lifts_storage == nullptr || lifts_storage->sites != in_large_sets)
    lifts_storage = std::make_shared<const Lifted_triangulation>(lifted_triangulation(sites, in_large_sets, cancellation));
  const Lifted_triangulation& lifts = *lifts_storage;
  std::vector<bool> in_set(in_large_sets.empty() ? 0 : sites.size(), false);  // the large set being listed
  std::vector<Site_index> unplaced_in_set;
  std::vector<Triple> triangulated;
  std::vector<Pair> triangulated_pairs;
  const auto list_triangulated = [&](const auto& set) {  // set: ascending, in in_large_sets
    triangulated.clear();
    triangulated_pairs.clear();
    unplaced_in_set.clear();
    for (const Site_index s : set) in_set[s] = true;
    for (const Site_index s : set)
      if (std::binary_search(lifts.unplaced.begin(), lifts.unplaced.end(), s)) unplaced_in_set.push_back(s);
    for (const Site_index a : set) {
      const std::vector<Site_index>& around_a = lifts.neighbours_of(a);
      for (auto b = std::upper_bound(around_a.begin(), around_a.end(), a); b != around_a.end(); ++b) {
        if (!in_set[*b]) continue;
        triangulated_pairs.push_back({a, *b});
        const std::vector<Site_index>& around_b = lifts.neighbours_of(*b);
        std::vector<Site_index>::const_iterator c = std::upper_bound(around_b.begin(), around_b.end(), *b);
        for (auto d = b + 1; d != around_a.end() && c != around_b.end();) {  // common neighbours above b
          if (*d < *c) ++d;
          else if (*c < *d) ++c;
          else {
            if (in_set[*d]) triangulated.push_back({a, *b, *d});
            ++c, ++d;
          }
        }
      }
    }
    // Each pair and triple with an unplaced site once: by its first unplaced site.
    for (std::size_t u = 0; u < unplaced_in_set.size(); ++u) {
      const auto earlier_unplaced = [&](Site_index s) {
        const auto end = unplaced_in_set.begin() + static_cast<std::ptrdiff_t>(u);
        return std::binary_search(unplaced_in_set.begin(), end, s);
      };
      const Site_index first = unplaced_in_set[u];
      for (std::size_t i = 0; i < set.size(); ++i) {
        if (set[i] == first || earlier_unplaced(set[i])) continue;
        triangulated_pairs.push_back(std::minmax(first, set[i]));
        for (std::size_t j = i + 1; j < set.size(); ++j) {
          if (set[j] == first || earlier_unplaced(set[j])) continue;
          Triple t{first, set[i], set[j]};
          std::sort(t.begin(), t.end());
          triangulated.push_back(t);
        }
      }
    }
    for (const Site_index s : set) in_set[s] = false;
  };
  const auto note = [&](const auto& set, Set_number seen_in) {
    throw_if_cancelled(cancellation);
    const std::size_t size = set.size();
    bool gaps_known = false;
    const auto maybe_closed = [&](std::size_t i, std::size_t j, std::size_t k) {
      if (!gaps_known) gaps.assign(sites, set), gaps_known = true;
      return gaps.maybe_closed(i, j, k);
    };
    const auto offer_pair = [&](Site_index a, Site_index b) {  // a < b
      if (escapes[a] && escapes[b] && !on_an_edge(a, b)) pair_seen.push_back({{a, b}, seen_in});
    };
    const auto offer = [&](std::size_t i, std::size_t j, std::size_t k) {
      if (vertex_triples.contains({set[i], set[j], set[k]})) return;
      if ((escapes[set[i]] && escapes[set[j]] && escapes[set[k]]) || maybe_closed(i, j, k))
        triple_seen.push_back({{set[i], set[j], set[k]}, seen_in});
    };
    if (size <= largest_with_all_triples) {
      for (std::size_t i = 0; i < size; ++i)
        for (std::size_t j = i + 1; j < size; ++j) offer_pair(set[i], set[j]);
      for (std::size_t i = 0; i < size; ++i)
        for (std::size_t j = i + 1; j < size; ++j)
          for (std::size_t k = j + 1; k < size; ++k) offer(i, j, k);
      return;
    }
    list_triangulated(set);
    for (const Pair& p : triangulated_pairs) offer_pair(p.first, p.second);
    const auto position = [&](Site_index s) {
      return static_cast<std::size_t>(std::lower_bound(set.begin(), set.end(), s) - set.begin());
    };
    for (const Triple& t : triangulated) offer(position(t[0]), position(t[1]), position(t[2]));
  };
  // Reserved up front (at most): doubling a vector of tens of millions of occurrences copies it without a
  // check. A large set's are not known before: they grow for them.
  std::size_t pair_count = 0, triple_count = 0;
  const auto count = [&](const auto& set) {
    const std::size_t k = set.size();
    if (k > largest_with_all_triples) return;
    const std::size_t e = std::count_if(set.begin(), set.end(), [&](Site_index s) { return escapes[s]; });
    pair_count += e * (e - 1) / 2;
    triple_count += k * (k - 1) * (k - 2) / 6;
  };
  for (std::size_t s = 0; s < region_sets.size(); ++s) count(region_sets.sites(s));
  for (const std::vector<Site_index>& set : regions.far_sets) count(set);
  pair_seen.reserve(pair_count);
  triple_seen.reserve(triple_count);  // the pages left out are never touched
  {
    Rounding_guard guard;  // for the intervals of maybe_closed
    for (std::size_t s = 0; s < region_sets.size(); ++s) note(region_sets.sites(s), static_cast<Set_number>(s));
    for (const std::vector<Site_index>& set : regions.far_sets) note(set, kFar);
  }
  const auto grouped = [&](auto& seen, auto first_site, auto skip) {
    bucketed_sort(seen, sites.size(), first_site, std::less<>(), cancellation);
    std::vector<std::pair<typename std::decay_t<decltype(seen)>::value_type::first_type, Occurrences>> groups;
    for (std::size_t i = 0, group = 0; i < seen.size(); ++group) {
      if (group % 4096 == 0) throw_if_cancelled(cancellation);
      std::size_t end = i;
      Occurrences o;
      for (; end < seen.size() && seen[end].first == seen[i].first; ++end)
        seen[end].second == kFar ? void(o.far = true) : o.sets.push_back(seen[end].second);
      if (!skip(seen[i].first)) groups.push_back({seen[i].first, std::move(o)});
      i = end;
    }
    seen.clear();
    seen.shrink_to_fit();
    return groups;
  };
  const auto triples =
      grouped(triple_seen, [](const auto& o) { return o.first[0]; }, [](const Triple&) { return false; });

  // The lifted fallback's regions have no box: each witness is tested against the sites that may reach it.
  const std::optional<Reaching_sites> reaching_storage =
      regions.lifted_fallback && !regions.far_sets.empty()
          ? std::optional<Reaching_sites>(std::in_place, sites, regions.far_sets.front())
          : std::nullopt;
  const Reaching_sites* reaching = reaching_storage ? &*reaching_storage : nullptr;
  const auto in_root = [&](const Curve_point& w) {
    return regions.has_octree && curve_point_in_box(w, regions.root);
  };
  // Each candidate's test is independent: in parallel, each into its own slot. (Pointers: few candidates
  // are edges, and a million empty edges took a fifth of a second to allocate.)
  std::vector<std::unique_ptr<Diagram_edge>> found(triples.size());
  Found_curves found_curves(sites.size());
  const auto test_triple = [&](std::size_t c) {
    throw_if_cancelled(cancellation);  // a throw cancels the parallel loop
    const Triple& triple = triples[c].first;  // not a structured binding: the lambda below captures it
    if (found_curves.covers(triple)) return;
    const Occurrences& seen = triples[c].second;
    const Trisector t(triple, {sites[triple[0]], sites[triple[1]], sites[triple[2]]});
    const auto [kind, shape] = classify_trisector(t);
    if (kind != Trisector_kind::ellipse && kind != Trisector_kind::hyperbola && kind != Trisector_kind::parabola) return;
    if (kind != Trisector_kind::ellipse && !(escapes[triple[0]] && escapes[triple[1]] && escapes[triple[2]])) return;
    Diagram_edge e;
    e.curve = shape;
    e.closed = kind == Trisector_kind::ellipse;
    Filtered_outcome filtered = Filtered_outcome::undecided;
    {
      Rounding_guard guard;
      const std::optional<Vector4<Interval>> X = enclosed_canonical_point(t);
      if (X) filtered = filtered_curve_test(t, *X, t.origin(), sites, regions, region_sets, seen, reaching);
      const auto try_framed = [&](auto number) {
        using NT = decltype(number);
        if (filtered == Filtered_outcome::undecided)
          if (const std::optional<Framed_curve_point<NT>> W = framed_enclosed_canonical_point<NT>(t))
            filtered = filtered_curve_test(t, W->X, t.sites()[W->origin], sites, regions, region_sets, seen, reaching);
      };
      if (!X) try_framed(Wide_interval());  // its precision is the intervals': only where they left the range
      try_framed(Mpfr_interval());           // signs a hair from zero (a lattice one ulp off)
    }
    if (filtered == Filtered_outcome::no_edge) return;
    if (filtered == Filtered_outcome::edge) {
      e.tie_set.assign(triple.begin(), triple.end());
      found[c] = std::make_unique<Diagram_edge>(std::move(e));
      return;
    }
    const Curve_point w = arc_witness(t, std::nullopt, std::nullopt);
    std::optional<Site_range> test;
    if (in_root(w)) {
      const Located_witness located(w);
      for_boxes(region_sets, seen, [&](std::uint32_t b) {
        if (located.in(regions.boxes[b].box)) test = range_of(regions.boxes[b].sites);
        return test.has_value();
      });
    } else if (seen.far) {
      test = reaching == nullptr ? range_of(regions.escaping)
                                 : witness_sites(regions, reaching, Located_witness(w).enclosure(), sites[triple[0]]);
    }
    if (!test) return;  // W's region has not all three: the curve is no edge
    const std::optional<std::vector<Site_index>> tie = tie_at({triple.begin(), triple.end()}, *test, [&](Site_index s) {
      return curve_point_conflict(w, sites[s]);
    });
    if (!tie) return;  // not in it
    if (tie->size() > 3) found_curves.add(*tie);
    e.tie_set = *tie;
    found[c] = std::make_unique<Diagram_edge>(std::move(e));
  };
  tbb::task_arena arena(usable_threads(threads));
  arena.execute([&] { tbb::parallel_for(std::size_t{0}, triples.size(), test_triple); });
  Vertex_free_parts parts;
  parts.candidate_triples = triples.size();
  for (std::size_t c = 0; c < found.size(); ++c) {
    if (c % 4096 == 0) throw_if_cancelled(cancellation);
    if (found[c]) parts.edges.push_back(std::move(*found[c]));
  }
  std::vector<std::unique_ptr<Diagram_edge>>().swap(found);
  // A curve of k > 3 tied sites is every one of its triples' whole trisector: found by the first of them
  // tested (Found_curves), or by a few at once on several threads: once. (The smallest triple would not do: a
  // triangulated set need not offer it.)
  cancellable_sort(parts.edges.begin(), parts.edges.end(), cancellation,
                   [](const Diagram_edge& x, const Diagram_edge& y) { return x.tie_set < y.tie_set; });
  parts.edges.erase(std::unique(parts.edges.begin(), parts.edges.end(),
                                [](const Diagram_edge& x, const Diagram_edge& y) { return x.tie_set == y.tie_set; }),
                    parts.edges.end());

  // The pairs on edges through vertices were left out as they were seen: those on the vertex-free ones now.
  const Items_by_site edges_of_site = items_by_site(
      sites.size(), parts.edges.size(), [&](std::size_t e) -> const auto& { return parts.edges[e].tie_set; },
      cancellation);
  const auto pairs = grouped(pair_seen, [](const auto& o) { return o.first.first; },
                             [&](const Pair& p) { return share(edges_of_site[p.first], edges_of_site[p.second]); });
  parts.candidate_pairs = pairs.size();
  for (const auto& [pair, seen] : pairs) {
    throw_if_cancelled(cancellation);
    const Site &a = sites[pair.first], &b = sites[pair.second];
    std::optional<Site_range> test;
    for_boxes(region_sets, seen, [&](std::uint32_t box) {
      if (axis_point_in_box(a, b, regions.boxes[box].box)) test = range_of(regions.boxes[box].sites);
      return test.has_value();
    });
    if (!test && !regions.has_octree && seen.far)  // no octree: all escape
      test = witness_sites(regions, reaching, enclose_axis_point(a, b), a);
    if (!test) continue;
    const std::optional<std::vector<Site_index>> tie = tie_at({pair.first, pair.second}, *test, [&](Site_index s) {
      return axis_point_conflict(a, b, sites[s]);
    });
    if (tie && tie->size() == 2) parts.sheets.push_back(pair);
  }
  return parts;
}

}  // namespace apollonius
