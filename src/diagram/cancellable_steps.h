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

}  // namespace apollonius
