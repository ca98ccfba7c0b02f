#include "quadruple_cache.h"

#include <algorithm>

namespace apollonius {

std::size_t Quadruple_cache::slot_of(const std::array<Site_index, 4>& key) const {
  std::uint64_t h = 0x9e3779b97f4a7c15ull;
  for (Site_index s : key) h = (h ^ s) * 0xff51afd7ed558ccdull;
  return static_cast<std::size_t>(h ^ (h >> 29)) & (slots_.size() - 1);
}

const Quadruple_vertices& Quadruple_cache::vertices_of_quadruple(const std::array<Site_index, 4>& sorted,
                                                                 const std::vector<Site>& sites) {
  ++lookups_;
  std::size_t slot = slot_of(sorted);
  for (; slots_[slot] != 0; slot = (slot + 1) & (slots_.size() - 1))
    if (entries_[slots_[slot] - 1].first == sorted) return entries_[slots_[slot] - 1].second;
  ++misses_;
  entries_.emplace_back(sorted, vertices_of(make_quadruple(sorted, sites)));
  slots_[slot] = static_cast<std::uint32_t>(entries_.size());
  if (2 * entries_.size() > slots_.size()) grow();
  return entries_.back().second;
}

void Quadruple_cache::grow() {
  std::fill(slots_.begin(), slots_.end(), 0);
  slots_.resize(2 * slots_.size(), 0);
  for (std::size_t e = 0; e < entries_.size(); ++e) {
    std::size_t slot = slot_of(entries_[e].first);
    while (slots_[slot] != 0) slot = (slot + 1) & (slots_.size() - 1);
    slots_[slot] = static_cast<std::uint32_t>(e + 1);
  }
}

void Quadruple_cache::limit(std::size_t entries) {
  if (entries_.size() <= entries) return;
  std::fill(slots_.begin(), slots_.end(), 0);
  entries_.clear();
}

}  // namespace apollonius
