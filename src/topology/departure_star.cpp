#include "topology/departure_star.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "predicates/number_types.h"
#include "predicates/rounding_guard.h"

namespace apollonius {
namespace {

// Patches are refined at most this deep (squares of side 2^-15 of a face).
constexpr int kMaxDepth = 16;
// Levels without a removal before every triple of the survivors is recorded.
constexpr int kStagnation = 3;
// Past these, per site of the tie set, the star gives up.
constexpr std::size_t kPatchesPerSite = 256;
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

class Departure_star {
 public:
  Departure_star(const std::vector<Site_index>& tie_set, Tie_gradients gradients,
                 std::vector<std::array<Site_index, 3>>& triples)
      : tie_set_(tie_set), gradients_(std::move(gradients)), triples_(triples) {}

  bool refine(const Patch& p, const std::vector<std::size_t>& survivors) {
    if (++patches_ > kPatchesPerSite * tie_set_.size()) return false;
    std::vector<std::size_t> kept = survivors;
    {
      Rounding_guard guard;
      Direction y;
      y[p.axis] = Interval(p.side);
      y[(p.axis + 1) % 3] = Interval(p.s0, p.s1);
      y[(p.axis + 2) % 3] = Interval(p.t0, p.t1);
      std::array<double, 3> middle;
      middle[p.axis] = p.side;
      middle[(p.axis + 1) % 3] = p.s0 + (p.s1 - p.s0) / 2;
      middle[(p.axis + 2) % 3] = p.t0 + (p.t1 - p.t0) / 2;
      std::vector<std::pair<double, std::size_t>> order;  // doubles: only a choice of witnesses
      for (std::size_t c : kept) {
        double value = 0;
        for (int a = 0; a < 3; ++a) value += middle[a] * (gradients_[c][a].inf() + gradients_[c][a].sup()) / 2;
        order.push_back({value, c});
      }
      const std::size_t witnesses = std::min(order.size(), kWitnesses);
      std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(witnesses), order.end());
      for (std::size_t w = 0; w < witnesses && kept.size() > 3; ++w) {
        const std::size_t j = order[w].second;
        if (std::find(kept.begin(), kept.end(), j) == kept.end()) continue;
        std::size_t end = 0;
        for (std::size_t c : kept) {
          const Direction difference = {gradients_[c][0] - gradients_[j][0], gradients_[c][1] - gradients_[j][1],
                                        gradients_[c][2] - gradients_[j][2]};
          const bool beaten = c != j && dot(y, difference).inf() > 0;
          if (!beaten) kept[end++] = c;
        }
        kept.resize(end);
      }
    }
    if (kept.size() < 3) return true;  // no direction of the patch has three sites nearest
    const int stagnant = kept.size() == survivors.size() ? p.stagnant + 1 : 0;
    if (kept.size() == 3 || stagnant >= kStagnation || p.depth >= kMaxDepth) return record(kept);
    const double sm = p.s0 + (p.s1 - p.s0) / 2, tm = p.t0 + (p.t1 - p.t0) / 2;
    for (int q = 0; q < 4; ++q) {
      const Patch child{p.axis, p.side, q & 1 ? sm : p.s0, q & 1 ? p.s1 : sm, q & 2 ? tm : p.t0,
                        q & 2 ? p.t1 : tm, p.depth + 1, stagnant};
      if (!refine(child, kept)) return false;
    }
    return true;
  }

 private:
  bool record(const std::vector<std::size_t>& survivors) {
    const std::size_t k = survivors.size();
    if (triples_.size() + k * (k - 1) / 2 * (k - 2) / 3 > kTriplesPerSite * tie_set_.size()) return false;
    std::vector<Site_index> s;
    for (std::size_t c : survivors) s.push_back(tie_set_[c]);
    std::sort(s.begin(), s.end());
    for (std::size_t a = 0; a < k; ++a)
      for (std::size_t b = a + 1; b < k; ++b)
        for (std::size_t c = b + 1; c < k; ++c) triples_.push_back({s[a], s[b], s[c]});
    return true;
  }

  const std::vector<Site_index>& tie_set_;
  Tie_gradients gradients_;
  std::vector<std::array<Site_index, 3>>& triples_;
  std::size_t patches_ = 0;
};

}  // namespace

bool tie_gradients(const std::vector<Site>& sites, const Diagram_vertex& v, Tie_gradients& gradients) {
  const std::size_t k = v.tie_set.size();
  gradients.resize(k);
  Rounding_guard guard;
  const std::array<Interval, 4> p = v.vertex.point_interval();
  for (std::size_t c = 0; c < k; ++c) {
    const Site& s = sites[v.tie_set[c]];
    const Direction offset = {p[0] - Interval(s.x), p[1] - Interval(s.y), p[2] - Interval(s.z)};
    const Interval distance = CGAL::sqrt(dot(offset, offset));
    if (!(distance.inf() > 0) || !std::isfinite(distance.sup())) return false;  // v may be a centre
    for (int a = 0; a < 3; ++a) gradients[c][a] = offset[a] / distance;
  }
  return true;
}

bool candidate_departure_triples(const std::vector<Site>& sites, const Diagram_vertex& v,
                                 std::vector<std::array<Site_index, 3>>& triples) {
  triples.clear();
  Tie_gradients gradients;
  if (!tie_gradients(sites, v, gradients)) return false;
  Departure_star star(v.tie_set, std::move(gradients), triples);
  std::vector<std::size_t> all(v.tie_set.size());
  std::iota(all.begin(), all.end(), std::size_t{0});
  for (int face = 0; face < 6; ++face)
    if (!star.refine({face / 2, face % 2 ? 1.0 : -1.0, -1, 1, -1, 1, 0, 0}, all)) return false;
  std::sort(triples.begin(), triples.end());
  triples.erase(std::unique(triples.begin(), triples.end()), triples.end());
  return true;
}

}  // namespace apollonius
