#include "measure/contact_measures.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <stdexcept>
#include <unordered_map>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "diagram/threads.h"
#include "diagram/site_set.h"
#include "measure/cell_cubature.h"
#include "measure/cut_candidates.h"
#include "measure/exit_regions.h"
#include "predicates/kernels.h"

namespace apollonius {
namespace {

// Sites whose probe-grown balls (radius w + P) may meet, by a grid of side 2 max(w + P): two such balls
// that meet have centres at most that far apart, so in neighbouring grid cells.
class Ball_grid {
 public:
  Ball_grid(const std::vector<Site>& sites, const std::vector<Site_index>& members, double probe) {
    double largest = 0;
    for (Site_index i : members) largest = std::max(largest, sites[i].w + probe);
    side_ = 2 * largest;
    for (Site_index i : members) cells_[key(cell_of(sites[i]))].push_back(i);
  }

  // Calls f(j) once for every member j in the 27 grid cells around site s (j = s included). Cells clamped
  // together (far sites) can make two of the 27 keys equal: each key is visited once.
  template <class F>
  void near(const Site& s, F&& f) const {
    const std::array<std::int64_t, 3> c = cell_of(s);
    std::array<std::uint64_t, 27> keys;
    int count = 0;
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz) keys[count++] = key({c[0] + dx, c[1] + dy, c[2] + dz});
    std::sort(keys.begin(), keys.end());
    for (int k = 0; k < count; ++k) {
      if (k > 0 && keys[k] == keys[k - 1]) continue;
      const auto found = cells_.find(keys[k]);
      if (found == cells_.end()) continue;
      for (Site_index j : found->second) f(j);
    }
  }

 private:
  // Grid coordinates are clamped to [-2^20, 2^20 - 1] (far sites then share cells, which costs time, not
  // answers), so that the key packs them exactly: distinct cells never share a key.
  static constexpr std::int64_t kLimit = std::int64_t{1} << 20;
  std::array<std::int64_t, 3> cell_of(const Site& s) const {
    const auto index = [&](double x) {
      const double q = side_ > 0 ? std::floor(x / side_) : 0;
      return static_cast<std::int64_t>(std::clamp(q, -static_cast<double>(kLimit), static_cast<double>(kLimit - 1)));
    };
    return {index(s.x), index(s.y), index(s.z)};
  }
  static std::uint64_t key(const std::array<std::int64_t, 3>& c) {
    std::uint64_t k = 0;
    for (std::int64_t v : c) k = (k << 21) | static_cast<std::uint64_t>(std::clamp(v, -kLimit, kLimit - 1) + kLimit);
    return k;
  }

  double side_ = 0;
  std::unordered_map<std::uint64_t, std::vector<Site_index>> cells_;  // by key(): one entry per grid cell
};

}  // namespace

Contact_measures measure_contacts(const std::vector<Site>& sites, const Contact_options& options) {
  if (!(options.probe >= 0) || !std::isfinite(options.probe))
    throw std::invalid_argument("the probe must be a finite number >= 0");
  if (!(options.relative_tolerance > 0 && options.relative_tolerance <= 0.5))
    throw std::invalid_argument("the tolerance must lie in (0, 0.5]");
  const std::size_t n = sites.size();
  Contact_measures result;
  result.hidden = classify_hidden_sites<Certified_kernel>(sites, options.cancellation);
  std::vector<bool> active(n, true);
  for (const Hidden_site& h : result.hidden) active[h.site] = false;
  // Only balls with w + P > 0 have a clipped cell; only they can cut one (at a cut, d_j = d_i <= P).
  std::vector<Site_index> members;
  for (Site_index i = 0; i < n; ++i)
    if (active[i] && sites[i].w + options.probe > 0) members.push_back(i);
  const Ball_grid grid(sites, members, options.probe);

  result.sas.assign(n, 0), result.sas_error.assign(n, 0), result.volume.assign(n, 0), result.volume_error.assign(n, 0);
  std::vector<std::vector<Cell_measure::Face_area>> faces(n);
  std::vector<std::size_t> directions(n, 0);
  tbb::task_arena arena(usable_threads(options.threads));
  arena.execute([&] {
    tbb::parallel_for(std::size_t{0}, members.size(), [&](std::size_t m) {
      throw_if_cancelled(options.cancellation);
      const Site_index i = members[m];
      const Site& s = sites[i];
      const double radius = s.w + options.probe;
      // Every site that can cut a ray within the clip: j beats i at distance t only if |D| - alpha <= 2 t,
      // so |x_i - x_j| <= (w_i + P) + (w_j + P). The rest cuts nowhere below the clip: clearance infinite.
      Cut_candidates candidates;
      candidates.clearance.fill(std::numeric_limits<double>::infinity());
      grid.near(s, [&](Site_index j) {
        if (j == i) return;
        const Site& o = sites[j];
        const double dx = s.x - o.x, dy = s.y - o.y, dz = s.z - o.z;
        const double reach = (radius + o.w + options.probe) * (1 + kClearanceMargin);
        if (dx * dx + dy * dy + dz * dz <= reach * reach) candidates.cuts.push_back(Radial_cut::between(s, o, j));
      });
      for (const Radial_cut& cut : candidates.cuts)
        if (too_close_to_measure(cut, radius)) throw Unmeasurable_pair(i, cut.site);
      std::sort(candidates.cuts.begin(), candidates.cuts.end(),
                [](const Radial_cut& x, const Radial_cut& y) { return x.site < y.site; });
      // A box twice the clip's size: its planes are never the nearest exit.
      const Axis_box box = box_beyond(s, 2 * radius);
      Cell_cubature_options cubature;
      cubature.relative_tolerance = options.relative_tolerance;
      cubature.clip_radius = radius;
      cubature.cancellation = options.cancellation;
      cubature.median_integrals = false;
      const Cell_cubature_result cell = integrate_cell(s, candidates, box, cubature);
      if (cell.clearance_exceeded) throw std::logic_error("measure_contacts: a clipped cell exceeded its clearance");
      const Cell_measure& measure = cell.measure;
      result.sas[i] = measure.sphere_area, result.sas_error[i] = measure.sphere_area_error;
      result.volume[i] = measure.volume, result.volume_error[i] = measure.volume_error;
      faces[i] = measure.contact_areas;
      directions[i] = measure.directions;
    });
  });
  // Both sides of each face, merged.
  std::map<std::pair<Site_index, Site_index>, std::array<double, 4>> pairs;  // area and error from a, from b
  for (Site_index i = 0; i < n; ++i) {
    result.directions += directions[i];
    for (const Cell_measure::Face_area& f : faces[i]) {
      const bool low = i < f.site;
      std::array<double, 4>& p = pairs[{std::min(i, f.site), std::max(i, f.site)}];
      p[low ? 0 : 2] = f.area, p[low ? 1 : 3] = f.error;
    }
  }
  for (const auto& [key, p] : pairs) {
    const double area = 0.5 * (p[0] + p[2]);
    if (!(area > 0)) continue;
    result.contacts.push_back({key.first, key.second, area, 0.5 * (p[1] + p[3]) + 0.5 * std::fabs(p[0] - p[2])});
  }
  return result;
}

}  // namespace apollonius
