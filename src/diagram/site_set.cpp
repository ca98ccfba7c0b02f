#include "diagram/site_set.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "diagram/site_tree.h"
#include "diagram/threads.h"
#include "predicates/kernels.h"
#include "predicates/rounding_guard.h"

namespace apollonius {

namespace {

// The search of the sites that can hide a given one: ball i lies in ball j only if |c_i - c_j| <= w_j - w_i.
// A search skips a node of the tree when intervals show that its largest weight minus w_i is below the
// distance from c_i to its box.
class Hider_tree {
 public:
  explicit Hider_tree(const std::vector<Site>& sites) : sites_(sites), tree_(sites, all_indices(sites.size())) {}

  // Sets `hiders` to every site j != i that can hide site i, and some that cannot; `stack` is scratch.
  void possible_hiders(Site_index i, std::vector<Site_index>& hiders, std::vector<std::size_t>& stack) const {
    hiders.clear();
    const Site& s = sites_[i];
    Rounding_guard guard;
    const auto may_hide = [&](const std::array<double, 3>& lo, const std::array<double, 3>& hi, double w) {
      const Interval weight_gap = Interval(w) - Interval(s.w);
      if (weight_gap.sup() < 0) return false;
      Interval distance_squared(0);  // a lower bound of |c_i - c|^2 over the box
      for (int a = 0; a < 3; ++a) {
        const Interval c(centre_coordinate(s, a));
        const double gap = std::max({0.0, (Interval(lo[a]) - c).inf(), (c - Interval(hi[a])).inf()});
        distance_squared += Interval(gap, gap) * Interval(gap, gap);  // gap may be infinite
      }
      return !(distance_squared.inf() > (weight_gap * weight_gap).sup());
    };
    tree_.search(may_hide,
                 [&](Site_index j) {
                   const std::array<double, 3> c{sites_[j].x, sites_[j].y, sites_[j].z};
                   if (j != i && may_hide(c, c, sites_[j].w)) hiders.push_back(j);
                 },
                 stack);
  }

 private:
  static std::vector<Site_index> all_indices(std::size_t n) {
    std::vector<Site_index> indices(n);
    for (Site_index i = 0; i < n; ++i) indices[i] = i;
    return indices;
  }

  const std::vector<Site>& sites_;
  Site_tree tree_;
};

}  // namespace

// Each site asks the tree for the sites that can hide it and tests them with is_hidden. The cost is
// O(n log n) for the tree, and per site the nodes whose largest weight is not certainly below w_i plus
// their distance: about O(log n + k) for k sites j with w_j >= w_i + |c_i - c_j| when the weights vary
// little over a node, and quadratic only when most sites could hold most others (the sweep in x that this
// replaced was quadratic as soon as the weight range was a good part of the extent).
template <class Kernel>
std::vector<Hidden_site> classify_hidden_sites(const std::vector<Site>& sites, const Cancellation* cancellation,
                                               int threads) {
  const std::size_t n = sites.size();
  std::vector<Hidden_site> hidden;
  if (n < 2) return hidden;
  const Hider_tree tree(sites);
  // Each site's verdict depends on it alone: chunks of sites in parallel, each verdict in its own slot.
  std::vector<std::optional<Hidden_site>> verdict(n);
  const auto classify = [&](std::size_t first, std::size_t last) {
    std::vector<Site_index> hiders;
    std::vector<std::size_t> stack;
    for (std::size_t k = first; k < last; ++k) {
      if ((k & 1023) == 0) throw_if_cancelled(cancellation);
      const auto i = static_cast<Site_index>(k);
      tree.possible_hiders(i, hiders, stack);
      std::optional<Hidden_site>& found = verdict[i];
      for (Site_index j : hiders) {
        if (!Kernel::hidden(sites[i], i, sites[j], j)) continue;
        const bool duplicate = sites[i] == sites[j];
        // Prefer a duplicate over a containing ball, then the smallest index.
        if (!found || (duplicate && !found->duplicate) || (duplicate == found->duplicate && j < found->hidden_by))
          found = Hidden_site{i, j, duplicate};
      }
    }
  };
  threads = usable_threads(threads);
  if (threads == 1) {
    classify(0, n);
  } else {
    tbb::task_arena arena(threads);
    arena.execute([&] {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1024),
                        [&](const tbb::blocked_range<std::size_t>& range) { classify(range.begin(), range.end()); });
    });
  }
  for (const std::optional<Hidden_site>& found : verdict)
    if (found) hidden.push_back(*found);
  return hidden;
}

template std::vector<Hidden_site> classify_hidden_sites<Certified_kernel>(const std::vector<Site>&, const Cancellation*, int);
template std::vector<Hidden_site> classify_hidden_sites<Floating_kernel>(const std::vector<Site>&, const Cancellation*, int);

std::vector<Site_index> active_sites(std::size_t site_count, const std::vector<Hidden_site>& hidden) {
  std::vector<bool> is_hidden_site(site_count, false);
  for (const Hidden_site& h : hidden) is_hidden_site[h.site] = true;
  std::vector<Site_index> active;
  for (Site_index i = 0; i < site_count; ++i)
    if (!is_hidden_site[i]) active.push_back(i);
  return active;
}

}  // namespace apollonius
