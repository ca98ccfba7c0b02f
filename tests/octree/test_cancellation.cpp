// Cancellation (diagram/cancellation.h): a requested cancellation stops every phase of octree_diagram with
// Cancelled, whenever it comes, and leaves nothing half done (the next computation is whole); one that is
// never requested changes no output. The bulk steps between phases (diagram/cancellable_steps.h) too.
#include <doctest/doctest.h>

#include <algorithm>
#include <chrono>
#include <random>
#include <thread>

#include "diagram/cancellable_steps.h"
#include "diagram/cancellation.h"
#include "diagram/site_set.h"
#include "octree/candidate_propagation.h"
#include "octree/far_field.h"
#include "octree/octree_diagram.h"
#include "octree/seed_partition.h"
#include "predicates/kernels.h"
#include "reference/site_generators.h"

using namespace apollonius;

namespace {

void check_same(const Diagram& a, const Diagram& b) {
  REQUIRE(a.vertices.size() == b.vertices.size());
  for (std::size_t i = 0; i < a.vertices.size(); ++i) {
    CAPTURE(i);
    CHECK(a.vertices[i].tie_set == b.vertices[i].tie_set);
    CHECK(a.vertices[i].rounded == b.vertices[i].rounded);
  }
  REQUIRE(a.hidden.size() == b.hidden.size());
  for (std::size_t i = 0; i < a.hidden.size(); ++i) {
    CHECK(a.hidden[i].site == b.hidden[i].site);
    CHECK(a.hidden[i].hidden_by == b.hidden[i].hidden_by);
    CHECK(a.hidden[i].duplicate == b.hidden[i].duplicate);
  }
  CHECK(a.sites_without_vertex == b.sites_without_vertex);
}

// The octree (never straight to step 5 for a small input) unless lifted_at_most_sites says otherwise.
Octree_options with(const Cancellation* cancellation, int threads = 1, std::size_t lifted_at_most_sites = 0) {
  Octree_options options;
  options.threads = threads;
  options.cancellation = cancellation;
  options.lifted_at_most_sites = lifted_at_most_sites;
  options.lifted_for_one_weight = false;
  options.lifted_for_deep_inputs = false;
  return options;
}

}  // namespace

TEST_CASE("a cancellation that is never requested changes nothing") {
  for (const Site_family_description& f : kSiteFamilies) {
    for (int threads : {1, 2}) {
      CAPTURE(f.name);
      CAPTURE(threads);
      const std::vector<Site> sites = generate_sites(f.family, 60, 7);
      const Cancellation never;
      check_same(octree_diagram(sites, with(&never, threads)), octree_diagram(sites, with(nullptr, threads)));
      const std::size_t small = Octree_options{}.lifted_at_most_sites;  // the lifted path for these 60 sites
      check_same(octree_diagram(sites, with(&never, threads, small)), octree_diagram(sites, with(nullptr, threads)));
    }
  }
}

TEST_CASE("a cancellation requested before the call stops it, and every phase checks it") {
  const std::vector<Site> sites = generate_sites(Site_family::uniform, 500, 3);
  Cancellation cancellation;
  cancellation.request();
  CHECK_THROWS_AS(octree_diagram(sites, with(&cancellation)), Cancelled);
  CHECK_THROWS_AS(octree_diagram(sites, with(&cancellation, 2)), Cancelled);
  CHECK_THROWS_AS(octree_diagram(sites, with(&cancellation, 1, sites.size())), Cancelled);  // the lifted path
  CHECK_THROWS_AS(classify_hidden_sites<Certified_kernel>(sites, &cancellation), Cancelled);

  std::vector<Site_index> all(sites.size());
  for (Site_index i = 0; i < all.size(); ++i) all[i] = i;
  const Seed_partition partition(sites, all, 32);
  CHECK_THROWS_AS(propagate_candidates(sites, all, partition, 1, &cancellation), Cancelled);
  CHECK_THROWS_AS(far_vertices<Certified_kernel>(sites, all, partition.origin(), partition.root_radius(),
                                                 partition.root_box(), true, &cancellation),
                  Cancelled);
  // Assembly, on the vertices of a small diagram.
  const Diagram small = octree_diagram(generate_sites(Site_family::uniform, 10, 1));
  REQUIRE_FALSE(small.vertices.empty());
  std::vector<Diagram_vertex> found;
  for (const Diagram_vertex& v : small.vertices) found.push_back({v.tie_set, v.vertex});
  CHECK_THROWS_AS(assemble_diagram<Certified_kernel>(10, {}, found, &cancellation), Cancelled);
  CHECK(assemble_diagram<Certified_kernel>(10, {}, found, nullptr).vertices.size() == small.vertices.size());
}

TEST_CASE("a cancellation requested during the computation gives Cancelled or the whole answer") {
  const std::vector<Site> sites = generate_sites(Site_family::uniform, 3000, 11);
  const Diagram reference = octree_diagram(sites);
  for (int threads : {1, 2}) {
    int cancelled = 0;
    for (int delay_ms : {0, 2, 10, 30, 60, 120, 250, 500, 1000, 4000}) {
      CAPTURE(threads);
      CAPTURE(delay_ms);
      Cancellation cancellation;
      std::thread requester([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms));
        cancellation.request();
      });
      try {
        check_same(octree_diagram(sites, with(&cancellation, threads)), reference);
      } catch (const Cancelled&) {
        ++cancelled;
        // Nothing of the cancelled run is left behind: the next one is whole.
        check_same(octree_diagram(sites, with(nullptr, threads)), reference);
      }
      requester.join();
      // Requested at once, long before a run of 3000 sites ends.
      if (delay_ms == 0) CHECK(cancelled == 1);
    }
    MESSAGE("threads " << threads << ": " << cancelled << " of 10 runs cancelled");
  }
}

TEST_CASE("the cancellable bulk steps equal the plain ones, and stop when cancellation is requested") {
  std::mt19937_64 random(20261125);
  std::vector<std::pair<int, int>> items(200000);
  for (std::size_t i = 0; i < items.size(); ++i) items[i] = {static_cast<int>(random() % 1000), static_cast<int>(i)};
  const auto by_key = [](const std::pair<int, int>& x, const std::pair<int, int>& y) { return x.first < y.first; };
  std::vector<std::pair<int, int>> expected = items;
  std::stable_sort(expected.begin(), expected.end(), by_key);
  std::vector<std::pair<int, int>> in_order = items;
  std::sort(in_order.begin(), in_order.end());
  const Cancellation never;
  for (const Cancellation* cancellation : {static_cast<const Cancellation*>(nullptr), &never}) {
    std::vector<std::pair<int, int>> sorted = items;
    cancellable_stable_sort(sorted.begin(), sorted.end(), cancellation, by_key);
    CHECK(sorted == expected);  // equal keys keep their order (the second members ascend)
    sorted = items;
    cancellable_sort(sorted.begin(), sorted.end(), cancellation);
    CHECK(sorted == in_order);

    std::vector<std::vector<int>> lists = {{1, 2}, {}, {3}, std::vector<int>(10000, 4)};
    std::vector<int> out = {0};
    move_concatenated(lists, out, cancellation);
    REQUIRE(out.size() == 10004);
    CHECK(std::vector<int>(out.begin(), out.begin() + 5) == std::vector<int>{0, 1, 2, 3, 4});
    CHECK(std::all_of(lists.begin(), lists.end(), [](const std::vector<int>& l) { return l.capacity() == 0; }));
  }

  Cancellation requested;
  requested.request();
  std::vector<std::pair<int, int>> sorted = items;
  CHECK_THROWS_AS(cancellable_sort(sorted.begin(), sorted.end(), &requested), Cancelled);
  std::sort(sorted.begin(), sorted.end());
  CHECK(sorted == in_order);  // the same elements, in some order
  CHECK_THROWS_AS(cancellable_stable_sort(sorted.begin(), sorted.end(), &requested, by_key), Cancelled);
  std::vector<std::pair<int, int>> two(items.begin(), items.begin() + 2);  // too short to check within
  CHECK_THROWS_AS(cancellable_sort(two.begin(), two.end(), &requested), Cancelled);
  std::vector<std::vector<int>> lists = {std::vector<int>(10000, 4)};
  std::vector<int> out;
  CHECK_THROWS_AS(move_concatenated(lists, out, &requested), Cancelled);
}
