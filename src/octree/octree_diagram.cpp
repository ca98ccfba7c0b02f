#include "octree/octree_diagram.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <new>
#include <stdexcept>
#include <vector>

#include "diagram/threads.h"
#include "diagram/cancellable_steps.h"
#include "octree/box_refinement.h"
#include "octree/candidate_propagation.h"
#include "octree/deep_clusters.h"
#include "octree/far_field.h"
#include "octree/lifted_triangulation.h"
#include "octree/equal_weight_lifts.h"
#include "octree/lifted_vertices.h"
#include "predicates/kernels.h"
#include "predicates/rounding_guard.h"
#include "predicates/trisector_rows.h"
#include "diagram/scale_normalization.h"
#include "octree/seed_partition.h"
#include "diagram/site_set.h"

namespace apollonius {
namespace {

// The root box reaches at least this many times G's size in every direction (seed_partition.h); beyond
// it, far_field.h decides. Near a flat face of sites (a lattice), the cells beyond it are parallel prisms
// that only the far field separates: the boxes between G and R cost about R / G per face
// (docs/benchmarks.md, "the root box at twice G").
constexpr double kFarFieldScale = 2;

// Each thread's list of vertices starts with room for this many per site, so that it is never moved while
// it grows and the assembly sorts it in place: a little more than the expected number of Delaunay
// tetrahedra per point of a uniform random set in space (6.77). Room that is never filled is address
// space, not memory: its pages are never touched.
constexpr std::size_t kReservedVerticesPerSite = 8;

// The same for the region boxes of the whole diagram (octree_diagram.h), with one thread: above what random
// balls and proteins make (docs/benchmarks.md, "Lists that never move"); ties make far more, and the list grows.
constexpr std::size_t kReservedRegionBoxesPerSite = 16;

// The refinement's budget (octree_diagram.h, step 5). Twice as many boxes when regions are asked for: past
// the budget the whole diagram's vertex-free search has no box and costs more than the boxes would have
// (sphere-tangent 4,000 refines 646 boxes per site: 9.7 s with them, 20.6 s past 512; docs/benchmarks.md).
constexpr std::size_t kBoxesPerSiteBeforeLifted = 512;
constexpr std::size_t kRegionBoxesPerSiteBeforeLifted = 1024;
constexpr std::size_t kBoxesBeforeLifted = 16384;
// The propagation's budget: seed candidates, (seed box, site) pairs. The benchmark inputs and the generated
// families enter 5 to 55 per site, a cluster beside one ball 10^6 to 10^12 away 9 to 34 (docs/benchmarks.md,
// "Witnesses by a search for the nearest sites"); with the witnesses of the paper's distance propagation,
// one ball 10^6 away from 10,000 others made 6,000 per site, and their refinement took 35 s.
constexpr std::size_t kSeedCandidatesPerSiteBeforeLifted = 128;
constexpr std::size_t kSeedCandidatesBeforeLifted = 16384;

// Room for `count` elements where the system grants the address space (a limit, or strict overcommit, may
// refuse it: the list then grows as it goes).
template <class T>
void reserve_if_granted(std::vector<T>& list, std::size_t count) {
  try {
    list.reserve(count);
  } catch (const std::bad_alloc&) {
  }
}

// Seconds since the last call (or construction).
class Lap_timer {
 public:
  double lap() {
    const auto now = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    return seconds;
  }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

// Regions with no box: every active site escapes, and they are one far set.
Octree_regions regions_without_boxes(const std::vector<Site_index>& active, bool lifted_fallback) {
  Octree_regions regions;
  regions.escaping = active;
  if (active.size() >= 2) regions.far_sets.push_back(active);
  regions.lifted_fallback = lifted_fallback;
  return regions;
}

// The regions in input units: boxes scaled back by 2^exponent, exactly (powers of two) unless a bound
// leaves the double range, which the whole diagram does not handle.
void unscale_regions(Octree_regions& regions, int exponent) {
  const auto unscale = [&](Axis_box& b) {
    for (int a = 0; a < 3; ++a) {
      b.lo[a] = std::ldexp(b.lo[a], exponent);
      b.hi[a] = std::ldexp(b.hi[a], exponent);
      if (!std::isfinite(b.lo[a]) || !std::isfinite(b.hi[a]))
        throw std::overflow_error("the octree's regions leave the double range in input units");
    }
  };
  if (regions.has_octree) unscale(regions.root);
  for (Octree_regions::Box& b : regions.boxes) unscale(b.box);
}

}  // namespace

bool region_box_needed(const std::vector<Site>& sites, const Site_index* first, const Site_index* last,
                       const std::vector<bool>& escapes) {
  if (std::count_if(first, last, [&](Site_index s) { return escapes[s]; }) >= 2) return true;
  const std::size_t size = static_cast<std::size_t>(last - first);
  if (size < 3) return false;
  Rounding_guard guard;
  thread_local Pairwise_gaps gaps;
  gaps.assign(sites, first, size);
  for (std::size_t i = 0; i < size; ++i)
    for (std::size_t j = i + 1; j < size; ++j)
      for (std::size_t k = j + 1; k < size; ++k)
        if (gaps.maybe_closed(i, j, k)) return true;
  return false;
}

namespace {

template <class Kernel>
Diagram octree_diagram_with(const std::vector<Site>& input_sites, const Octree_options& options) {
  Octree_statistics statistics;
  Lap_timer timer;
  std::vector<Hidden_site> hidden = classify_hidden_sites<Kernel>(input_sites, options.cancellation, options.threads);
  const std::vector<Site_index> active = active_sites(input_sites.size(), hidden);
  if (active.size() < 4) {
    if (options.regions != nullptr) *options.regions = regions_without_boxes(active, false);
    return assemble_diagram<Kernel>(input_sites.size(), std::move(hidden), std::vector<Diagram_vertex>{}, options.cancellation);
  }
  const int exponent = normalizing_exponent(input_sites, active);
  const std::vector<Site> normalized = exponent == 0 ? std::vector<Site>{} : scaled_sites(input_sites, exponent);
  const std::vector<Site>& sites = exponent == 0 ? input_sites : normalized;

  // Each thread's vertices, in no particular order (assemble_diagram sorts them): one list per seed would
  // take one more copy of them all to gather.
  const int threads = usable_threads(options.threads);
  tbb::enumerable_thread_specific<std::vector<Found_vertex>> found([&] {
    std::vector<Found_vertex> list;
    reserve_if_granted(list, kReservedVerticesPerSite * active.size());  // every thread may find nearly all of them
    return list;
  });
  std::vector<std::vector<Found_vertex>> lists;
  const std::size_t budget_boxes =
      options.box_budget.value_or((options.regions != nullptr ? kRegionBoxesPerSiteBeforeLifted : kBoxesPerSiteBeforeLifted) *
                                      active.size() +
                                  kBoxesBeforeLifted);
  // A budget of 0 (step 5 asked for) is its own reason, for --stats.
  const bool may_go_at_once =
      options.regions == nullptr && options.arithmetic == Arithmetic::certified && budget_boxes > 0;
  const bool small_input = may_go_at_once && active.size() <= options.lifted_at_most_sites;
  const bool one_weight =
      may_go_at_once && !small_input && options.lifted_for_one_weight && has_one_weight(sites, active);
  const bool deep_input =
      may_go_at_once && !small_input && !one_weight && options.lifted_for_deep_inputs && has_deep_clusters(sites, active);
  const std::size_t box_limit = small_input || one_weight || deep_input ? 0 : budget_boxes;
  Work_budget box_budget(box_limit);
  Work_budget seed_budget(options.seed_candidate_budget.value_or(kSeedCandidatesPerSiteBeforeLifted * active.size() +
                                                                 kSeedCandidatesBeforeLifted));
  // Every parallel step runs inside: --threads holds. More threads than the machine runs at once would
  // change nothing but make TBB print a warning.
  tbb::task_arena arena(threads);
  try {
    if (box_limit == 0) throw Work_budget_exceeded();
    arena.execute([&] {
      const Seed_partition partition(sites, active, kFarFieldScale);
      statistics.partition_seconds = timer.lap();
      const std::vector<std::vector<Site_index>> candidates =
          propagate_candidates(sites, active, partition, Kernel::filter_slack, options.cancellation, &seed_budget);
      statistics.propagation_seconds = timer.lap();

      // The sites owning a point outside R own a point of its boundary, so they are candidates of the boxes
      // on it; far_field.h decides the vertices beyond R among them.
      std::vector<Site_index> escaping;
      std::vector<std::size_t> seeds;
      for (std::size_t id = 0; id < partition.id_count(); ++id) {
        if (candidates[id].size() >= 4) seeds.push_back(id);
        statistics.seed_candidates += candidates[id].size();
        if (partition.touches_root_boundary(id))
          escaping.insert(escaping.end(), candidates[id].begin(), candidates[id].end());
      }
      std::sort(escaping.begin(), escaping.end());
      escaping.erase(std::unique(escaping.begin(), escaping.end()), escaping.end());
      statistics.seed_boxes = seeds.size();
      statistics.escaping_sites = escaping.size();

      tbb::enumerable_thread_specific<Box_refinement<Kernel>> refinement(sites, partition.root_box(), options.cancellation,
                                                                         &box_budget, options.tie_point_stars);
      std::vector<bool> escapes(options.regions != nullptr ? sites.size() : 0, false);
      if (options.regions != nullptr) {
        for (Site_index s : escaping) escapes[s] = true;
        Octree_regions& r = *options.regions;
        r = {};
        r.has_octree = true;
        r.root = partition.root_box();
        // One thread refines straight into the list: room for the usual count, so that it rarely moves.
        if (threads <= 1) reserve_if_granted(r.boxes, kReservedRegionBoxesPerSite * active.size());
        for (std::size_t id = 0; id < partition.id_count(); ++id) {
          if (id % 4096 == 0) throw_if_cancelled(options.cancellation);
          const std::vector<Site_index>& c = candidates[id];
          if (partition.is_box(id) && c.size() >= 2 && c.size() < 4 &&
              region_box_needed(sites, c.data(), c.data() + c.size(), escapes))
            r.boxes.push_back({partition.box(id), Octree_regions::Sites(c.begin(), c.end())});
        }
      }
      // The regions follow the partition's boxes in the order of the seeds, each refined depth first: the
      // same for every thread count, with no sort. One thread refines the seeds in order, straight into
      // the regions; more keep a list per seed (one list per thread would grow to millions of boxes, and each
      // reallocation would move them all at once), concatenated in order.
      const auto refine_seed = [&](std::size_t k, std::vector<Octree_regions::Box>* regions) {
        throw_if_cancelled(options.cancellation);
        Box_refinement<Kernel>& local = refinement.local();
        if (regions != nullptr) local.record_regions(regions, &escapes);
        local.find_vertices(partition.box(seeds[k]), candidates[seeds[k]], found.local());
      };
      // The far field needs only the escaping sites: it runs beside the refinement (a task that the one thread
      // of --threads 1 runs at the wait).
      Far_field_vertices far;
      tbb::task_group far_task;
      far_task.run([&] {
        Lap_timer far_timer;
        far = far_vertices<Kernel>(sites, escaping, partition.origin(), partition.root_radius(), partition.root_box(),
                                   options.regions != nullptr, options.cancellation);
        statistics.far_field_seconds = far_timer.lap();
      });
      try {
        if (options.threads <= 1) {
          for (std::size_t k = 0; k < seeds.size(); ++k)
            refine_seed(k, options.regions != nullptr ? &options.regions->boxes : nullptr);
        } else {
          std::vector<std::vector<Octree_regions::Box>> seed_regions(options.regions != nullptr ? seeds.size() : 0);
          tbb::parallel_for(std::size_t{0}, seeds.size(), [&](std::size_t k) {
            refine_seed(k, options.regions != nullptr ? &seed_regions[k] : nullptr);
          });
          if (options.regions != nullptr) move_concatenated(seed_regions, options.regions->boxes, options.cancellation);
        }
      } catch (...) {
        far_task.cancel();
        far_task.wait();  // a task_group must not be destroyed with a task running
        throw;
      }
      statistics.refinement_seconds = timer.lap();
      far_task.wait();
      timer.lap();  // the wait is the far field's, which it timed itself
      for (const Box_refinement<Kernel>& r : refinement) {
        const Refinement_counts counts = r.counts();
        statistics.boxes += counts.boxes;
        statistics.leaves += counts.leaves;
        statistics.leaf_candidates += counts.leaf_candidates;
        statistics.box_candidates += counts.box_candidates;
        statistics.lifted_leaves += counts.lifted_leaves;
        statistics.quadruples += counts.quadruples;
        statistics.distinct_quadruples += counts.distinct_quadruples;
      }
      for (std::vector<Found_vertex>& list : found) lists.push_back(std::move(list));
      lists.push_back(std::move(far.vertices));
      if (options.regions != nullptr) {
        options.regions->escaping = escaping;
        options.regions->far_sets = std::move(far.patch_sites);
      }
      statistics.far_field_quadruples = far.quadruples;
    });
  } catch (const Work_budget_exceeded&) {
    // Step 5: what the refinement found goes, and the vertices come from the lifted triangulation.
    lists.clear();
    statistics = Octree_statistics{};
    statistics.boxes = box_budget.spent();
    statistics.lifted_fallback = true;
    statistics.lifted_small_input = small_input;
    statistics.lifted_one_weight = one_weight;
    statistics.lifted_deep_input = deep_input;
    statistics.lifted_seed_candidates = seed_budget.exceeded();
    if (options.regions != nullptr) *options.regions = regions_without_boxes(active, true);
    Lap_timer lifted_timer;
    arena.execute([&] {
      auto lifts = std::make_shared<const Lifted_triangulation>(lifted_triangulation(sites, active, options.cancellation));
      statistics.lifted_quadruples = lifts->quadruples.size();
      lists.push_back(lifted_vertices<Kernel>(sites, *lifts, [](const Vertex&) { return true; }, options.cancellation));
      if (options.regions != nullptr) options.regions->lifts = std::move(lifts);
    });
    statistics.lifted_seconds = lifted_timer.lap();
    timer.lap();
  }
  if (exponent != 0) {
    for (std::vector<Found_vertex>& list : lists)
      for (Found_vertex& f : list) {  // rounded again on the input sites: the scaled rounding need not scale
        f = {std::move(f.tie_set), unscaled_vertex(f.vertex, input_sites, exponent)};
        settle<Kernel>(f);
      }
    if (options.regions != nullptr) unscale_regions(*options.regions, exponent);
  }
  Diagram diagram =
      assemble_diagram<Kernel>(sites.size(), std::move(hidden), std::move(lists), options.cancellation);
  statistics.assembly_seconds = timer.lap();
  if (options.statistics) *options.statistics = statistics;
  return diagram;
}

}  // namespace

Diagram octree_diagram(const std::vector<Site>& sites, const Octree_options& options) {
  return options.arithmetic == Arithmetic::certified ? octree_diagram_with<Certified_kernel>(sites, options)
                                                     : octree_diagram_with<Floating_kernel>(sites, options);
}

}  // namespace apollonius
