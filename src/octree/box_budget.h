// The boxes the octree may refine before the vertices are taken from the lifted triangulation instead
// (octree_diagram.h, step 5). Shared by the refining threads. A tie-point leaf that enumerates its
// quadruples one by one spends one box for each.
#pragma once

#include <atomic>
#include <cstddef>
#include <limits>

namespace apollonius {

// Thrown out of the refinement once the budget is spent; nothing refined so far is kept.
struct Box_budget_exceeded {};

// Invariant: spent only grows; it counts boxes in the steps the threads report them.
class Box_budget {
 public:
  explicit Box_budget(std::size_t limit = std::numeric_limits<std::size_t>::max()) : limit_(limit) {}
  // Counts `boxes` more; throws Box_budget_exceeded once the total passes the limit.
  void spend(std::size_t boxes) {
    if (spent_.fetch_add(boxes, std::memory_order_relaxed) + boxes > limit_) throw Box_budget_exceeded();
  }
  std::size_t spent() const { return spent_.load(std::memory_order_relaxed); }

 private:
  std::size_t limit_;
  std::atomic<std::size_t> spent_{0};
};

}  // namespace apollonius
