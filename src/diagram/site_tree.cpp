#include "diagram/site_tree.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace apollonius {

namespace {

// |x_a - y_a| as the larger minus the smaller, so that the two formulas below round alike in any mode.
double separation(double x, double y) { return x < y ? y - x : x - y; }

// d at x as the searches compute it (a NaN is infinitely far).
double floating_distance(const std::array<double, 3>& x, const Site& s) {
  const double dx = separation(x[0], s.x), dy = separation(x[1], s.y), dz = separation(x[2], s.z);
  const double d = std::sqrt(dx * dx + dy * dy + dz * dz) - s.w;
  return std::isnan(d) ? std::numeric_limits<double>::infinity() : d;
}

// The same formula on the gaps to the node's box and its largest weight. Each operation rounds monotonically
// (in any rounding mode), and each gap is at most the site's separation on its axis, so this is at most
// floating_distance of each site of the node.
double floating_bound(const std::array<double, 3>& x, const Site_tree::Node& node) {
  std::array<double, 3> gap;
  for (int a = 0; a < 3; ++a)
    gap[a] = x[a] < node.lo[a] ? separation(x[a], node.lo[a]) : x[a] > node.hi[a] ? separation(x[a], node.hi[a]) : 0;
  const double bound = std::sqrt(gap[0] * gap[0] + gap[1] * gap[1] + gap[2] * gap[2]) - node.heaviest;
  return std::isnan(bound) ? -std::numeric_limits<double>::infinity() : bound;
}

}  // namespace

Site_tree::Site_tree(const std::vector<Site>& sites, std::vector<Site_index> subset)
    : sites_(sites), order_(std::move(subset)) {
  if (order_.empty()) return;
  nodes_.reserve(2 * order_.size() / kLeafSize + 1);
  build(0, order_.size());
}

void Site_tree::build(std::size_t begin, std::size_t end) {
  const std::size_t k = nodes_.size();
  nodes_.push_back(Node{begin, end, 0, {}, {}, -std::numeric_limits<double>::infinity()});
  Node node = nodes_[k];
  node.lo.fill(std::numeric_limits<double>::infinity());
  node.hi.fill(-std::numeric_limits<double>::infinity());
  for (std::size_t m = begin; m < end; ++m) {
    const Site& s = sites_[order_[m]];
    for (int a = 0; a < 3; ++a) {
      node.lo[a] = std::min(node.lo[a], centre_coordinate(s, a));
      node.hi[a] = std::max(node.hi[a], centre_coordinate(s, a));
    }
    node.heaviest = std::max(node.heaviest, s.w);
  }
  if (end - begin > kLeafSize) {
    int axis = 0;  // the longest, compared by halves so that it stays finite
    for (int a = 1; a < 3; ++a)
      if (node.hi[a] / 2 - node.lo[a] / 2 > node.hi[axis] / 2 - node.lo[axis] / 2) axis = a;
    const std::size_t middle = begin + (end - begin) / 2;
    std::nth_element(order_.begin() + static_cast<std::ptrdiff_t>(begin), order_.begin() + static_cast<std::ptrdiff_t>(middle),
                     order_.begin() + static_cast<std::ptrdiff_t>(end), [&](Site_index a, Site_index b) {
                       const double ca = centre_coordinate(sites_[a], axis), cb = centre_coordinate(sites_[b], axis);
                       return ca < cb || (ca == cb && a < b);
                     });
    build(begin, middle);
    node.right = nodes_.size();
    build(middle, end);
  }
  nodes_[k] = node;
}

// Depth first, the nearer child first, skipping a node whose bound exceeds the k-th key found: by the
// bound's monotonicity, no site in it could enter. The stack holds at most one node per level plus one.
std::size_t Site_tree::nearest(const std::array<double, 3>& x, std::size_t k, Site_index* out) const {
  k = std::min(k, kMostNearest);
  if (k == 0 || nodes_.empty()) return 0;
  std::array<double, kMostNearest> key;  // key[i] is d of out[i]; ascending by (key, site)
  std::size_t count = 0;
  const auto before = [&](double d, Site_index s, std::size_t at) { return d < key[at] || (d == key[at] && s < out[at]); };
  const auto offer = [&](Site_index s) {
    const double d = floating_distance(x, sites_[s]);
    if (count == k && !before(d, s, k - 1)) return;
    std::size_t at = std::min(count, k - 1);
    for (; at > 0 && before(d, s, at - 1); --at) key[at] = key[at - 1], out[at] = out[at - 1];
    key[at] = d, out[at] = s, count = std::min(count + 1, k);
  };
  std::array<std::pair<std::size_t, double>, 2 * 64> stack;  // depth <= log2(n) + 1 < 64
  std::size_t size = 0;
  stack[size++] = {0, floating_bound(x, nodes_[0])};
  while (size > 0) {
    const auto [n, bound] = stack[--size];
    if (count == k && bound > key[k - 1]) continue;
    const Node& node = nodes_[n];
    if (node.right == 0) {
      for (std::size_t m = node.begin; m < node.end; ++m) offer(order_[m]);
      continue;
    }
    std::pair<std::size_t, double> near{n + 1, floating_bound(x, nodes_[n + 1])};
    std::pair<std::size_t, double> far{node.right, floating_bound(x, nodes_[node.right])};
    if (far.second < near.second) std::swap(near, far);
    stack[size++] = far;
    stack[size++] = near;
  }
  return count;
}

}  // namespace apollonius
