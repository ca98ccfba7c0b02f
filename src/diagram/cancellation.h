// A request from another thread to stop a long computation, and the exception that stops it. The Python
// module requests it on Ctrl-C. The algorithms check it between units of work (the vertices: a step of the
// hidden-site sweep, 4096 boxes or events of the distance propagation, a site's flood, a seed box, a
// far-field patch or quadruple, a thousand boxes refined, 1024 vertex roundings; the topology: a vertex's
// departures, a curve's edges, a box's candidates, a vertex-free candidate, an edge's half-edges, a vertex's
// sectors, a pair's nesting, a level line, 4096 items validated; the centroidal loop: an iteration, a
// cell's measure; the sorts and gathers between phases: cancellable_steps.h), each a small fraction of a
// second on the benchmark inputs (docs/design.md), and then throw Cancelled: nothing computed so far is
// returned, and no state outlives the call. With no Cancellation given, nothing is checked.
#pragma once

#include <atomic>
#include <stdexcept>

namespace apollonius {

// Invariant: once requested, stays requested.
class Cancellation {
 public:
  void request() { requested_.store(true, std::memory_order_relaxed); }
  bool requested() const { return requested_.load(std::memory_order_relaxed); }

 private:
  std::atomic<bool> requested_{false};
};

struct Cancelled : std::runtime_error {
  Cancelled() : std::runtime_error("computation cancelled") {}
};

// Throws Cancelled if cancellation is given and was requested.
inline void throw_if_cancelled(const Cancellation* cancellation) {
  if (cancellation != nullptr && cancellation->requested()) throw Cancelled();
}

}  // namespace apollonius
