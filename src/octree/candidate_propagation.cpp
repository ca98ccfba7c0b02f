#include "octree/candidate_propagation.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "diagram/site_tree.h"
#include "predicates/centre_expansion.h"

namespace apollonius {
namespace {

// Each box keeps this many witnesses: sites of least distance at its centre, found by pass 1.
constexpr std::size_t kWitnesses = 4;
static_assert(kWitnesses <= Site_tree::kMostNearest);

// The boxes with their centres, witnesses and face neighbours (compressed rows).
// Invariant: witnesses[b] holds distinct sites by ascending d at the centre.
struct Box_graph {
  std::vector<Axis_box> box;
  std::vector<Box_frame> frame;
  std::vector<std::size_t> neighbour_start, neighbours;
  std::vector<std::vector<std::pair<Site_index, Witness_expansion>>> witnesses;

  // Built in parallel over fixed chunks of identifiers, whose rows are then laid end to end in order: the
  // same graph for every thread count.
  Box_graph(const Seed_partition& partition, const Cancellation* cancellation)
      : box(partition.id_count()),
        frame(partition.id_count()),
        neighbour_start(partition.id_count() + 1, 0),
        witnesses(partition.id_count()) {
    constexpr std::size_t kChunk = 4096;
    const std::size_t ids = partition.id_count(), chunks = (ids + kChunk - 1) / kChunk;
    const auto chunk_end = [&](std::size_t c) { return std::min(ids, (c + 1) * kChunk); };
    std::vector<std::vector<std::size_t>> chunk_neighbours(chunks);
    tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t c) {
      throw_if_cancelled(cancellation);
      std::vector<std::size_t>& out = chunk_neighbours[c];
      for (std::size_t id = c * kChunk; id < chunk_end(c); ++id) {
        if (partition.is_box(id)) {
          box[id] = partition.box(id);
          frame[id] = frame_of(box[id]);
          partition.append_face_neighbours(id, out);
        }
        neighbour_start[id + 1] = out.size();  // within the chunk, made absolute below
      }
    });
    std::size_t offset = 0;
    for (std::size_t c = 0; c < chunks; ++c) {
      for (std::size_t id = c * kChunk; id < chunk_end(c); ++id) neighbour_start[id + 1] += offset;
      neighbours.insert(neighbours.end(), chunk_neighbours[c].begin(), chunk_neighbours[c].end());
      offset += chunk_neighbours[c].size();
      std::vector<std::size_t>().swap(chunk_neighbours[c]);
    }
  }
};

// Pass 1: each box's witnesses are the kWitnesses sites of least d at its centre, in floating point (which
// sites they are matters for speed only). The paper propagates distances from the sites' home boxes in
// Dijkstra order, which finds them only approximately and one event at a time; a search per box in a tree
// of the sites finds them outright, each box on its own, in parallel and the same for every thread count.
void find_witnesses(Box_graph& graph, const std::vector<Site>& sites, const std::vector<Site_index>& active,
                    const Seed_partition& partition, const Cancellation* cancellation) {
  const Site_tree tree(sites, active);
  tbb::parallel_for(std::size_t{0}, graph.box.size(), [&](std::size_t b) {
    if (b % 4096 == 0) throw_if_cancelled(cancellation);
    if (!partition.is_box(b)) return;
    std::array<Site_index, kWitnesses> nearest;
    const std::size_t count = tree.nearest(graph.frame[b].centre, kWitnesses, nearest.data());
    auto& held = graph.witnesses[b];
    held.reserve(count);
    for (std::size_t k = 0; k < count; ++k) {
      held.emplace_back(nearest[k], expand_witness(expand_at_centre(sites[nearest[k]], graph.frame[b])));
      add_corners(held.back().second, sites[nearest[k]], graph.frame[b]);
    }
  });
}

// Whether a witness of box b certainly dominates site s on it (centre_expansion.h).
bool dominated(const Box_graph& graph, const std::vector<Site>& sites, std::size_t b, Site_index s, double slack) {
  const auto& held = graph.witnesses[b];
  if (held.empty()) return false;
  const Centre_expansion at_s = expand_at_centre(sites[s], graph.frame[b]);
  Candidate_on_box on_box;
  for (const auto& [w, at_w] : held)
    if (w != s && expansion_dominates(sites[w], at_w, sites[s], at_s, on_box, graph.frame[b], slack)) return true;
  return false;
}

// Pass 2: each site floods from its home box through face neighbours, entering every box where no
// witness dominates it. Returns the (box, site) pairs of one thread's sites.
struct Flood {
  std::vector<Site_index> last_visitor;  // per box: the last site whose flood visited it, or none
  std::vector<std::size_t> stack;
  std::vector<std::pair<std::size_t, Site_index>> entered;
  explicit Flood(std::size_t boxes) : last_visitor(boxes, std::numeric_limits<Site_index>::max()) {}
};

void flood(Flood& f, const Box_graph& graph, const std::vector<Site>& sites, const Seed_partition& partition,
           Site_index s, double slack) {
  const std::size_t home = partition.home(sites[s]);
  f.last_visitor[home] = s;
  f.stack.assign(1, home);
  while (!f.stack.empty()) {
    const std::size_t b = f.stack.back();
    f.stack.pop_back();
    if (dominated(graph, sites, b, s, slack)) continue;
    f.entered.emplace_back(b, s);
    for (std::size_t k = graph.neighbour_start[b]; k < graph.neighbour_start[b + 1]; ++k) {
      const std::size_t next = graph.neighbours[k];
      if (f.last_visitor[next] == s) continue;
      f.last_visitor[next] = s;
      f.stack.push_back(next);
    }
  }
}

}  // namespace

std::vector<std::vector<Site_index>> propagate_candidates(const std::vector<Site>& sites,
                                                          const std::vector<Site_index>& active,
                                                          const Seed_partition& partition, double slack,
                                                          const Cancellation* cancellation, Work_budget* budget) {
  Box_graph graph(partition, cancellation);
  find_witnesses(graph, sites, active, partition, cancellation);

  tbb::enumerable_thread_specific<Flood> floods(partition.id_count());
  tbb::parallel_for(std::size_t{0}, active.size(), [&](std::size_t k) {
    throw_if_cancelled(cancellation);
    Flood& local = floods.local();
    const std::size_t entered = local.entered.size();
    flood(local, graph, sites, partition, active[k], slack);
    if (budget != nullptr) budget->spend(local.entered.size() - entered);
  });
  std::vector<std::size_t> count(partition.id_count(), 0);
  for (const Flood& f : floods)
    for (const auto& entry : f.entered) ++count[entry.first];
  std::vector<std::vector<Site_index>> candidates(partition.id_count());
  for (std::size_t b = 0; b < candidates.size(); ++b) candidates[b].reserve(count[b]);
  for (const Flood& f : floods)
    for (const auto& [b, s] : f.entered) candidates[b].push_back(s);
  throw_if_cancelled(cancellation);
  // The same lists for every thread count.
  for (auto& list : candidates) std::sort(list.begin(), list.end());
  return candidates;
}

}  // namespace apollonius
