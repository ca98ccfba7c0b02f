#include "octree/quadruple_cache.h"

#include <algorithm>

#include "predicates/kernels.h"

namespace apollonius {

namespace {

std::uint64_t low_word(const std::array<Site_index, 4>& key) { return key[0] | std::uint64_t{key[1]} << 32; }
std::uint64_t high_word(const std::array<Site_index, 4>& key) { return key[2] | std::uint64_t{key[3]} << 32; }

}  // namespace

template <class Kernel>
std::size_t Quadruple_cache<Kernel>::slot_of(std::uint64_t low, std::uint64_t high) const {
  std::uint64_t h = (low ^ 0x9e3779b97f4a7c15ull) * 0xff51afd7ed558ccdull;
  h = (h ^ high ^ (h >> 29)) * 0xc4ceb9fe1a85ec53ull;
  return static_cast<std::size_t>(h ^ (h >> 32)) & (slots_.size() - 1);
}

template <class Kernel>
const Quadruple_vertices& Quadruple_cache<Kernel>::vertices_of_quadruple(const std::array<Site_index, 4>& sorted,
                                                                 const std::vector<Site>& sites) {
  ++lookups_;
  const std::uint64_t low = low_word(sorted), high = high_word(sorted);
  std::size_t slot = slot_of(low, high);
  for (; slots_[slot].entry != 0; slot = (slot + 1) & (slots_.size() - 1))
    if (slots_[slot].low == low && slots_[slot].high == high) return entries_[slots_[slot].entry - 1];
  ++misses_;
  entries_.push_back(Kernel::vertices_of_quadruple(make_quadruple(sorted, sites)));
  slots_[slot] = {low, high, static_cast<std::uint32_t>(entries_.size())};
  if (2 * entries_.size() > slots_.size()) grow();
  return entries_.back();
}

template <class Kernel>
void Quadruple_cache<Kernel>::grow() {
  std::vector<Slot> old(2 * slots_.size());
  old.swap(slots_);
  for (const Slot& moved : old) {
    if (moved.entry == 0) continue;
    std::size_t slot = slot_of(moved.low, moved.high);
    while (slots_[slot].entry != 0) slot = (slot + 1) & (slots_.size() - 1);
    slots_[slot] = moved;
  }
}

template <class Kernel>
void Quadruple_cache<Kernel>::limit(std::size_t entries) {
  if (entries_.size() <= entries) return;
  std::fill(slots_.begin(), slots_.end(), Slot{});
  entries_.clear();
}

template class Quadruple_cache<Certified_kernel>;
template class Quadruple_cache<Floating_kernel>;

}  // namespace apollonius
