#include "octree_diagram.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include "dominates_on_box.h"
#include "far_field.h"
#include "leaf_decision.h"
#include "lipschitz_filter.h"
#include "rounding_guard.h"
#include "site_set.h"
#include "vertex_in_box.h"

namespace apollonius {
namespace {

// A leaf is decided by enumerating the quadruples of its candidates once refining stops helping: the
// candidate count has not dropped for kStagnationLevels levels and the box is tiny against the candidates
// (a degenerate vertex keeps its whole tie set as candidates however small the box), or the box cannot be
// split in doubles, or the depth reaches kMaxDepth. None of these drops a vertex: the leaf is decided
// exactly.
constexpr int kStagnationLevels = 4;
constexpr double kTinyBox = 64;
// Deciding a leaf of k candidates costs C(k, 4) quadruples; up to 6 (15 quadruples) that is cheaper than
// refining further, especially far away, where separating the 5th and 6th site takes many levels.
constexpr std::size_t kLeafCandidates = 6;
constexpr int kMaxDepth = 400;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The root box reaches this many times G's size in every direction; beyond it, far_field.h decides.
// Measured on BALL_SMALL_1000: 64 and 128 leave the far field too many candidates, 1024 refines more.
constexpr double kFarFieldScale = 256;

// The seed grid over the box G: cells[i + m0 * (j + m1 * k)].
class Seed_grid {
 public:
  Seed_grid(const std::vector<Site>& sites, const std::vector<Site_index>& active) {
    std::array<double, 3> lo{kInfinity, kInfinity, kInfinity}, hi{-kInfinity, -kInfinity, -kInfinity};
    for (Site_index i : active) {
      const double c[3] = {sites[i].x, sites[i].y, sites[i].z};
      for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], c[a]), hi[a] = std::max(hi[a], c[a]);
    }
    // About one site per cell: the cell size of a cube of n cells over the largest extent, halved while a
    // flat input would leave far fewer cells than sites.
    const double extent = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
    const double n = static_cast<double>(active.size());
    double cell = extent / std::max(1.0, std::ceil(std::cbrt(n)));
    auto count = [&](double size) {
      double cells = 1;
      for (int a = 0; a < 3; ++a) cells *= std::floor((hi[a] - lo[a]) / size) + 1;
      return cells;
    };
    while (count(cell) < n / 4 && cell > extent * 1e-6) cell /= 2;
    for (int a = 0; a < 3; ++a) {
      cells_[a] = static_cast<int>(std::floor((hi[a] - lo[a]) / cell)) + 1;
      const double width = cells_[a] * cell, pad = (width - (hi[a] - lo[a])) / 2;
      box_.lo[a] = lo[a] - pad;
      box_.hi[a] = hi[a] + pad;
      if (!(box_.lo[a] < lo[a]) || !(box_.hi[a] > hi[a]))  // keep every centre strictly inside G
        box_.lo[a] = std::nextafter(std::min(box_.lo[a], lo[a]), -kInfinity),
        box_.hi[a] = std::nextafter(std::max(box_.hi[a], hi[a]), kInfinity);
    }
  }

  const Axis_box& box() const { return box_; }
  int cells(int axis) const { return cells_[axis]; }
  std::size_t size() const { return static_cast<std::size_t>(cells_[0]) * cells_[1] * cells_[2]; }
  std::size_t index(int i, int j, int k) const {
    return static_cast<std::size_t>(i) + cells_[0] * (static_cast<std::size_t>(j) + cells_[1] * static_cast<std::size_t>(k));
  }
  std::array<int, 3> coordinates(std::size_t cell) const {
    return {static_cast<int>(cell % cells_[0]), static_cast<int>(cell / cells_[0] % cells_[1]),
            static_cast<int>(cell / cells_[0] / cells_[1])};
  }
  // Boundary k of an axis; adjacent cells share it exactly because it is computed one way only.
  double bound(int axis, int k) const {
    if (k == 0) return box_.lo[axis];
    if (k == cells_[axis]) return box_.hi[axis];
    return box_.lo[axis] + (box_.hi[axis] - box_.lo[axis]) * (static_cast<double>(k) / cells_[axis]);
  }
  Axis_box cell_box(std::size_t cell) const {
    const auto c = coordinates(cell);
    Axis_box b;
    for (int a = 0; a < 3; ++a) b.lo[a] = bound(a, c[a]), b.hi[a] = bound(a, c[a] + 1);
    return b;
  }
  // A cell whose closed box contains the point.
  std::size_t locate(const Site& s) const {
    const double c[3] = {s.x, s.y, s.z};
    int k[3];
    for (int a = 0; a < 3; ++a) {
      k[a] = std::clamp(static_cast<int>((c[a] - box_.lo[a]) / (box_.hi[a] - box_.lo[a]) * cells_[a]), 0, cells_[a] - 1);
      while (k[a] > 0 && c[a] < bound(a, k[a])) --k[a];
      while (k[a] < cells_[a] - 1 && c[a] > bound(a, k[a] + 1)) ++k[a];
    }
    return index(k[0], k[1], k[2]);
  }
  bool on_boundary(std::size_t cell) const {
    const auto c = coordinates(cell);
    for (int a = 0; a < 3; ++a)
      if (c[a] == 0 || c[a] == cells_[a] - 1) return true;
    return false;
  }

 private:
  Axis_box box_;
  std::array<int, 3> cells_;
};

// Step 1: candidate sites of every seed cell by Dijkstra-like propagation (paper section 5.2.1).
std::vector<std::vector<Site_index>> propagate_sites(const std::vector<Site>& sites, const std::vector<Site_index>& active,
                                                     const Seed_grid& grid) {
  struct Cell_state {
    std::vector<Site_index> candidates;
    double upper = kInfinity;  // greatest distance of the witness over the cell
    Site_index witness = 0;
  };
  struct Event {
    double key;  // least distance of the site over the cell
    Site_index site;
    std::size_t cell;
    bool operator>(const Event& e) const { return key > e.key; }
  };
  std::vector<Cell_state> cells(grid.size());
  std::priority_queue<Event, std::vector<Event>, std::greater<Event>> events;
  auto contains = [](const Cell_state& c, Site_index s) {
    return std::find(c.candidates.begin(), c.candidates.end(), s) != c.candidates.end();
  };
  for (Site_index i : active) events.push({-sites[i].w, i, grid.locate(sites[i])});
  while (!events.empty()) {
    const Event e = events.top();
    events.pop();
    Cell_state& cell = cells[e.cell];
    if (contains(cell, e.site)) continue;
    const Axis_box box = grid.cell_box(e.cell);
    if (!cell.candidates.empty() && (Lipschitz_filter(box, sites[cell.witness]).witness_dominates(sites[e.site]) ||
                                     dominates_on_box(sites[cell.witness], sites[e.site], box)))
      continue;
    cell.candidates.push_back(e.site);
    if (const double upper = greatest_distance_bounds(sites[e.site], box).upper; upper < cell.upper)
      cell.upper = upper, cell.witness = e.site;
    const auto c = grid.coordinates(e.cell);
    for (int dk = -1; dk <= 1; ++dk)
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
          const int i = c[0] + di, j = c[1] + dj, k = c[2] + dk;
          if (i < 0 || j < 0 || k < 0 || i >= grid.cells(0) || j >= grid.cells(1) || k >= grid.cells(2)) continue;
          const std::size_t next = grid.index(i, j, k);
          const Cell_state& n = cells[next];
          if (contains(n, e.site)) continue;
          const double key = least_distance_bounds(sites[e.site], grid.cell_box(next)).lower;
          if (key > n.upper) continue;  // certainly dominated there: least of i > greatest of the witness
          events.push({key, e.site, next});
        }
  }
  std::vector<std::vector<Site_index>> candidates(grid.size());
  for (std::size_t c = 0; c < grid.size(); ++c) {
    candidates[c] = std::move(cells[c].candidates);
    std::sort(candidates[c].begin(), candidates[c].end());
  }
  return candidates;
}

// Steps 3: refinement of one box and exact decision of its leaves.
class Box_refiner {
 public:
  Box_refiner(const std::vector<Site>& sites, const Axis_box& root) : sites_(sites), root_(root) {}

  void refine(const Axis_box& box, std::vector<Site_index> candidates, int depth, int stagnant,
              std::vector<Found_vertex>& out) const {
    const std::size_t before = candidates.size();
    remove_dominated(box, candidates);
    if (candidates.size() < 4) return;
    stagnant = candidates.size() == before ? stagnant + 1 : 0;
    const bool settled = candidates.size() <= kLeafCandidates || depth >= kMaxDepth ||
                         (stagnant >= kStagnationLevels && tiny_against_candidates(box, candidates));
    std::vector<Axis_box> children;
    if (!settled) children = split(box);
    if (children.empty()) {
      decide_leaf(box, candidates, out);
      return;
    }
    for (const Axis_box& child : children) refine(child, candidates, depth + 1, stagnant, out);
  }

 private:
  // Every candidate that the witness certainly dominates on the box goes: the certified Lipschitz filter
  // first (lipschitz_filter.h), then paper Theorem 6 on the box (exact). The witness is the site nearest
  // to the box centre, the best for the Lipschitz test; which site it is does not matter for soundness.
  void remove_dominated(const Axis_box& box, std::vector<Site_index>& candidates) const {
    if (candidates.size() < 2) return;
    const Site_index witness = nearest_to_centre(box, candidates);
    const Lipschitz_filter lipschitz(box, sites_[witness]);
    candidates.erase(std::remove_if(candidates.begin(), candidates.end(),
                                    [&](Site_index s) {
                                      return s != witness && (lipschitz.witness_dominates(sites_[s]) ||
                                                              dominates_on_box(sites_[witness], sites_[s], box));
                                    }),
                     candidates.end());
  }

  Site_index nearest_to_centre(const Axis_box& box, const std::vector<Site_index>& candidates) const {
    const double c[3] = {box.lo[0] + (box.hi[0] - box.lo[0]) / 2, box.lo[1] + (box.hi[1] - box.lo[1]) / 2,
                         box.lo[2] + (box.hi[2] - box.lo[2]) / 2};
    Site_index nearest = candidates[0];
    double best = kInfinity;
    for (Site_index s : candidates) {
      const Site& site = sites_[s];
      const double d = std::sqrt((c[0] - site.x) * (c[0] - site.x) + (c[1] - site.y) * (c[1] - site.y) +
                                 (c[2] - site.z) * (c[2] - site.z)) - site.w;
      if (d < best) best = d, nearest = s;
    }
    return nearest;
  }

  // The box is tiny against its distance to every candidate centre: kTinyBox times its half-diagonal is
  // below each distance. Refining further cannot separate candidates that tie at a point (a degenerate
  // vertex) or along a curve. Boxes near site centres are never settled this way.
  bool tiny_against_candidates(const Axis_box& box, const std::vector<Site_index>& candidates) const {
    Rounding_guard guard;
    Interval scaled_half_diagonal_squared(0);
    for (int a = 0; a < 3; ++a)
      scaled_half_diagonal_squared += CGAL::square((Interval(box.hi[a]) - Interval(box.lo[a])) * Interval(kTinyBox / 2));
    return std::all_of(candidates.begin(), candidates.end(), [&](Site_index s) {
      return (squared_distance_to_box<Interval>(sites_[s], box) - scaled_half_diagonal_squared).inf() > 0;
    });
  }

  // Halves the axes at least half as long as the longest; no children if some such axis has no double
  // strictly inside it.
  static std::vector<Axis_box> split(const Axis_box& box) {
    double longest = 0;
    for (int a = 0; a < 3; ++a) longest = std::max(longest, box.hi[a] - box.lo[a]);
    std::array<double, 3> middle;
    std::array<bool, 3> halve{};
    for (int a = 0; a < 3; ++a) {
      halve[a] = box.hi[a] - box.lo[a] >= longest / 2;
      middle[a] = box.lo[a] + (box.hi[a] - box.lo[a]) / 2;
      if (halve[a] && !(box.lo[a] < middle[a] && middle[a] < box.hi[a])) return {};
    }
    std::vector<Axis_box> children;
    for (int corner = 0; corner < 8; ++corner) {
      Axis_box child = box;
      bool valid = true;
      for (int a = 0; a < 3; ++a) {
        const bool upper = corner >> a & 1;
        if (!halve[a]) {
          valid = valid && !upper;
        } else {
          (upper ? child.lo[a] : child.hi[a]) = middle[a];
        }
      }
      if (valid) children.push_back(child);
    }
    return children;
  }

  // Every vertex located in the half-open leaf, with its tie set among the candidates (which include every
  // site owning a point of the box).
  void decide_leaf(const Axis_box& box, const std::vector<Site_index>& candidates, std::vector<Found_vertex>& out) const {
    const std::array<bool, 3> closed_above = {box.hi[0] == root_.hi[0], box.hi[1] == root_.hi[1], box.hi[2] == root_.hi[2]};
    decide_quadruples(sites_, candidates, candidates, [&](const Vertex& v) { return vertex_in_box(v, box, closed_above); },
                      out, out.size());
  }

  const std::vector<Site>& sites_;
  Axis_box root_;
};

struct Work_item {
  Axis_box box;
  const std::vector<Site_index>* candidates;
};

}  // namespace

Diagram octree_diagram(const std::vector<Site>& sites, const Octree_options& options) {
  std::vector<Hidden_site> hidden = classify_hidden_sites(sites);
  const std::vector<Site_index> active = active_sites(sites.size(), hidden);
  if (active.size() < 4) return assemble_diagram(sites.size(), std::move(hidden), {});

  const Seed_grid grid(sites, active);
  const std::vector<std::vector<Site_index>> cell_candidates = propagate_sites(sites, active, grid);

  // Step 2: the escaping sites own every point outside G (a segment from a centre inside G to a point
  // outside crosses a boundary cell), and bound the far field.
  std::vector<Site_index> escaping;
  for (std::size_t c = 0; c < grid.size(); ++c)
    if (grid.on_boundary(c)) escaping.insert(escaping.end(), cell_candidates[c].begin(), cell_candidates[c].end());
  std::sort(escaping.begin(), escaping.end());
  escaping.erase(std::unique(escaping.begin(), escaping.end()), escaping.end());

  // The root box: G and the ball about G's centre that the far-field analysis certifies, 2^10 times the
  // farthest site centre (its margins then only need to exceed ~|a| / 2^10).
  const Axis_box& g = grid.box();
  const std::array<double, 3> origin = {g.lo[0] + (g.hi[0] - g.lo[0]) / 2, g.lo[1] + (g.hi[1] - g.lo[1]) / 2,
                                        g.lo[2] + (g.hi[2] - g.lo[2]) / 2};
  double radius = 0;
  Axis_box root;
  {
    Rounding_guard guard;  // upward rounding: every bound below is rounded outwards
    for (int a = 0; a < 3; ++a) radius = std::max({radius, origin[a] - g.lo[a], g.hi[a] - origin[a]});
    radius = radius * 2 * kFarFieldScale;  // G's half-diagonal is at most twice its largest half-extent
    for (int a = 0; a < 3; ++a) root.lo[a] = -(radius - origin[a]), root.hi[a] = origin[a] + radius;
  }
  if (!std::isfinite(radius)) throw std::overflow_error("the far field of this input exceeds the double range");

  // The work: every seed cell, and the 26 boxes of the root around G.
  std::vector<Work_item> items;
  for (std::size_t c = 0; c < grid.size(); ++c)
    if (cell_candidates[c].size() >= 4) items.push_back({grid.cell_box(c), &cell_candidates[c]});
  for (int corner = 0; corner < 27; ++corner) {
    if (corner == 13) continue;  // G itself
    Axis_box b;
    int code = corner;
    for (int a = 0; a < 3; ++a, code /= 3) {
      const int part = code % 3;
      b.lo[a] = part == 0 ? root.lo[a] : part == 1 ? g.lo[a] : g.hi[a];
      b.hi[a] = part == 0 ? g.lo[a] : part == 1 ? g.hi[a] : root.hi[a];
    }
    if (b.lo[0] < b.hi[0] && b.lo[1] < b.hi[1] && b.lo[2] < b.hi[2]) items.push_back({b, &escaping});
  }

  const Box_refiner refiner(sites, root);
  std::vector<std::vector<Found_vertex>> found(items.size());
  std::vector<Found_vertex> vertices;
  tbb::task_arena arena(std::max(1, options.threads));  // every parallel step runs inside: --threads holds
  arena.execute([&] {
    tbb::parallel_for(std::size_t{0}, items.size(), [&](std::size_t w) {
      refiner.refine(items[w].box, *items[w].candidates, 0, 0, found[w]);
    });
    vertices = far_vertices(sites, escaping, origin, radius, root);
  });
  for (auto& f : found) std::move(f.begin(), f.end(), std::back_inserter(vertices));
  return assemble_diagram(sites.size(), std::move(hidden), std::move(vertices));
}

}  // namespace apollonius
