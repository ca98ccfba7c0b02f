// How often each predicate ran and how often its interval filter failed, for --stats (SPEC section 3).
#pragma once

#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

namespace apollonius {

// One counter per predicate, registered at static initialisation; counts are relaxed atomics because
// only their totals are read, after the computation.
class Predicate_counter {
 public:
  explicit Predicate_counter(const char* name);
  Predicate_counter(const Predicate_counter&) = delete;
  Predicate_counter& operator=(const Predicate_counter&) = delete;

  void count_evaluation() { evaluations_.fetch_add(1, std::memory_order_relaxed); }
  void count_exact_stage() { exact_stages_.fetch_add(1, std::memory_order_relaxed); }

  const char* name() const { return name_; }
  std::uint64_t evaluations() const { return evaluations_.load(std::memory_order_relaxed); }
  std::uint64_t exact_stages() const { return exact_stages_.load(std::memory_order_relaxed); }
  void reset();

 private:
  const char* name_;
  std::atomic<std::uint64_t> evaluations_{0};
  std::atomic<std::uint64_t> exact_stages_{0};
};

struct Predicate_statistics {
  std::string name;
  std::uint64_t evaluations = 0;
  std::uint64_t exact_stages = 0;
};

// Every registered predicate, sorted by name.
std::vector<Predicate_statistics> predicate_statistics();
void reset_predicate_statistics();

}  // namespace apollonius
