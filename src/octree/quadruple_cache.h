// The vertices of the quadruples met while refining: neighbouring leaves share most of their candidates,
// so most quadruples are met several times, and vertices_of runs once for each. One cache per thread,
// kept across the seed boxes it refines (neighbours in space, mostly), emptied when it grows too large.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "predicates/vertices_of.h"

namespace apollonius {

// Invariant: slots_ has a power-of-two size at least twice entries_.size(); a slot is empty (entry 0) or
// holds the key and 1 + the index of an entry whose key hashes there or, by linear probing, after it.
// Kernel: kernels.h.
template <class Kernel>
class Quadruple_cache {
 public:
  // The vertices of the quadruple of `sorted` (ascending site indices).
  const Quadruple_vertices& vertices_of_quadruple(const std::array<Site_index, 4>& sorted, const std::vector<Site>& sites);
  // Empties the cache once it holds more than `entries` quadruples.
  void limit(std::size_t entries);

  std::size_t lookups() const { return lookups_; }
  std::size_t misses() const { return misses_; }

 private:
  // The key in two words, compared without touching the entries.
  struct Slot {
    std::uint64_t low = 0, high = 0;
    std::uint32_t entry = 0;
  };

  void grow();
  std::size_t slot_of(std::uint64_t low, std::uint64_t high) const;

  std::vector<Slot> slots_ = std::vector<Slot>(64);
  std::vector<Quadruple_vertices> entries_;  // in insertion order; their keys are in the slots
  std::size_t lookups_ = 0, misses_ = 0;
};

}  // namespace apollonius
