// How often each predicate ran and how often its filters failed, for --stats (docs/design.md, "Arithmetic").
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

namespace apollonius {

// Up to this many predicates can be counted.
constexpr std::size_t kMaxCountedPredicates = 32;

// The counts of one thread, written by that thread only (plain loads and stores, no locked operation:
// predicates run millions of times), read when the totals are asked for.
struct Thread_predicate_counts {
  std::array<std::atomic<std::uint64_t>, kMaxCountedPredicates> evaluations{}, exact_stages{};
  Thread_predicate_counts();
  ~Thread_predicate_counts();  // adds its counts to the totals of finished threads
  Thread_predicate_counts(const Thread_predicate_counts&) = delete;
  Thread_predicate_counts& operator=(const Thread_predicate_counts&) = delete;
};

Thread_predicate_counts& this_thread_predicate_counts();

// One counter per predicate, registered at static initialisation.
class Predicate_counter {
 public:
  explicit Predicate_counter(const char* name);
  Predicate_counter(const Predicate_counter&) = delete;
  Predicate_counter& operator=(const Predicate_counter&) = delete;

  void count_evaluation() { increment(this_thread_predicate_counts().evaluations[index_]); }
  void count_exact_stage() { increment(this_thread_predicate_counts().exact_stages[index_]); }

  const char* name() const { return name_; }
  std::size_t index() const { return index_; }

 private:
  static void increment(std::atomic<std::uint64_t>& count) {
    count.store(count.load(std::memory_order_relaxed) + 1, std::memory_order_relaxed);
  }

  const char* name_;
  std::size_t index_;
};

struct Predicate_statistics {
  std::string name;
  std::uint64_t evaluations = 0;
  std::uint64_t exact_stages = 0;
};

// Every registered predicate, sorted by name: the counts of every thread, finished or not. Call it, and
// reset_predicate_statistics, while no predicate runs.
std::vector<Predicate_statistics> predicate_statistics();
void reset_predicate_statistics();

}  // namespace apollonius
