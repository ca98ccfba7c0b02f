#include "octree/far_field.h"

#include <CGAL/FPU.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>
#include <type_traits>

#include "diagram/cancellable_steps.h"
#include "predicates/kernels.h"
#include "octree/leaf_decision.h"
#include "octree/lift_span.h"
#include "octree/lifted_triangulation.h"
#include "octree/lifted_vertices.h"

namespace apollonius {
namespace {

// Patches are refined at most this often (6 * 8^10 patches at the most, only where sites nearly tie at
// infinity). A patch whose kept sites stop changing for kStagnationLevels levels, with at most
// kStagnantSites of them, stops earlier: sites that tie at infinity (or beyond what the root box lets the
// bound see) are not separated by finer patches, and the whole diagram's search takes a few sites per
// patch as cheaply as fewer (twelve, as the octree's stagnant boxes), while the patches down to the depth
// limit would cost 4^7 per stagnant patch at depth 3.
constexpr int kMaxPatchDepth = 10;
constexpr int kDistanceDepth = 3;
constexpr int kStagnationLevels = 2;
constexpr std::size_t kStagnantSites = 12;
// Witnesses tried per patch (refine()).
constexpr int kWitnesses = 3;

// A patch is a box of the far region in the coordinates (y, tau): x = O + y / tau (far_field.h). Halving
// tau as well as the directions makes patches at finite distance bounded, so sites that own points only
// near R (a lattice face's lighter balls, whose cells end a few spacings above the face) are separated
// from those owning the points far away, as in the octree; the patch [0, tau1) reaches infinity.
struct Patch {
  int axis;     // the face of [-1, 1]^3: direction y with y[axis] = side
  double side;  // +1 or -1
  double s0, s1, t0, t1;  // the other two coordinates of y, in axis order
  double tau0, tau1;      // absolute, dyadic fractions of the root's bound (below): every point is in a leaf
  int depth;
  int stagnant;  // levels since the kept sites last changed
};

// The certified far field rounds its intervals outwards; the floating path (kernels.h) evaluates the same
// formulas in round-to-nearest, as plain doubles would. Either way the caller's mode comes back.
template <class Kernel>
struct Far_field_rounding {
  CGAL::Protect_FPU_rounding<true> protect{Kernel::rounds_outwards ? CGAL_FE_UPWARD : CGAL_FE_TONEAREST};
};

// CGAL's interval square root switches the rounding mode to downward and back to upward, which is right
// only under the certified guard: the floating path takes the square roots of its bounds, to nearest.
template <class Kernel>
Interval interval_sqrt(const Interval& x) {
  if constexpr (Kernel::rounds_outwards)
    return CGAL::sqrt(x);
  else
    return Interval(std::sqrt(std::max(x.inf(), 0.0)), std::sqrt(x.sup()));
}

template <class Kernel>
class Far_field {
 public:
  Far_field(const std::vector<Site>& sites, const std::array<double, 3>& origin, double radius,
            const Cancellation* cancellation)
      : sites_(sites), origin_(origin), radius_(radius), cancellation_(cancellation) {}

  // The root patches: a face of the direction cube, tau in [0, sqrt(3) / R] (|y| <= sqrt(3)).
  Patch root(int face) const {
    return {face / 2, face % 2 ? 1.0 : -1.0, -1, 1, -1, 1, 0, std::nextafter(std::sqrt(3.0) / radius_, INFINITY), 0, 0};
  }

  // Termination: each call either stops or recurses into 8 children one level deeper, and stops at
  // kMaxPatchDepth. Cost per patch: O(k kWitnesses) interval tests and an O(k log(sets)) lookup; the lift
  // span costs O(k log k) once per distinct set of kept sites (span_dimension).
  void refine(const Patch& p, const std::vector<Site_index>& candidates) {
    throw_if_cancelled(cancellation_);
    std::vector<Site_index> kept = candidates;
    {
      const Far_field_rounding<Kernel> rounding;
      const std::optional<Direction_box> directions = direction_box(p);
      if (!directions) return;  // no point of the patch lies outside R
      // A witness far from the others (a lone ball beside a small cluster) may tie with all of them, so
      // the next witness is the best of the sites it kept, up to kWitnesses of them.
      std::vector<Site_index> tried;
      for (int round = 0; round < kWitnesses && kept.size() > 3; ++round) {
        const std::optional<Site_index> w = witness(p, kept, tried);
        if (!w) break;
        tried.push_back(*w);
        remove_beaten(*directions, sites_[*w], kept);
      }
    }
    if (kept.size() <= 3) {
      if (kept.size() >= 2) record_sites(kept);
      return;
    }
    // Sites whose lifts span at most a plane (a lattice face of one weight, equal balls on one circle) have
    // no vertex among themselves (lift_outside_span.h), wherever they are: nothing to refine.
    if (span_dimension(kept) <= 2) {
      record_sites(kept);
      return;
    }
    const int stagnant = kept.size() == candidates.size() ? p.stagnant + 1 : 0;
    if (kept.size() == 4 || p.depth >= kMaxPatchDepth ||
        (stagnant >= kStagnationLevels && kept.size() <= kStagnantSites)) {
      record_sites(kept);
      return;
    }
    const double sm = p.s0 + (p.s1 - p.s0) / 2, tm = p.t0 + (p.t1 - p.t0) / 2, taum = p.tau0 + (p.tau1 - p.tau0) / 2;
    const int children = p.depth < kDistanceDepth ? 8 : 4;
    for (int q = 0; q < children; ++q)
      refine({p.axis, p.side, q & 1 ? sm : p.s0, q & 1 ? p.s1 : sm, q & 2 ? tm : p.t0, q & 2 ? p.t1 : tm,
              q & 4 ? taum : p.tau0, q & 4 ? p.tau1 : taum, p.depth + 1, stagnant},
             kept);
  }

  // Each run of patches keeping the same sites adds them once (duplicates are removed by far_vertices).
  void record_sites(const std::vector<Site_index>& kept) {
    if (patch_sites_.empty() || patch_sites_.back() != kept) patch_sites_.push_back(kept);
  }
  std::vector<std::vector<Site_index>> take_patch_sites() { return std::move(patch_sites_); }

 private:
  // The patch's directions y = (side, s, t) in face coordinates, and its tau within [0, |y| / R]
  // (far_field.h); none when the patch's tau all exceed |y| / R (its points are inside R).
  struct Direction_box {
    std::array<Interval, 3> y;
    Interval tau;
  };

  std::optional<Direction_box> direction_box(const Patch& p) const {
    Direction_box box;
    box.y[p.axis] = Interval(p.side);
    box.y[(p.axis + 1) % 3] = Interval(p.s0, p.s1);
    box.y[(p.axis + 2) % 3] = Interval(p.t0, p.t1);
    const Interval y_norm = interval_sqrt<Kernel>(CGAL::square(box.y[0]) + CGAL::square(box.y[1]) + CGAL::square(box.y[2]));
    const double outside = (y_norm / Interval(radius_)).sup();
    if (p.tau0 > outside) return std::nullopt;
    box.tau = Interval(p.tau0, std::min(p.tau1, outside));
    return box;
  }

  // Keeps the sites of `kept` that w may not beat everywhere in the patch's cone outside R.
  void remove_beaten(const Direction_box& directions, const Site& w, std::vector<Site_index>& kept) const {
    // The box of v = y - tau (p_w - O) over the patch.
    const std::array<Interval, 3>& y = directions.y;
    const Interval& tau = directions.tau;
    const std::array<Interval, 3> v = {y[0] - tau * (Interval(w.x) - Interval(origin_[0])),
                                       y[1] - tau * (Interval(w.y) - Interval(origin_[1])),
                                       y[2] - tau * (Interval(w.z) - Interval(origin_[2]))};
    const Interval v_norm = interval_sqrt<Kernel>(CGAL::square(v[0]) + CGAL::square(v[1]) + CGAL::square(v[2]));
    std::size_t end = 0;
    for (Site_index s : kept) {
      const Site& c = sites_[s];
      // (w_w - w_s) |v| + v.(p_w - p_s) > 0 on the whole box: s owns no point of the cone outside R.
      const Interval margin = (Interval(w.w) - Interval(c.w)) * v_norm + v[0] * (Interval(w.x) - Interval(c.x)) +
                              v[1] * (Interval(w.y) - Interval(c.y)) + v[2] * (Interval(w.z) - Interval(c.z));
      if (!(margin.inf() > 0)) kept[end++] = s;
    }
    kept.resize(end);
  }

  // The site of `kept` not yet tried that looks nearest at the patch's middle: at the point O + y / tau
  // for a patch at finite distance, else far away in the middle direction y (the largest y.p + w |y|).
  // Only a choice (plain doubles), the latter compared by differences p_k - p_best so that a small cluster
  // far from O is still ordered; every removal is certified in remove_beaten().
  std::optional<Site_index> witness(const Patch& p, const std::vector<Site_index>& kept,
                                    const std::vector<Site_index>& tried) const {
    std::array<double, 3> y;
    y[p.axis] = p.side;
    y[(p.axis + 1) % 3] = p.s0 + (p.s1 - p.s0) / 2;
    y[(p.axis + 2) % 3] = p.t0 + (p.t1 - p.t0) / 2;
    const double y_norm = std::sqrt(y[0] * y[0] + y[1] * y[1] + y[2] * y[2]);
    const double tau = p.tau0 + (p.tau1 - p.tau0) / 2;
    const std::array<double, 3> x = {origin_[0] + y[0] / tau, origin_[1] + y[1] / tau, origin_[2] + y[2] / tau};
    const auto distance = [&](const Site& s) {
      return std::sqrt((x[0] - s.x) * (x[0] - s.x) + (x[1] - s.y) * (x[1] - s.y) + (x[2] - s.z) * (x[2] - s.z)) - s.w;
    };
    std::optional<Site_index> best;
    double best_distance = 0;
    for (Site_index k : kept) {
      if (std::find(tried.begin(), tried.end(), k) != tried.end()) continue;
      if (!best) {
        best = k, best_distance = distance(sites_[k]);
        continue;
      }
      const Site& a = sites_[k];
      const Site& b = sites_[*best];
      if (p.tau0 > 0) {
        const double d = distance(a);
        if (d < best_distance) best = k, best_distance = d;
      } else if (y[0] * (a.x - b.x) + y[1] * (a.y - b.y) + y[2] * (a.z - b.z) + (a.w - b.w) * y_norm > 0) {
        best = k;
      }
    }
    return best;
  }

  const std::vector<Site>& sites_;
  // The dimension of the lifts' span of each set of kept sites met so far (heaviest_lift_basis). Patches
  // keep few distinct sets, but not in runs: sibling patches alternate between two or three, and
  // recomputing at each change made 1,895 exact power-lift tests for 11 sites
  // (tests/data/regression/far_field_span_recomputed_for_alternating_patches.balls). Cleared when it
  // reaches kRememberedSpans sets, so its memory stays bounded.
  static constexpr std::size_t kRememberedSpans = 4096;
  std::map<std::vector<Site_index>, int> span_dimensions_;
  int span_dimension(const std::vector<Site_index>& kept) {
    const auto found = span_dimensions_.find(kept);
    if (found != span_dimensions_.end()) return found->second;
    if (span_dimensions_.size() >= kRememberedSpans) span_dimensions_.clear();
    std::array<Site_index, 4> basis;
    const int dimension = heaviest_lift_basis<Kernel>(sites_, kept.begin(), kept.end(), basis);
    span_dimensions_.emplace(kept, dimension);
    return dimension;
  }
  std::array<double, 3> origin_;
  double radius_;
  const Cancellation* cancellation_;
  std::vector<std::vector<Site_index>> patch_sites_;
};

}  // namespace

template <class Kernel>
Far_field_vertices far_vertices(const std::vector<Site>& sites, const std::vector<Site_index>& escaping,
                                const std::array<double, 3>& origin, double radius, const Axis_box& root,
                                bool with_patch_sites, const Cancellation* cancellation) {
  if (escaping.size() < 4) {
    Far_field_vertices none;
    if (escaping.size() >= 2) none.patch_sites.push_back(escaping);
    return none;
  }
  // Candidate quadruples: the 3-faces of the escaping sites' lifted triangulation, which cover every vertex
  // (lifted_triangulation.h): O(E log E) for E escaping sites, whatever their ties at infinity.
  const Lifted_triangulation lifts = lifted_triangulation(sites, escaping, cancellation);
  std::vector<std::vector<Site_index>> patch_sites;
  if (with_patch_sites) {
    std::vector<std::vector<std::vector<Site_index>>> sites_by_face(6);
    tbb::parallel_for(0, 6, [&](int face) {
      Far_field<Kernel> field(sites, origin, radius, cancellation);
      field.refine(field.root(face), escaping);
      sites_by_face[face] = field.take_patch_sites();
    });
    for (auto& face : sites_by_face)
      for (auto& kept : face) patch_sites.push_back(std::move(kept));
    cancellable_sort(patch_sites.begin(), patch_sites.end(), cancellation);
    patch_sites.erase(std::unique(patch_sites.begin(), patch_sites.end()), patch_sites.end());
  }

  // Each vertex outside the closed root box, decided exactly against the escaping sites (which own every
  // point there), with its tie set among them through the lifts' edges.
  std::vector<Found_vertex> vertices = lifted_vertices<Kernel>(
      sites, lifts, [&](const Vertex& v) { return !Kernel::in_box(v, root, std::array<bool, 3>{true, true, true}); },
      cancellation);
  return {std::move(vertices), lifts.quadruples.size(), std::move(patch_sites)};
}

template Far_field_vertices far_vertices<Certified_kernel>(const std::vector<Site>&, const std::vector<Site_index>&,
                                                          const std::array<double, 3>&, double, const Axis_box&, bool,
                                                          const Cancellation*);
template Far_field_vertices far_vertices<Floating_kernel>(const std::vector<Site>&, const std::vector<Site_index>&,
                                                         const std::array<double, 3>&, double, const Axis_box&, bool,
                                                         const Cancellation*);

}  // namespace apollonius
