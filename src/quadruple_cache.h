// The vertices of the quadruples met while refining: neighbouring leaves share most of their candidates,
// so most quadruples are met several times, and vertices_of runs once for each. One cache per thread,
// kept across the seed boxes it refines (neighbours in space, mostly), emptied when it grows too large.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "vertices_of.h"

namespace apollonius {

// Invariant: slots_ has a power-of-two size at least twice entries_.size(); a slot holds 0 (empty) or
// 1 + the index of the entry whose key hashes there or, by linear probing, after it.
class Quadruple_cache {
 public:
  // The vertices of the quadruple of `sorted` (ascending site indices).
  const Quadruple_vertices& vertices_of_quadruple(const std::array<Site_index, 4>& sorted, const std::vector<Site>& sites);
  // Empties the cache once it holds more than `entries` quadruples.
  void limit(std::size_t entries);

  std::size_t size() const { return entries_.size(); }
  std::size_t lookups() const { return lookups_; }
  std::size_t misses() const { return misses_; }

 private:
  void grow();
  std::size_t slot_of(const std::array<Site_index, 4>& key) const;

  std::vector<std::uint32_t> slots_ = std::vector<std::uint32_t>(64, 0);
  std::vector<std::pair<std::array<Site_index, 4>, Quadruple_vertices>> entries_;
  std::size_t lookups_ = 0, misses_ = 0;
};

}  // namespace apollonius
