// Quadruple_cache (octree/quadruple_cache.h) against vertices_of (predicates/vertices_of.h): the same
// vertices for every quadruple asked, asked in random order and again and again, while the table grows and
// while limit() empties it, for keys that share a home slot of the hash and for site indices far from 0.
// A model of what the cache holds predicts every hit and miss.
//
// Site indices reach only about 2^20 here, not 2^32: the cache reads the sites of a key through
// make_quadruple, which indexes the vector of sites, and a vector of 2^32 sites would take 128 GiB.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "octree/quadruple_cache.h"
#include "predicates/kernels.h"
#include "reference/site_generators.h"

using namespace apollonius;

namespace {

using Key = std::array<Site_index, 4>;

// The sites: small sets of several families (general, cospherical, coplanar, duplicated, tangent) at the
// low indices [0, kBlock) and again at the top [kSiteCount - kBlock, kSiteCount); zero sites between.
constexpr Site_index kBlock = 40;
constexpr Site_index kSiteCount = (Site_index{1} << 20) + 7;

std::vector<Site> make_sites() {
  std::vector<Site> sites(kSiteCount, Site{0, 0, 0, 0});
  std::vector<Site> block;
  for (Site_family family : {Site_family::uniform, Site_family::lattice, Site_family::coplanar,
                             Site_family::duplicates, Site_family::tangent}) {
    const std::vector<Site> some = generate_sites(family, kBlock / 5, 7);
    block.insert(block.end(), some.begin(), some.end());
  }
  REQUIRE(block.size() == kBlock);
  for (Site_index i = 0; i < kBlock; ++i) {
    sites[i] = block[i];
    sites[kSiteCount - kBlock + i] = block[(i * 7) % kBlock];  // the same sites in another order
  }
  return sites;
}

// The site indices that keys are made of: both blocks.
std::vector<Site_index> used_indices() {
  std::vector<Site_index> used;
  for (Site_index i = 0; i < kBlock; ++i) used.push_back(i);
  for (Site_index i = kSiteCount - kBlock; i < kSiteCount; ++i) used.push_back(i);
  return used;
}

Key random_key(std::mt19937_64& random, const std::vector<Site_index>& used) {
  for (;;) {
    Key key;
    for (Site_index& k : key) k = used[random() % used.size()];
    std::sort(key.begin(), key.end());
    if (std::adjacent_find(key.begin(), key.end()) == key.end()) return key;
  }
}

// A copy of the mixing in Quadruple_cache::slot_of, used only to pick keys that share a home slot; if the
// cache's hash changes, these keys still test it, they only collide less.
std::uint64_t hash_copy(const Key& key) {
  const std::uint64_t low = key[0] | std::uint64_t{key[1]} << 32, high = key[2] | std::uint64_t{key[3]} << 32;
  std::uint64_t h = (low ^ 0x9e3779b97f4a7c15ull) * 0xff51afd7ed558ccdull;
  h = (h ^ high ^ (h >> 29)) * 0xc4ceb9fe1a85ec53ull;
  return h ^ (h >> 32);
}

template <class Kernel>
Quadruple_vertices reference_vertices(const Key& key, const std::vector<Site>& sites) {
  return Kernel::vertices_of_quadruple(make_quadruple(key, sites));
}

// The cached answer is the reference one: the same flags, and the same vertices in the same order (same
// quadruple, sites, root and enclosure; with `exactly`, also the same point by the kernel's compare).
template <class Kernel>
void check_same(const Quadruple_vertices& got, const Quadruple_vertices& expected, const std::vector<Site>& sites,
                bool exactly) {
  CHECK(got.rank_deficient == expected.rank_deficient);
  CHECK(got.equidistant_curve == expected.equidistant_curve);
  REQUIRE(got.vertices.size() == expected.vertices.size());
  for (std::size_t k = 0; k < got.vertices.size(); ++k) {
    const Vertex& u = got.vertices[k];
    const Vertex& v = expected.vertices[k];
    CHECK(u.sites() == v.sites());
    for (int m = 0; m < 4; ++m) CHECK(u.quadruple().sites[m] == sites[v.sites()[m]]);
    CHECK(u.root() == v.root());
    const auto& bu = u.coordinates<Interval>().scaled;
    const auto& bv = v.coordinates<Interval>().scaled;
    for (int j = 0; j < 4; ++j) CHECK((bu[j].inf() == bv[j].inf() && bu[j].sup() == bv[j].sup()));
    if (exactly) CHECK(Kernel::compare(u, v) == Sign::ZERO);
  }
}

struct Run_counts {
  std::size_t asks = 0, misses = 0, emptied = 0, vertices = 0, rank_deficient = 0, high_keys = 0;
};

// Asks `sequence` in order; before ask k, limit(limits[k]) when limits has an entry for k. A model of the
// cache's contents (every key asked since it was last emptied) predicts each miss.
template <class Kernel>
void run(Quadruple_cache<Kernel>& cache, const std::vector<Key>& sequence,
         const std::map<std::size_t, std::size_t>& limits, const std::vector<Site>& sites,
         std::map<Key, Quadruple_vertices>& reference, std::set<Key>& held, Run_counts& counts) {
  for (std::size_t k = 0; k < sequence.size(); ++k) {
    if (const auto it = limits.find(k); it != limits.end()) {
      cache.limit(it->second);
      if (held.size() > it->second) {
        held.clear();
        ++counts.emptied;
      }
    }
    const Key& key = sequence[k];
    INFO("ask ", k, ": quadruple ", key[0], " ", key[1], " ", key[2], " ", key[3], ", ", held.size(),
         " quadruples held");
    const bool first_time = reference.find(key) == reference.end();
    if (first_time) reference.emplace(key, reference_vertices<Kernel>(key, sites));
    const bool miss = held.insert(key).second;
    const Quadruple_vertices got = cache.vertices_of_quadruple(key, sites);  // a copy: the next ask may move it
    ++counts.asks;
    counts.misses += miss;
    CHECK(cache.lookups() == counts.asks);
    CHECK(cache.misses() == counts.misses);
    check_same<Kernel>(got, reference.at(key), sites, first_time);
    counts.vertices += got.vertices.size();
    counts.rank_deficient += got.rank_deficient;
    counts.high_keys += key[3] >= kSiteCount - kBlock;
  }
}

template <class Kernel>
void check_cache() {
  const std::vector<Site> sites = make_sites();
  const std::vector<Site_index> used = used_indices();
  constexpr std::uint64_t kSeed = 20240615;
  INFO("random seed ", kSeed);
  std::mt19937_64 random(kSeed);
  Quadruple_cache<Kernel> cache;
  std::map<Key, Quadruple_vertices> reference;
  std::set<Key> held;
  Run_counts counts;

  SUBCASE("random keys, each asked again and again, across growth and emptying") {
    // A pool of distinct keys, asked in random order with repeats; limit() now and then, mostly with a
    // bound the cache exceeds (emptying it), sometimes with one it does not.
    std::set<Key> pool_set;
    while (pool_set.size() < 3000) pool_set.insert(random_key(random, used));
    const std::vector<Key> pool(pool_set.begin(), pool_set.end());
    std::vector<Key> sequence;
    for (int k = 0; k < 20000; ++k) sequence.push_back(pool[random() % (k < 10000 ? pool.size() : 300)]);
    std::map<std::size_t, std::size_t> limits;
    for (std::size_t k = 2000; k < sequence.size(); k += 1 + random() % 3000)
      limits[k] = random() % 2 == 0 ? random() % 200 : 1000000;
    limits[sequence.size() - 1] = 0;  // the last ask follows an emptying
    run(cache, sequence, limits, sites, reference, held, counts);
    CHECK(counts.emptied >= 3);
    CHECK(counts.misses > pool.size());  // keys were asked again after an emptying
    CHECK(counts.rank_deficient > 0);    // from the coplanar and duplicated sites
  }

  SUBCASE("keys that share a home slot") {
    // Keys whose hash agrees in the low 12 bits share a home slot while the table has up to 4096 slots:
    // each group probes a run of slots. Asked in rounds, so that later keys of a group find earlier ones
    // in their way, and again after the table grew.
    std::map<std::uint64_t, std::vector<Key>> by_slot;
    while (by_slot.size() < 100 || std::count_if(by_slot.begin(), by_slot.end(), [](const auto& g) {
                                      return g.second.size() >= 6;
                                    }) < 40) {
      const Key key = random_key(random, used);
      std::vector<Key>& group = by_slot[hash_copy(key) & 0xfff];
      if (std::find(group.begin(), group.end(), key) == group.end()) group.push_back(key);
    }
    std::vector<std::vector<Key>> groups;
    for (const auto& entry : by_slot)
      if (entry.second.size() >= 6 && groups.size() < 40) groups.push_back(entry.second);
    std::vector<Key> sequence;
    for (int round = 0; round < 3; ++round)
      for (const std::vector<Key>& group : groups)
        for (std::size_t k = 0; k < 6; ++k) sequence.push_back(group[(k + 2 * round) % group.size()]);
    run(cache, sequence, {{sequence.size() / 2, 0}}, sites, reference, held, counts);
    CHECK(counts.emptied == 1);
  }

  SUBCASE("every quadruple of indices spread over every bit") {
    // Keys that differ in one or two indices, and indices that differ in any of the 21 low bits: a
    // packing of the key that loses or mixes bits makes two of them one. Most quadruples include the zero
    // sites between the blocks (rank-deficient, no vertices): then the miss count tells them apart.
    std::vector<Site_index> spread;
    for (Site_index i = 0; i < 6; ++i) spread.push_back(i);
    for (int bit = 3; bit < 20; ++bit) spread.push_back(Site_index{1} << bit);
    for (Site_index i = (Site_index{1} << 20) - 2; i < kSiteCount; ++i) spread.push_back(i);
    std::vector<Key> sequence;
    for (std::size_t a = 0; a < spread.size(); ++a)
      for (std::size_t b = a + 1; b < spread.size(); ++b)
        for (std::size_t c = b + 1; c < spread.size(); ++c)
          for (std::size_t d = c + 1; d < spread.size(); ++d)
            sequence.push_back({spread[a], spread[b], spread[c], spread[d]});
    std::shuffle(sequence.begin(), sequence.end(), random);
    run(cache, sequence, {}, sites, reference, held, counts);
    CHECK(counts.misses == sequence.size());
    CHECK(counts.vertices > 0);
  }

  SUBCASE("one key over and over, and keys that differ in one index") {
    const Key base{1, 2, kSiteCount - 2, kSiteCount - 1};
    std::vector<Key> sequence(50, base);
    for (Site_index low : {Site_index{0}, Site_index{3}, kBlock - 1, kSiteCount - kBlock})
      for (int position = 0; position < 4; ++position) {
        Key key = base;
        key[position] = low;
        std::sort(key.begin(), key.end());
        if (std::adjacent_find(key.begin(), key.end()) != key.end()) continue;
        sequence.push_back(key);
        sequence.push_back(base);
      }
    // limit(0) empties a cache holding one quadruple; limit(1) keeps it.
    run(cache, sequence, {{10, 0}, {20, 1}}, sites, reference, held, counts);
    CHECK(counts.emptied == 1);
  }

  MESSAGE(std::string(Kernel::name), ": ", counts.asks, " asks, ", counts.misses, " misses, ", reference.size(),
          " distinct quadruples, emptied ", counts.emptied, " times; ", counts.vertices, " vertices returned, ",
          counts.rank_deficient, " rank-deficient answers, ", counts.high_keys, " keys with an index near 2^20");
  CHECK(counts.asks > 0);
  CHECK(counts.vertices > 0);
  CHECK(counts.high_keys > 0);
}

}  // namespace

TEST_CASE("Quadruple_cache<Certified_kernel> returns what vertices_of returns") { check_cache<Certified_kernel>(); }

TEST_CASE("Quadruple_cache<Floating_kernel> returns what vertices_of.floating returns") {
  check_cache<Floating_kernel>();
}
