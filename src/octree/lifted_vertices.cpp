#include "octree/lifted_vertices.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cstdint>
#include <new>
#include <stdexcept>
#include <type_traits>
#include <unordered_map>

#include "diagram/cancellable_steps.h"
#include "predicates/kernels.h"

namespace apollonius {
namespace {

// Sites tested for one vertex, by index; cleared in O(tested).
class Tested_sites {
 public:
  explicit Tested_sites(std::size_t sites) : tested_(sites, false) {}
  bool first_test(Site_index s) {
    if (tested_[s]) return false;
    tested_[s] = true;
    touched_.push_back(s);
    return true;
  }
  void clear() {
    for (Site_index s : touched_) tested_[s] = false;
    touched_.clear();
  }

 private:
  std::vector<bool> tested_;
  std::vector<Site_index> touched_;
};

// Whether site s, if not tested yet for v, is strictly closer to v; a tie goes into `tie`.
template <class Kernel>
bool beats(const Vertex& v, Site_index s, const std::vector<Site>& sites, Tested_sites& tested,
           std::vector<Site_index>& tie) {
  if (!tested.first_test(s)) return false;
  const Sign sign = Kernel::conflict(v, sites[s]);
  if (sign == Sign::ZERO) tie.push_back(s);
  return sign == Sign::NEGATIVE;
}

// The unplaced sites' part of tie_set_through_edges and tie_set_through_cells: false if one beats v.
template <class Kernel>
bool unplaced_tie(const Vertex& v, const std::vector<Site>& sites, const Lifted_triangulation& lifts,
                  Tested_sites& tested, std::vector<Site_index>& tie) {
  return std::none_of(lifts.unplaced.begin(), lifts.unplaced.end(),
                      [&](Site_index s) { return beats<Kernel>(v, s, sites, tested, tie); });
}

// The tie set of v, a root of a 3-face, or false if some site is strictly closer (lifted_vertices.h): its
// lift lies in the power cell of v's first site iff no neighbour of that site and no unplaced site beats
// it; the later passes only find ties. Cost: O((|tie set| + 1) degree + unplaced) conflict tests.
template <class Kernel>
bool tie_set_through_edges(const Vertex& v, const std::vector<Site>& sites, const Lifted_triangulation& lifts,
                           Tested_sites& tested, std::vector<Site_index>& tie) {
  const auto& own = v.sites();
  tie.assign(own.begin(), own.end());
  tested.clear();
  for (Site_index s : own) tested.first_test(s);
  if (!unplaced_tie<Kernel>(v, sites, lifts, tested, tie)) return false;
  // A site beating v after the first site's neighbours accepted it contradicts the power cell, which the
  // exact predicates cannot; the floating path's rounding can, and rejects v.
  for (std::size_t k = 0; k < tie.size(); ++k)
    for (Site_index s : lifts.neighbours_of(tie[k]))
      if (beats<Kernel>(v, s, sites, tested, tie)) {
        if (k != 0 && std::is_same_v<Kernel, Certified_kernel>)
          throw std::logic_error("lifted vertices: a site beats a vertex that its first site's neighbours accept");
        return false;
      }
  std::sort(tie.begin(), tie.end());
  return true;
}

// The tie set of v, the root of the Delaunay cell quadruples[q] (equal_weight_lifts.h), or false if an
// unplaced site is closer. The cell's circumsphere is empty, so no placed site is closer to v than its
// sites are. The placed sites on that sphere are the vertices of the cells that share it, which triangulate
// their convex hull and so are connected through facets: the cells reached across facets marked
// same_sphere. Each is marked covered, since its root is v. No conflict test but the unplaced sites';
// O(cells on the sphere).
template <class Kernel>
bool tie_set_through_cells(const Vertex& v, std::size_t q, const std::vector<Site>& sites,
                           const Lifted_triangulation& lifts, Tested_sites& tested, std::vector<bool>& covered,
                           std::vector<std::uint32_t>& cells, std::vector<Site_index>& tie) {
  const auto& own = lifts.quadruples[q];
  tie.assign(own.begin(), own.end());
  tested.clear();
  for (Site_index s : own) tested.first_test(s);
  if (!unplaced_tie<Kernel>(v, sites, lifts, tested, tie)) return false;
  cells.assign(1, static_cast<std::uint32_t>(q));
  covered[q] = true;
  for (std::size_t k = 0; k < cells.size(); ++k)
    for (const Lifted_triangulation::Across_facet& across : lifts.across_facets[cells[k]]) {
      if (!across.same_sphere || covered[across.cell]) continue;
      covered[across.cell] = true;
      cells.push_back(across.cell);
      if (tested.first_test(across.site)) tie.push_back(across.site);
    }
  std::sort(tie.begin(), tie.end());
  return true;
}

}  // namespace

template <class Kernel>
std::vector<Found_vertex> lifted_vertices(const std::vector<Site>& sites, const Lifted_triangulation& lifts,
                                          const std::function<bool(const Vertex&)>& wanted,
                                          const Cancellation* cancellation) {
  const std::vector<std::array<Site_index, 4>>& quadruples = lifts.quadruples;
  // Each thread's list, with room for a vertex per quadruple (one per Delaunay cell, equal_weight_lifts.h):
  // never moved as it grows, and one of them then takes the others. Room never filled is address space,
  // not memory. Lists per chunk of quadruples held the vertices twice while they were concatenated.
  tbb::enumerable_thread_specific<std::vector<Found_vertex>> found([&] {
    std::vector<Found_vertex> list;
    try {
      list.reserve(quadruples.size());
    } catch (const std::bad_alloc&) {
      // Address space refused (a limit, or strict overcommit): the list grows as it goes.
    }
    return list;
  });
  // At most 8 ranges per thread (a range splits while longer than the grain): a vertex of many tied sites
  // has its tie set found once in each range that meets it (below), at O(k) conflict tests. TBB's own split
  // made about 64 ranges with one thread: two-spheres 4,000 took 511,488 exact tests, now 47,952
  // (docs/benchmarks.md).
  const std::size_t grain = std::max<std::size_t>(
      1, quadruples.size() / (4 * static_cast<std::size_t>(tbb::this_task_arena::max_concurrency())));
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, quadruples.size(), grain), [&](const tbb::blocked_range<std::size_t>& range) {
    std::vector<Found_vertex>& list = found.local();
    Tested_sites tested(sites.size());
    std::vector<Site_index> tie;
    // Delaunay's cells whose root this range has decided, as one of a sphere's (tie_set_through_cells).
    const bool delaunay = !lifts.across_facets.empty();
    std::vector<bool> covered(delaunay ? quadruples.size() : 0, false);
    std::vector<std::uint32_t> cells;
    // The vertices of more than four tied sites found in this range, and for each site the ones it ties
    // at: a quadruple's first site names every such vertex that can be its root.
    std::vector<Found_vertex> degenerate;
    std::unordered_map<Site_index, std::vector<std::size_t>> degenerate_at;
    for (std::size_t q = range.begin(); q != range.end(); ++q) {
      throw_if_cancelled(cancellation);
      if (delaunay && covered[q]) continue;
      const std::size_t first = list.size();
      const std::array<Site_index, 4>& quadruple = quadruples[q];
      const Quadruple_vertices roots = Kernel::vertices_of_quadruple(make_quadruple(quadruple, sites));
      unsigned skipped = 0;
      if (const auto at = degenerate_at.find(quadruple[0]); at != degenerate_at.end())
        for (std::size_t d : at->second) {
          const std::vector<Site_index>& tied = degenerate[d].tie_set;  // O(log t): t reaches every site
          if (std::all_of(quadruple.begin(), quadruple.end(),
                          [&](Site_index s) { return std::binary_search(tied.begin(), tied.end(), s); }))
            skipped |= 1u << root_equal_to<Kernel>(degenerate[d].vertex, roots);
        }
      const auto beaten_by_apex = [&](const Vertex& v) {
        return std::any_of(lifts.apexes[q].begin(), lifts.apexes[q].end(), [&](Site_index a) {
          return a != Lifted_triangulation::kNoSite && Kernel::conflict(v, sites[a]) == Sign::NEGATIVE;
        });
      };
      for (std::size_t r = 0; r < roots.vertices.size(); ++r) {
        const Vertex& v = roots.vertices[r];
        if (skipped >> r & 1 || !wanted(v) || beaten_by_apex(v)) continue;
        if (delaunay ? !tie_set_through_cells<Kernel>(v, q, sites, lifts, tested, covered, cells, tie)
                     : !tie_set_through_edges<Kernel>(v, sites, lifts, tested, tie))
          continue;
        if (tie.size() > 4 && !delaunay) {
          for (Site_index s : tie) degenerate_at[s].push_back(degenerate.size());
          degenerate.push_back({tie, v});
        }
        append_unique<Kernel>(list, first, {tie, v});
      }
    }
  });
  // A vertex of five or more tied sites is found once in each range that meets it: kept once, from its
  // first quadruple (always found: it is the first of its range), whatever the threads. Four sites tie at
  // the roots of their own quadruple only, which append_unique kept apart. Only those positions are sorted:
  // the vertices themselves are large, and the assembly sorts them in place.
  std::vector<std::vector<Found_vertex>> lists;
  for (std::vector<Found_vertex>& list : found) lists.push_back(std::move(list));
  std::vector<Found_vertex> vertices = gathered(lists, cancellation);
  std::vector<std::size_t> degenerate;
  for (std::size_t k = 0; k < vertices.size(); ++k)
    if (vertices[k].tie_set.size() > 4) degenerate.push_back(k);
  const auto first_quadruple = [&](std::size_t x, std::size_t y) {
    if (vertices[x].tie_set != vertices[y].tie_set) return vertices[x].tie_set < vertices[y].tie_set;
    return vertices[x].vertex.quadruple().indices < vertices[y].vertex.quadruple().indices;
  };
  cancellable_sort(degenerate.begin(), degenerate.end(), cancellation, first_quadruple);
  std::vector<bool> repeated(vertices.size(), false);
  for (std::size_t i = 0; i < degenerate.size();) {
    throw_if_cancelled(cancellation);
    std::size_t end = i;
    while (end < degenerate.size() && vertices[degenerate[end]].tie_set == vertices[degenerate[i]].tie_set) ++end;
    for (std::size_t k = i + 1; k < end; ++k)
      for (std::size_t j = i; j < k && !repeated[degenerate[k]]; ++j)
        repeated[degenerate[k]] =
            !repeated[degenerate[j]] &&
            Kernel::compare(vertices[degenerate[j]].vertex, vertices[degenerate[k]].vertex) == Sign::ZERO;
    i = end;
  }
  std::size_t kept = 0;
  for (std::size_t k = 0; k < vertices.size(); ++k)
    if (!repeated[k]) {
      if (kept != k) vertices[kept] = std::move(vertices[k]);
      ++kept;
    }
  vertices.erase(vertices.begin() + static_cast<std::ptrdiff_t>(kept), vertices.end());
  return vertices;
}

template std::vector<Found_vertex> lifted_vertices<Certified_kernel>(const std::vector<Site>&, const Lifted_triangulation&,
                                                                    const std::function<bool(const Vertex&)>&,
                                                                    const Cancellation*);
template std::vector<Found_vertex> lifted_vertices<Floating_kernel>(const std::vector<Site>&, const Lifted_triangulation&,
                                                                   const std::function<bool(const Vertex&)>&,
                                                                   const Cancellation*);

}  // namespace apollonius
