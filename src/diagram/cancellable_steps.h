// The bulk steps between the phases of a large input (sorting, gathering per-task lists), which take up to
// a second each: too long for Ctrl-C unless they check a Cancellation (cancellation.h) as they go. A throw
// leaves the containers valid with unspecified contents (some elements may be moved-from); they are dropped
// with the rest of the cancelled computation. With no Cancellation, these are the plain steps.
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <iterator>
#include <utility>
#include <vector>

#include "diagram/cancellation.h"
#include "diagram/fresh_memory.h"

namespace apollonius {

// The comparison, counted: copies share the count (std::sort copies its comparator down the recursion).
template <class Less>
class Cancellable_less {
 public:
  Cancellable_less(Less less, const Cancellation* cancellation, std::uint64_t* comparisons)
      : less_(std::move(less)), cancellation_(cancellation), comparisons_(comparisons) {}
  template <class X, class Y>
  bool operator()(const X& x, const Y& y) {
    if ((++*comparisons_ & 0xFFFF) == 0) throw_if_cancelled(cancellation_);
    return less_(x, y);
  }

 private:
  Less less_;
  const Cancellation* cancellation_;
  std::uint64_t* comparisons_;
};

// std::sort, checking every 2^16 comparisons.
template <class Iterator, class Less = std::less<>>
void cancellable_sort(Iterator first, Iterator last, const Cancellation* cancellation, Less less = Less()) {
  if (cancellation == nullptr) return std::sort(first, last, less);
  std::uint64_t comparisons = 0;
  std::sort(first, last, Cancellable_less<Less>(std::move(less), cancellation, &comparisons));
  throw_if_cancelled(cancellation);
}

// std::stable_sort, checking every 2^16 comparisons.
template <class Iterator, class Less = std::less<>>
void cancellable_stable_sort(Iterator first, Iterator last, const Cancellation* cancellation, Less less = Less()) {
  if (cancellation == nullptr) return std::stable_sort(first, last, less);
  std::uint64_t comparisons = 0;
  std::stable_sort(first, last, Cancellable_less<Less>(std::move(less), cancellation, &comparisons));
  throw_if_cancelled(cancellation);
}

// Sorts by `less`, which must order first by bucket_of (an integer below bucket_count): the elements are
// moved in place into their buckets (one American-flag pass: each move puts one element in its bucket for
// good), then each bucket is sorted. O(n + bucket_count) plus the buckets' sorts; the occurrence lists of
// the whole diagram, keyed by their smallest site, have buckets of a few dozen elements.
template <class T, class Bucket_of, class Less>
void bucketed_sort(std::vector<T>& items, std::size_t bucket_count, Bucket_of bucket_of, Less less,
                   const Cancellation* cancellation) {
  std::vector<std::size_t> start(bucket_count + 1, 0);
  for (const T& x : items) ++start[bucket_of(x) + 1];
  for (std::size_t b = 0; b < bucket_count; ++b) start[b + 1] += start[b];
  std::vector<std::size_t> next(start.begin(), start.end() - 1);  // the first place of bucket b not yet final
  std::size_t moves = 0;
  for (std::size_t b = 0; b < bucket_count; ++b)
    while (next[b] < start[b + 1]) {
      if (++moves % 4096 == 0) throw_if_cancelled(cancellation);
      const std::size_t c = bucket_of(items[next[b]]);
      if (c == b)
        ++next[b];
      else
        std::swap(items[next[b]], items[next[c]++]);
    }
  for (std::size_t b = 0; b < bucket_count; ++b) {
    if (b % 4096 == 0) throw_if_cancelled(cancellation);
    if (start[b + 1] - start[b] > 1)
      cancellable_sort(items.begin() + static_cast<std::ptrdiff_t>(start[b]),
                       items.begin() + static_cast<std::ptrdiff_t>(start[b + 1]), cancellation, less);
  }
}

// Moves the elements of every list, in order, to the end of `out` (reserved once), freeing each list as it
// goes (freeing millions of small vectors at once takes a while too); checks every 4096 elements.
template <class T>
void move_concatenated(std::vector<std::vector<T>>& lists, std::vector<T>& out, const Cancellation* cancellation) {
  std::size_t total = out.size();
  for (const std::vector<T>& list : lists) total += list.size();
  out.reserve(total);  // exactly: capacity doubling would hold up to twice the elements at the peak
  std::size_t moved = 0;
  for (std::vector<T>& list : lists) {
    for (T& element : list) {
      if (++moved % 4096 == 0) throw_if_cancelled(cancellation);
      out.push_back(std::move(element));
    }
    std::vector<T>().swap(list);
  }
}

// The lists as one: the others moved onto the end of the longest one with room for all, whose elements stay
// where they are (each thread's list, reserved in advance, never moves); else all of them moved into a new one.
template <class T>
std::vector<T> gathered(std::vector<std::vector<T>>& lists, const Cancellation* cancellation) {
  std::size_t total = 0;
  for (const std::vector<T>& list : lists) total += list.size();
  std::vector<T> all;
  auto roomy = lists.end();
  for (auto list = lists.begin(); list != lists.end(); ++list)
    if (list->capacity() >= total && (roomy == lists.end() || list->size() > roomy->size())) roomy = list;
  if (roomy != lists.end()) {
    all = std::move(*roomy);  // leaves *roomy empty
    // The others land on pages never touched: backed in one call, not one fault per page (docs/benchmarks.md,
    // "Lists that never move").
    populate_for_writing(all.data() + all.size(), (total - all.size()) * sizeof(T));
  }
  move_concatenated(lists, all, cancellation);
  return all;
}

}  // namespace apollonius
