#include "topology/departure_star.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <set>

#include "predicates/number_types.h"
#include "predicates/rounding_guard.h"
#include "predicates/trisector.h"
#include "predicates/trisector_predicates.h"

namespace apollonius {
namespace {

// Patches are refined at most this deep (squares of side 2^-15 of a face).
constexpr int kMaxDepth = 16;
// Levels without a removal before the survivors are settled (settle_first_order_tie, settle_second_order_tie).
constexpr int kStagnation = 3;
// Past these, per site of the tie set, the star gives up.
constexpr std::size_t kPatchesPerSite = 4096;
constexpr std::size_t kTriplesPerSite = 64;
// Survivors least in y.n at a patch's middle, each tried as the site that beats the others.
constexpr std::size_t kWitnesses = 3;

using Direction = std::array<Interval, 3>;  // as Tie_gradients' entries

Interval dot(const Direction& a, const Direction& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

struct Patch {
  int axis;     // the face of [-1, 1]^3: y[axis] = side
  double side;  // +1 or -1
  double s0, s1, t0, t1;  // the other two coordinates of y, in axis order
  int depth;
  int stagnant;  // levels since a site was last removed
};

// smallest_curve_unless's test for sites tied to first order along a curve: apart unless its first order is 0.
bool apart_to_first_order(Sign after, Sign before) { return after != Sign::ZERO && before == -after; }

// The star of one vertex: refines patches of directions y for points P_k (the gradients n_k, then, within
// a cocircular set, the second-order lifts), keeping the sites that minimise y.P_k somewhere in the patch.
class Departure_star {
 public:
  Departure_star(const std::vector<Site>& sites, const Diagram_vertex& v, Tie_gradients gradients,
                 std::vector<Interval> inverse_distances, std::vector<std::array<Site_index, 3>>& triples)
      : sites_(sites),
        v_(v),
        gradients_(std::move(gradients)),
        inverse_distances_(std::move(inverse_distances)),
        triples_(triples) {}

  bool run() {
    std::vector<std::size_t> all(v_.tie_set.size());
    std::iota(all.begin(), all.end(), std::size_t{0});
    // Every n_k on one circle (balls tangent to one circle): three of them tie to first order only along its
    // axis, where all do, so the first star would find just that, refining toward the axis through
    // O(k^2 log) patches whose few survivors tie nowhere else (docs/benchmarks.md). Settled at once. Tied
    // sites have distinct n_k: two on one ray from v would be nested tangent balls, one of them hidden.
    if (all.size() > 3)
      if (const std::optional<std::array<std::size_t, 3>> smallest = smallest_curve_unless(all, apart_to_first_order))
        return settle_cocircular(all, *smallest);
    for (int face = 0; face < 6; ++face)
      if (!refine(gradients_, Order::first, {face / 2, face % 2 ? 1.0 : -1.0, -1, 1, -1, 1, 0, 0}, all))
        return false;
    return true;
  }

 private:
  enum class Order { first, second };

  bool refine(const Tie_gradients& points, Order order, const Patch& p, const std::vector<std::size_t>& survivors) {
    if (++patches_ > kPatchesPerSite * v_.tie_set.size()) return false;
    std::vector<std::size_t> kept = survivors;
    {
      Rounding_guard guard;
      Direction y;
      y[p.axis] = Interval(p.side);
      y[(p.axis + 1) % 3] = Interval(p.s0, p.s1);
      y[(p.axis + 2) % 3] = Interval(p.t0, p.t1);
      // A lower facet of the lifts has a supporting plane from below: y's last coordinate is positive.
      if (order == Order::second && y[2].sup() <= 0) return true;
      std::array<double, 3> middle;
      middle[p.axis] = p.side;
      middle[(p.axis + 1) % 3] = p.s0 + (p.s1 - p.s0) / 2;
      middle[(p.axis + 2) % 3] = p.t0 + (p.t1 - p.t0) / 2;
      std::vector<std::pair<double, std::size_t>> order_at_middle;  // doubles: only a choice of witnesses
      for (std::size_t c : kept) {
        double value = 0;
        for (int a = 0; a < 3; ++a) value += middle[a] * (points[c][a].inf() + points[c][a].sup()) / 2;
        order_at_middle.push_back({value, c});
      }
      const std::size_t witnesses = std::min(order_at_middle.size(), kWitnesses);
      std::partial_sort(order_at_middle.begin(), order_at_middle.begin() + static_cast<std::ptrdiff_t>(witnesses),
                        order_at_middle.end());
      for (std::size_t w = 0; w < witnesses && kept.size() > 3; ++w) {
        const std::size_t j = order_at_middle[w].second;
        if (std::find(kept.begin(), kept.end(), j) == kept.end()) continue;
        std::size_t end = 0;
        for (std::size_t c : kept) {
          const Direction difference = {points[c][0] - points[j][0], points[c][1] - points[j][1],
                                        points[c][2] - points[j][2]};
          const bool beaten = c != j && dot(y, difference).inf() > 0;
          if (!beaten) kept[end++] = c;
        }
        kept.resize(end);
      }
    }
    if (kept.size() < 3) return true;  // no direction of the patch has three sites nearest
    if (kept.size() == 3) return record(kept);
    const int stagnant = kept.size() == survivors.size() ? p.stagnant + 1 : 0;
    if (stagnant >= kStagnation || p.depth >= kMaxDepth)
      return order == Order::first ? settle_first_order_tie(kept) : settle_second_order_tie(kept);
    const double sm = p.s0 + (p.s1 - p.s0) / 2, tm = p.t0 + (p.t1 - p.t0) / 2;
    for (int q = 0; q < 4; ++q) {
      const Patch child{p.axis, p.side, q & 1 ? sm : p.s0, q & 1 ? p.s1 : sm, q & 2 ? tm : p.t0,
                        q & 2 ? p.t1 : tm, p.depth + 1, stagnant};
      if (!refine(points, order, child, kept)) return false;
    }
    return true;
  }

  // Survivors that first order does not separate. If they are exactly cocircular (each ties to first order
  // along the curve of three of them, sides_near_vertex), an edge of them leaves along the circle's axis nu
  // and, with x(s) = v + s nu + s^2 kappa / 2 on it, d_k(x(s)) = d(v) + s c + s^2 (kappa.n_k + (1 - c^2) / D_k) / 2
  // (c = nu.n_k, D_k = |v - p_k|); writing n_j as an affine combination of T's n_a, n_b, n_c, kappa cancels:
  // j is farther than T to second order where 1 / D_j lies above the plane through T's lifts
  // (n_k, 1 / D_k). So T is a lower facet of the lifts, which a second star over them finds, the lifts
  // projected to the plane along an axis where nu is certainly not 0 (an affine bijection of the circle's
  // plane keeps the lower facets). Otherwise every triple of the survivors.
  // A survivor set is settled once: patches that meet at the circle's axis (a corner of theirs where the
  // axis is a coordinate axis, as for balls tangent to a circle in a coordinate plane) keep the same sites,
  // and the second star depends on them alone.
  bool settle_first_order_tie(const std::vector<std::size_t>& survivors) {
    if (!settled_.insert(survivors).second) return true;
    const std::optional<std::array<std::size_t, 3>> smallest = smallest_curve_unless(survivors, apart_to_first_order);
    if (!smallest) return record(survivors);
    return settle_cocircular(survivors, *smallest);
  }

  // The second star, for survivors whose n_k lie on the circle of their smallest triple's.
  bool settle_cocircular(const std::vector<std::size_t>& survivors, const std::array<std::size_t, 3>& smallest) {
    Tie_gradients lifts(gradients_.size());
    {
      Rounding_guard guard;
      const Direction& a = gradients_[smallest[0]];
      const Direction& b = gradients_[smallest[1]];
      const Direction& c = gradients_[smallest[2]];
      const Direction u = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
      const Direction axis_normal = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
      int axis = -1;
      double clearance = 0;
      for (int i = 0; i < 3; ++i) {
        const Interval x = axis_normal[i];
        const double apart = x.inf() > 0 ? x.inf() : x.sup() < 0 ? -x.sup() : 0;
        if (apart > clearance) axis = i, clearance = apart;
      }
      if (axis < 0) return record(survivors);
      for (std::size_t k : survivors)
        lifts[k] = {gradients_[k][(axis + 1) % 3], gradients_[k][(axis + 2) % 3], inverse_distances_[k]};
    }
    for (int face = 0; face < 6; ++face)
      if (!refine(lifts, Order::second, {face / 2, face % 2 ? 1.0 : -1.0, -1, 1, -1, 1, 0, 0}, survivors))
        return false;
    return true;
  }

  // Survivors that second order does not separate either. If all tie along the whole curve of their
  // smallest triple, that curve is every one of their triples' trisector and its edge (tie set: these
  // survivors, as a site tied along it ties to first and second order) is counted from that triple alone.
  // Otherwise every triple of them.
  bool settle_second_order_tie(const std::vector<std::size_t>& survivors) {
    const auto not_tied = [](Sign after, Sign before) { return after != Sign::ZERO || before != Sign::ZERO; };
    const std::optional<std::array<std::size_t, 3>> smallest = smallest_curve_unless(survivors, not_tied);
    if (!smallest) return record(survivors);
    triples_.push_back({v_.tie_set[(*smallest)[0]], v_.tie_set[(*smallest)[1]], v_.tie_set[(*smallest)[2]]});
    return true;
  }

  // The positions in the tie set (ascending, so its sites are ascending too) of the survivors' smallest
  // triple, if its trisector is a curve and no other survivor's sides along it near v (sides_near_vertex)
  // make `rejects` true; else nothing.
  template <class Rejects>
  std::optional<std::array<std::size_t, 3>> smallest_curve_unless(const std::vector<std::size_t>& survivors,
                                                                  Rejects rejects) const {
    std::vector<std::size_t> s(survivors);
    std::partial_sort(s.begin(), s.begin() + 3, s.end());
    const std::array<std::size_t, 3> smallest = {s[0], s[1], s[2]};
    const std::array<Site_index, 3> triple = {v_.tie_set[s[0]], v_.tie_set[s[1]], v_.tie_set[s[2]]};
    const Trisector trisector(triple, {sites_[triple[0]], sites_[triple[1]], sites_[triple[2]]});
    const Trisector_kind kind = classify_trisector(trisector).first;
    if (kind != Trisector_kind::ellipse && kind != Trisector_kind::hyperbola && kind != Trisector_kind::parabola)
      return std::nullopt;
    for (auto c = s.begin() + 3; c != s.end(); ++c) {
      const auto [after, before] = sides_near_vertex(trisector, v_.vertex, sites_[v_.tie_set[*c]]);
      if (rejects(after, before)) return std::nullopt;
    }
    return smallest;
  }

  bool record(const std::vector<std::size_t>& survivors) {
    const std::size_t k = survivors.size();
    const std::size_t count = k * (k - 1) / 2 * (k - 2) / 3;  // C(k, 3), exact at each step
    const std::size_t cap = kTriplesPerSite * v_.tie_set.size();
    if (triples_.size() + count > cap) {  // neighbouring patches record the same triples: count each once
      std::sort(triples_.begin(), triples_.end());
      triples_.erase(std::unique(triples_.begin(), triples_.end()), triples_.end());
      if (triples_.size() + count > cap) return false;
    }
    std::vector<Site_index> s;
    for (std::size_t c : survivors) s.push_back(v_.tie_set[c]);
    std::sort(s.begin(), s.end());
    for (std::size_t a = 0; a < k; ++a)
      for (std::size_t b = a + 1; b < k; ++b)
        for (std::size_t c = b + 1; c < k; ++c) triples_.push_back({s[a], s[b], s[c]});
    return true;
  }

  const std::vector<Site>& sites_;
  const Diagram_vertex& v_;
  Tie_gradients gradients_;
  std::vector<Interval> inverse_distances_;  // per site of the tie set: encloses 1 / D_k = 1 / |v - p_k|
  std::vector<std::array<Site_index, 3>>& triples_;
  std::size_t patches_ = 0;
  std::set<std::vector<std::size_t>> settled_;  // survivor sets settled to first order (ascending, as all kept)
};

}  // namespace

bool tie_gradients(const std::vector<Site>& sites, const Diagram_vertex& v, Tie_gradients& gradients,
                   std::vector<Interval>* inverse_distances) {
  const std::size_t k = v.tie_set.size();
  gradients.resize(k);
  if (inverse_distances != nullptr) inverse_distances->resize(k);
  Rounding_guard guard;
  const std::array<Interval, 4> p = v.vertex.point_interval();
  for (std::size_t c = 0; c < k; ++c) {
    const Site& s = sites[v.tie_set[c]];
    const Direction offset = {p[0] - Interval(s.x), p[1] - Interval(s.y), p[2] - Interval(s.z)};
    const Interval distance = CGAL::sqrt(dot(offset, offset));
    if (!(distance.inf() > 0) || !std::isfinite(distance.sup())) return false;  // v may be a centre
    for (int a = 0; a < 3; ++a) gradients[c][a] = offset[a] / distance;
    if (inverse_distances != nullptr) (*inverse_distances)[c] = Interval(1) / distance;
  }
  return true;
}

bool candidate_departure_triples(const std::vector<Site>& sites, const Diagram_vertex& v,
                                 std::vector<std::array<Site_index, 3>>& triples) {
  triples.clear();
  Tie_gradients gradients;
  std::vector<Interval> inverse_distances;
  if (!tie_gradients(sites, v, gradients, &inverse_distances)) return false;
  Departure_star star(sites, v, std::move(gradients), std::move(inverse_distances), triples);
  if (!star.run()) return false;
  std::sort(triples.begin(), triples.end());
  triples.erase(std::unique(triples.begin(), triples.end()), triples.end());
  return true;
}

}  // namespace apollonius
