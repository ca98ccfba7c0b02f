#include "predicate_counter.h"

#include <algorithm>
#include <mutex>

namespace apollonius {
namespace {

struct Registry {
  std::mutex mutex;
  std::vector<Predicate_counter*> counters;
};

Registry& registry() {
  static Registry instance;
  return instance;
}

}  // namespace

Predicate_counter::Predicate_counter(const char* name) : name_(name) {
  Registry& r = registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  r.counters.push_back(this);
}

void Predicate_counter::reset() {
  evaluations_.store(0, std::memory_order_relaxed);
  exact_stages_.store(0, std::memory_order_relaxed);
}

std::vector<Predicate_statistics> predicate_statistics() {
  Registry& r = registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  std::vector<Predicate_statistics> result;
  for (const Predicate_counter* c : r.counters) result.push_back({c->name(), c->evaluations(), c->exact_stages()});
  std::sort(result.begin(), result.end(), [](const auto& x, const auto& y) { return x.name < y.name; });
  return result;
}

void reset_predicate_statistics() {
  Registry& r = registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  for (Predicate_counter* c : r.counters) c->reset();
}

}  // namespace apollonius
