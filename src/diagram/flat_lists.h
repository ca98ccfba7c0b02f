// Values grouped by key in one flat array (compressed rows), built in two passes over the same items: a
// count, then a placement. No list per key (a vector per key grows by doubling) and no list of (key,
// value) pairs sorted by key (twice the memory, touched again by the sort): the whole diagram's
// bookkeeping by vertex and by site, where fresh memory is most of the cost.
#pragma once

#include <cstddef>
#include <vector>

#include "diagram/cancellation.h"

namespace apollonius {

// Invariant: first_ is non-decreasing, first_.front() == 0 and first_.back() == values_.size(); key k's
// values are values_[first_[k], first_[k + 1]), in the order they were emitted.
template <class T>
class Flat_lists {
 public:
  template <class Pointer>
  struct Range {
    Pointer first, last;
    Pointer begin() const { return first; }
    Pointer end() const { return last; }
    std::size_t size() const { return static_cast<std::size_t>(last - first); }
  };

  // emit_all(emit) calls emit(key, value) for every value, with key < key_count, the same way each time
  // it is called (twice). Checks cancellation every 4096 values of each pass.
  Flat_lists() : first_(1, 0) {}  // no key
  template <class Emit_all>
  Flat_lists(std::size_t key_count, Emit_all emit_all, const Cancellation* cancellation = nullptr)
      : first_(key_count + 1, 0) {
    std::size_t emitted = 0;
    const auto check = [&] {
      if (++emitted % 4096 == 0) throw_if_cancelled(cancellation);
    };
    emit_all([&](std::size_t key, const T&) { check(), ++first_[key + 1]; });
    for (std::size_t k = 0; k < key_count; ++k) first_[k + 1] += first_[k];
    values_.resize(first_.back());
    std::vector<std::size_t> next(first_.begin(), first_.end() - 1);
    emit_all([&](std::size_t key, const T& value) { check(), values_[next[key]++] = value; });
  }

  std::size_t key_count() const { return first_.size() - 1; }
  Range<const T*> operator[](std::size_t key) const { return {values_.data() + first_[key], values_.data() + first_[key + 1]}; }
  Range<T*> operator[](std::size_t key) { return {values_.data() + first_[key], values_.data() + first_[key + 1]}; }
  // Every value, key by key.
  const std::vector<T>& values() const { return values_; }

 private:
  std::vector<std::size_t> first_;
  std::vector<T> values_;
};

}  // namespace apollonius
