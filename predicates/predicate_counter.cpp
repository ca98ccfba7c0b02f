#include "predicates/predicate_counter.h"

#include <algorithm>
#include <mutex>
#include <stdexcept>

namespace apollonius {
namespace {

// Invariant: live holds every thread's counts until the thread ends; finished holds the sums of the
// counts of the threads that ended.
struct Registry {
  std::mutex mutex;
  std::vector<Predicate_counter*> counters;
  std::vector<Thread_predicate_counts*> live;
  std::array<std::uint64_t, kMaxCountedPredicates> finished_evaluations{}, finished_exact_stages{};
};

// Never destroyed: worker threads may end, and hand in their counts, after static destruction began.
Registry& registry() {
  static Registry* const instance = new Registry;
  return *instance;
}

}  // namespace

Thread_predicate_counts::Thread_predicate_counts() {
  Registry& r = registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  r.live.push_back(this);
}

Thread_predicate_counts::~Thread_predicate_counts() {
  Registry& r = registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  for (std::size_t k = 0; k < kMaxCountedPredicates; ++k) {
    r.finished_evaluations[k] += evaluations[k].load(std::memory_order_relaxed);
    r.finished_exact_stages[k] += exact_stages[k].load(std::memory_order_relaxed);
  }
  r.live.erase(std::find(r.live.begin(), r.live.end(), this));
}

Thread_predicate_counts& this_thread_predicate_counts() {
  thread_local Thread_predicate_counts counts;
  return counts;
}

Predicate_counter::Predicate_counter(const char* name) : name_(name) {
  Registry& r = registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  if (r.counters.size() == kMaxCountedPredicates) throw std::length_error("too many counted predicates");
  index_ = r.counters.size();
  r.counters.push_back(this);
}

std::vector<Predicate_statistics> predicate_statistics() {
  Registry& r = registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  std::vector<Predicate_statistics> result;
  for (const Predicate_counter* c : r.counters) {
    Predicate_statistics s{c->name(), r.finished_evaluations[c->index()], r.finished_exact_stages[c->index()]};
    for (const Thread_predicate_counts* t : r.live) {
      s.evaluations += t->evaluations[c->index()].load(std::memory_order_relaxed);
      s.exact_stages += t->exact_stages[c->index()].load(std::memory_order_relaxed);
    }
    result.push_back(s);
  }
  std::sort(result.begin(), result.end(), [](const auto& x, const auto& y) { return x.name < y.name; });
  return result;
}

void reset_predicate_statistics() {
  Registry& r = registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  r.finished_evaluations.fill(0);
  r.finished_exact_stages.fill(0);
  for (Thread_predicate_counts* t : r.live)
    for (std::size_t k = 0; k < kMaxCountedPredicates; ++k) {
      t->evaluations[k].store(0, std::memory_order_relaxed);
      t->exact_stages[k].store(0, std::memory_order_relaxed);
    }
}

}  // namespace apollonius
