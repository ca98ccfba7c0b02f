#include "diagram/site_set.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "diagram/threads.h"
#include "predicates/kernels.h"
#include "predicates/rounding_guard.h"

namespace apollonius {

namespace {

// A kd-tree of the centres for the search of the sites that can hide a given one: ball i lies in ball j
// only if |c_i - c_j| <= w_j - w_i. Each node keeps the exact bounding box of its centres and its largest
// weight, and a search skips a node when intervals show that this largest weight minus w_i is below the
// distance from c_i to the box. Invariant: nodes_[k]'s sites are order_[begin, end), its children (if any)
// are nodes_[k + 1] and nodes_[right], splitting that range at its median on the box's longest axis.
class Hider_tree {
 public:
  explicit Hider_tree(const std::vector<Site>& sites) : sites_(sites), order_(sites.size()) {
    for (Site_index i = 0; i < sites.size(); ++i) order_[i] = i;
    nodes_.reserve(2 * sites.size() / kLeafSize + 1);
    build(0, sites.size());
  }

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
        const Interval c(coordinate(s, a));
        const double gap = std::max({0.0, (Interval(lo[a]) - c).inf(), (c - Interval(hi[a])).inf()});
        distance_squared += Interval(gap, gap) * Interval(gap, gap);  // gap may be infinite
      }
      return !(distance_squared.inf() > (weight_gap * weight_gap).sup());
    };
    stack.assign(1, 0);
    while (!stack.empty()) {
      const std::size_t k = stack.back();
      stack.pop_back();
      const Node& node = nodes_[k];
      if (!may_hide(node.lo, node.hi, node.heaviest)) continue;
      if (node.right == 0) {
        for (std::size_t m = node.begin; m < node.end; ++m) {
          const Site_index j = order_[m];
          const std::array<double, 3> c{sites_[j].x, sites_[j].y, sites_[j].z};
          if (j != i && may_hide(c, c, sites_[j].w)) hiders.push_back(j);
        }
      } else {
        stack.push_back(node.right);
        stack.push_back(k + 1);
      }
    }
  }

 private:
  static constexpr std::size_t kLeafSize = 8;

  struct Node {
    std::size_t begin, end;
    std::size_t right = 0;  // 0: a leaf
    std::array<double, 3> lo, hi;
    double heaviest;
  };

  static double coordinate(const Site& s, int axis) { return axis == 0 ? s.x : axis == 1 ? s.y : s.z; }

  // Depth O(log n): every split halves the range.
  void build(std::size_t begin, std::size_t end) {
    const std::size_t k = nodes_.size();
    nodes_.push_back(Node{begin, end, 0, {}, {}, -std::numeric_limits<double>::infinity()});
    Node node = nodes_[k];
    node.lo.fill(std::numeric_limits<double>::infinity());
    node.hi.fill(-std::numeric_limits<double>::infinity());
    for (std::size_t m = begin; m < end; ++m) {
      const Site& s = sites_[order_[m]];
      for (int a = 0; a < 3; ++a) node.lo[a] = std::min(node.lo[a], coordinate(s, a)), node.hi[a] = std::max(node.hi[a], coordinate(s, a));
      node.heaviest = std::max(node.heaviest, s.w);
    }
    if (end - begin > kLeafSize) {
      int axis = 0;  // the longest, compared by halves so that it stays finite
      for (int a = 1; a < 3; ++a)
        if (node.hi[a] / 2 - node.lo[a] / 2 > node.hi[axis] / 2 - node.lo[axis] / 2) axis = a;
      const std::size_t middle = begin + (end - begin) / 2;
      std::nth_element(order_.begin() + begin, order_.begin() + middle, order_.begin() + end, [&](Site_index a, Site_index b) {
        return coordinate(sites_[a], axis) < coordinate(sites_[b], axis) || (coordinate(sites_[a], axis) == coordinate(sites_[b], axis) && a < b);
      });
      build(begin, middle);
      node.right = nodes_.size();
      build(middle, end);
    }
    nodes_[k] = node;
  }

  const std::vector<Site>& sites_;
  std::vector<Site_index> order_;
  std::vector<Node> nodes_;
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
