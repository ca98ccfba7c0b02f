#include "topology/region_site_sets.h"

#include <algorithm>
#include <limits>

namespace apollonius {
namespace {

std::uint64_t hash_of(const Octree_regions::Sites& sites) {
  std::uint64_t h = 0x9e3779b97f4a7c15ULL ^ sites.size();
  for (Site_index s : sites) {  // splitmix64's finaliser on each step
    h += 0x9e3779b97f4a7c15ULL + s;
    h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ULL;
    h = (h ^ (h >> 27)) * 0x94d049bb133111ebULL;
    h ^= h >> 31;
  }
  return h;
}

}  // namespace

Region_site_sets::Region_site_sets(const Octree_regions& regions, const Cancellation* cancellation)
    : regions_(regions) {
  constexpr std::uint32_t kEmpty = std::numeric_limits<std::uint32_t>::max();
  const std::vector<Octree_regions::Box>& boxes = regions.boxes;
  // Open addressing with linear probing, at most half full: each slot holds a set's number.
  std::vector<std::uint32_t> slots(64, kEmpty);
  std::vector<std::uint64_t> hashes;  // per set
  const auto insert = [&](std::uint32_t set, std::uint64_t h) {
    std::size_t i = h & (slots.size() - 1);
    while (slots[i] != kEmpty) i = (i + 1) & (slots.size() - 1);
    slots[i] = set;
  };
  std::vector<std::uint32_t> set_of_box(boxes.size());
  for (std::size_t b = 0; b < boxes.size(); ++b) {
    if (b % 4096 == 0) throw_if_cancelled(cancellation);
    const Octree_regions::Sites& sites = boxes[b].sites;
    const std::uint64_t h = hash_of(sites);
    std::size_t i = h & (slots.size() - 1);
    for (; slots[i] != kEmpty; i = (i + 1) & (slots.size() - 1))
      if (hashes[slots[i]] == h && regions.boxes[first_box_[slots[i]]].sites == sites) break;
    if (slots[i] != kEmpty) {
      set_of_box[b] = slots[i];
      continue;
    }
    const auto set = static_cast<std::uint32_t>(first_box_.size());
    first_box_.push_back(static_cast<std::uint32_t>(b));
    hashes.push_back(h);
    slots[i] = set;
    set_of_box[b] = set;
    if (2 * first_box_.size() > slots.size()) {
      slots.assign(2 * slots.size(), kEmpty);
      for (std::uint32_t s = 0; s < first_box_.size(); ++s) insert(s, hashes[s]);
    }
  }
  boxes_ = Flat_lists<std::uint32_t>(
      first_box_.size(),
      [&](auto emit) {
        for (std::size_t b = 0; b < boxes.size(); ++b) emit(set_of_box[b], static_cast<std::uint32_t>(b));
      },
      cancellation);
}

}  // namespace apollonius
