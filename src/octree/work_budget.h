// The work the octree may do before the vertices are taken from the lifted triangulation instead
// (octree_diagram.h, step 5), in one unit per budget: boxes refined (a tie-point leaf that enumerates its
// quadruples one by one spends one box for each), or (seed box, site) pairs the propagation enters. Shared
// by the threads.
#pragma once

#include <atomic>
#include <cstddef>
#include <limits>

namespace apollonius {

// Thrown out of the propagation or the refinement once a budget is spent; nothing found so far is kept.
struct Work_budget_exceeded {};

// Invariant: spent only grows; it counts units in the steps the threads report them.
class Work_budget {
 public:
  explicit Work_budget(std::size_t limit = std::numeric_limits<std::size_t>::max()) : limit_(limit) {}
  // Counts `units` more; throws Work_budget_exceeded once the total passes the limit.
  void spend(std::size_t units) {
    if (spent_.fetch_add(units, std::memory_order_relaxed) + units > limit_) throw Work_budget_exceeded();
  }
  std::size_t spent() const { return spent_.load(std::memory_order_relaxed); }
  bool exceeded() const { return spent() > limit_; }

 private:
  std::size_t limit_;
  std::atomic<std::size_t> spent_{0};
};

}  // namespace apollonius
