// A kd-tree of site centres whose nodes keep their largest weight, so that a search can bound the weighted
// distance d_s(x) = |x - c_s| - w_s over a whole node: d_s(x) >= |x - node box| - heaviest. Two searches use
// it: the sites that can hide a site (site_set.cpp, with certified bounds) and the sites nearest a point
// (the octree's witnesses, in floating point).
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "predicates/site.h"

namespace apollonius {

class Site_tree {
 public:
  // Invariant: the node's sites are order()[begin, end); a node with right != 0 has the children
  // nodes()[k + 1] and nodes()[right], splitting that range at its median on the longest axis of the box;
  // lo and hi bound its centres exactly, and heaviest is its largest weight.
  struct Node {
    std::size_t begin, end;
    std::size_t right = 0;  // 0: a leaf
    std::array<double, 3> lo, hi;
    double heaviest;
  };

  // The tree of sites[subset]. Cost O(n log n) for n sites; depth O(log n).
  Site_tree(const std::vector<Site>& sites, std::vector<Site_index> subset);

  const std::vector<Node>& nodes() const { return nodes_; }
  const std::vector<Site_index>& order() const { return order_; }

  // Writes to out up to k (at most kMostNearest) sites of least d at x, ascending by d, then by index, and
  // returns how many: fewer only if the tree holds fewer. Floating point, for choosing among sites where the
  // choice matters for speed only: a site whose d rounds to NaN counts as infinitely far.
  static constexpr std::size_t kMostNearest = 8;
  std::size_t nearest(const std::array<double, 3>& x, std::size_t k, Site_index* out) const;

  // Calls leaf_site(s) for each site s of the leaves reached through nodes that all pass
  // may_hold(lo, hi, heaviest), depth first: for the searches whose certified bound excludes whole nodes.
  // `stack` is scratch. Cost: the nodes tested, at most twice the sites over kLeafSize.
  template <class May_hold, class Leaf_site>
  void search(May_hold may_hold, Leaf_site leaf_site, std::vector<std::size_t>& stack) const {
    if (nodes_.empty()) return;
    stack.assign(1, 0);
    while (!stack.empty()) {
      const std::size_t k = stack.back();
      stack.pop_back();
      const Node& node = nodes_[k];
      if (!may_hold(node.lo, node.hi, node.heaviest)) continue;
      if (node.right == 0) {
        for (std::size_t m = node.begin; m < node.end; ++m) leaf_site(order_[m]);
      } else {
        stack.push_back(node.right);
        stack.push_back(k + 1);
      }
    }
  }

 private:
  static constexpr std::size_t kLeafSize = 8;
  void build(std::size_t begin, std::size_t end);

  const std::vector<Site>& sites_;
  std::vector<Site_index> order_;
  std::vector<Node> nodes_;
};

}  // namespace apollonius
