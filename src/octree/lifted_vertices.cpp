#include "octree/lifted_vertices.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <stdexcept>
#include <type_traits>
#include <unordered_map>

#include "diagram/cancellable_steps.h"
#include "predicates/kernels.h"

namespace apollonius {
namespace {

// Sites tested for one vertex, by position in the lifted triangulation's sites; cleared in O(tested).
class Tested_sites {
 public:
  explicit Tested_sites(std::size_t sites) : tested_(sites, false) {}
  bool first_test(std::size_t position) {
    if (tested_[position]) return false;
    tested_[position] = true;
    touched_.push_back(position);
    return true;
  }
  void clear() {
    for (std::size_t p : touched_) tested_[p] = false;
    touched_.clear();
  }

 private:
  std::vector<bool> tested_;
  std::vector<std::size_t> touched_;
};

// The tie set of v, a root of a 3-face, or false if some site is strictly closer (lifted_vertices.h): its
// lift lies in the power cell of v's first site iff no neighbour of that site and no unplaced site beats
// it; the later passes only find ties. Cost: O((|tie set| + 1) degree + unplaced) conflict tests.
template <class Kernel>
bool tie_set_through_edges(const Vertex& v, const std::vector<Site>& sites, const Lifted_triangulation& lifts,
                           Tested_sites& tested, std::vector<Site_index>& tie) {
  const auto& own = v.sites();
  tie.assign(own.begin(), own.end());
  tested.clear();
  for (Site_index s : own) tested.first_test(lifts.position_of(s));
  const auto beats = [&](Site_index s) {
    if (!tested.first_test(lifts.position_of(s))) return false;
    const Sign sign = Kernel::conflict(v, sites[s]);
    if (sign == Sign::ZERO) tie.push_back(s);
    return sign == Sign::NEGATIVE;
  };
  for (Site_index s : lifts.unplaced)
    if (beats(s)) return false;
  // A site beating v after the first site's neighbours accepted it contradicts the power cell, which the
  // exact predicates cannot; the floating path's rounding can, and rejects v.
  for (std::size_t k = 0; k < tie.size(); ++k)
    for (Site_index s : lifts.neighbours_of(tie[k]))
      if (beats(s)) {
        if (k != 0 && std::is_same_v<Kernel, Certified_kernel>)
          throw std::logic_error("lifted vertices: a site beats a vertex that its first site's neighbours accept");
        return false;
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
  std::vector<std::vector<Found_vertex>> found(quadruples.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, quadruples.size()), [&](const tbb::blocked_range<std::size_t>& range) {
    Tested_sites tested(lifts.sites.size());
    std::vector<Site_index> tie;
    // The vertices of more than four tied sites found in this range, and for each site the ones it ties
    // at: a quadruple's first site names every such vertex that can be its root.
    std::vector<Found_vertex> degenerate;
    std::unordered_map<Site_index, std::vector<std::size_t>> degenerate_at;
    for (std::size_t q = range.begin(); q != range.end(); ++q) {
      throw_if_cancelled(cancellation);
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
        if (skipped >> r & 1 || !wanted(v) || beaten_by_apex(v) ||
            !tie_set_through_edges<Kernel>(v, sites, lifts, tested, tie))
          continue;
        if (tie.size() > 4) {
          for (Site_index s : tie) degenerate_at[s].push_back(degenerate.size());
          degenerate.push_back({tie, v});
        }
        append_unique<Kernel>(found[q], 0, {tie, v});
      }
    }
  });
  // A vertex of five or more tied sites is found once in each range that meets it: kept once.
  std::vector<Found_vertex> vertices;
  move_concatenated(found, vertices, cancellation);
  cancellable_stable_sort(vertices.begin(), vertices.end(), cancellation,
                          [](const Found_vertex& x, const Found_vertex& y) { return x.tie_set < y.tie_set; });
  std::vector<Found_vertex> unique;
  for (std::size_t i = 0; i < vertices.size();) {
    std::size_t end = i;
    while (end < vertices.size() && vertices[end].tie_set == vertices[i].tie_set) ++end;
    const std::size_t group = unique.size();
    for (std::size_t k = i; k < end; ++k) append_unique<Kernel>(unique, group, std::move(vertices[k]));
    i = end;
  }
  return unique;
}

template std::vector<Found_vertex> lifted_vertices<Certified_kernel>(const std::vector<Site>&, const Lifted_triangulation&,
                                                                    const std::function<bool(const Vertex&)>&,
                                                                    const Cancellation*);
template std::vector<Found_vertex> lifted_vertices<Floating_kernel>(const std::vector<Site>&, const Lifted_triangulation&,
                                                                   const std::function<bool(const Vertex&)>&,
                                                                   const Cancellation*);

}  // namespace apollonius
