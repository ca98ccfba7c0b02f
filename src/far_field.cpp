#include "far_field.h"

#include <CGAL/FPU.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "kernels.h"
#include "leaf_decision.h"

namespace apollonius {
namespace {

// Patches are refined at most this often (6 * 4^10 patches at the most, only where sites nearly tie at
// infinity). A patch whose kept sites stop changing for kStagnationLevels levels, with at most
// kStagnantSites of them, stops earlier: sites that tie at infinity (or beyond what the root box lets the
// bound see) are not separated by finer patches, and their quadruples are decided anyway.
constexpr int kMaxPatchDepth = 10;
constexpr int kStagnationLevels = 2;
constexpr std::size_t kStagnantSites = 8;

struct Patch {
  int axis;     // the face of [-1, 1]^3: direction y with y[axis] = side
  double side;  // +1 or -1
  double s0, s1, t0, t1;  // the other two coordinates of y, in axis order
  int depth;
  int stagnant;  // levels since the kept sites last changed
};

using Quadruple_key = std::array<Site_index, 4>;

// a = p - O, |a|^2 and |a| of an escaping site.
struct Offset {
  std::array<Interval, 3> a;
  Interval norm_squared, norm;
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
  Far_field(const std::vector<Site>& sites, const std::vector<Site_index>& escaping, const std::array<double, 3>& origin,
            double radius, const Axis_box& root)
      : sites_(sites), escaping_(escaping), radius_(radius), root_(root), offsets_(sites.size()) {
    const Far_field_rounding<Kernel> rounding;
    for (Site_index i : escaping) {
      Offset& o = offsets_[i];
      o.a = {Interval(sites[i].x) - Interval(origin[0]), Interval(sites[i].y) - Interval(origin[1]),
             Interval(sites[i].z) - Interval(origin[2])};
      o.norm_squared = CGAL::square(o.a[0]) + CGAL::square(o.a[1]) + CGAL::square(o.a[2]);
      o.norm = interval_sqrt<Kernel>(o.norm_squared);
    }
  }

  void refine(const Patch& p, const std::vector<Site_index>& candidates) {
    std::vector<Site_index> kept;
    {
      const Far_field_rounding<Kernel> rounding;
      // u.a + w over the directions of the patch: y = (side, s, t) in face coordinates, u = y / |y|.
      const int first = (p.axis + 1) % 3, second = (p.axis + 2) % 3;
      const Interval S(p.s0, p.s1), T(p.t0, p.t1);
      const Interval norm = interval_sqrt<Kernel>(Interval(1) + CGAL::square(S) + CGAL::square(T));
      // Over the patch, u.a for an offset a; the witness is the site whose support u.a + w is largest at
      // the patch's middle direction. Margins are taken on differences, u.(a_j - a_k) + w_j - w_k, whose
      // interval is as wide as |a_j - a_k| times the patch, not |a_j| + |a_k|.
      auto projection = [&](const std::array<Interval, 3>& a) {
        return (Interval(p.side) * a[p.axis] + S * a[first] + T * a[second]) / norm;
      };
      const double middle[3] = {p.side, p.s0 + (p.s1 - p.s0) / 2, p.t0 + (p.t1 - p.t0) / 2};
      std::size_t best = 0;
      double best_support = -std::numeric_limits<double>::infinity();
      for (std::size_t k = 0; k < candidates.size(); ++k) {
        const Offset& o = offsets_[candidates[k]];
        const double support = middle[0] * o.a[p.axis].inf() + middle[1] * o.a[first].inf() +
                               middle[2] * o.a[second].inf() + sites_[candidates[k]].w * std::sqrt(1 + middle[1] * middle[1] + middle[2] * middle[2]);
        if (support > best_support) best_support = support, best = k;
      }
      const Site_index w = candidates[best];
      const Offset& witness = offsets_[w];
      // q_j = |a_j|^2 - (u.a_j)^2 over the patch, at least 0.
      const double witness_spread = std::max(0.0, (witness.norm_squared - CGAL::square(projection(witness.a))).sup());
      for (std::size_t k = 0; k < candidates.size(); ++k) {
        const Site_index s = candidates[k];
        bool removed = false;
        if (k != best) {
          const std::array<Interval, 3> difference = {witness.a[0] - offsets_[s].a[0], witness.a[1] - offsets_[s].a[1],
                                                      witness.a[2] - offsets_[s].a[2]};
          const Interval margin = projection(difference) + (Interval(sites_[w].w) - Interval(sites_[s].w));
          removed = margin.inf() > 0 && leaves_within_radius(witness, witness_spread, margin.inf());
        }
        if (!removed) kept.push_back(s);
      }
    }
    if (kept.size() <= 3) return;
    const int stagnant = kept.size() == candidates.size() ? p.stagnant + 1 : 0;
    if (kept.size() == 4 || p.depth >= kMaxPatchDepth ||
        (stagnant >= kStagnationLevels && kept.size() <= kStagnantSites)) {
      record_quadruples(kept);
      return;
    }
    const double sm = p.s0 + (p.s1 - p.s0) / 2, tm = p.t0 + (p.t1 - p.t0) / 2;
    for (int q = 0; q < 4; ++q)
      refine({p.axis, p.side, q & 1 ? sm : p.s0, q & 1 ? p.s1 : sm, q & 2 ? tm : p.t0, q & 2 ? p.t1 : tm, p.depth + 1,
              stagnant},
             kept);
  }

  std::vector<Quadruple_key> take_quadruples() { return std::move(quadruples_); }

 private:
  // Whether a site beaten by margin m owns no point of the cone beyond the root box's inscribed ball:
  // |a_j| + q_j / (2 m) <= radius, for the witness j. A spread that overflowed bounds nothing: the site stays.
  bool leaves_within_radius(const Offset& witness, double witness_spread, double margin) const {
    if (!std::isfinite(witness_spread)) return false;
    return (witness.norm + Interval(witness_spread) / (Interval(2) * Interval(margin))).sup() <= radius_;
  }

  // Every vertex outside the root box in this patch's cone has its tie set among `kept`, so it is a vertex
  // of one of their quadruples (sorted; kept is ascending).
  void record_quadruples(const std::vector<Site_index>& kept) {
    const std::size_t k = kept.size();
    for (std::size_t a = 0; a < k; ++a)
      for (std::size_t b = a + 1; b < k; ++b)
        for (std::size_t c = b + 1; c < k; ++c)
          for (std::size_t d = c + 1; d < k; ++d) quadruples_.push_back({kept[a], kept[b], kept[c], kept[d]});
  }

  const std::vector<Site>& sites_;
  const std::vector<Site_index>& escaping_;
  double radius_;
  Axis_box root_;
  std::vector<Offset> offsets_;
  std::vector<Quadruple_key> quadruples_;
};

}  // namespace

template <class Kernel>
std::vector<Found_vertex> far_vertices(const std::vector<Site>& sites, const std::vector<Site_index>& escaping,
                                       const std::array<double, 3>& origin, double radius, const Axis_box& root) {
  if (escaping.size() < 4) return {};
  // The six faces of the direction cube are refined independently; neighbouring patches share most of
  // their quadruples, so those are collected first and each is decided once.
  std::vector<std::vector<Quadruple_key>> by_face(6);
  tbb::parallel_for(0, 6, [&](int face) {
    Far_field<Kernel> field(sites, escaping, origin, radius, root);
    field.refine({face / 2, face % 2 ? 1.0 : -1.0, -1, 1, -1, 1, 0, 0}, escaping);
    by_face[face] = field.take_quadruples();
  });
  std::vector<Quadruple_key> quadruples;
  for (const auto& face : by_face) quadruples.insert(quadruples.end(), face.begin(), face.end());
  std::sort(quadruples.begin(), quadruples.end());
  quadruples.erase(std::unique(quadruples.begin(), quadruples.end()), quadruples.end());

  // Each vertex outside the closed root box, decided exactly against the escaping sites (which own every
  // point there), with its tie set among them.
  std::vector<std::vector<Found_vertex>> found(quadruples.size());
  tbb::parallel_for(std::size_t{0}, quadruples.size(), [&](std::size_t q) {
    const std::vector<Site_index> quadruple(quadruples[q].begin(), quadruples[q].end());
    decide_quadruples<Kernel>(sites, quadruple, escaping,
                              [&](const Vertex& v) { return !Kernel::in_box(v, root, std::array<bool, 3>{true, true, true}); },
                              found[q], 0);
  });
  // A vertex with five or more tied sites is found from several of their quadruples: kept once.
  std::vector<Found_vertex> vertices;
  for (auto& list : found)
    for (Found_vertex& f : list) vertices.push_back(std::move(f));
  std::stable_sort(vertices.begin(), vertices.end(), [](const Found_vertex& x, const Found_vertex& y) { return x.first < y.first; });
  std::vector<Found_vertex> unique;
  for (std::size_t i = 0; i < vertices.size();) {
    std::size_t end = i;
    while (end < vertices.size() && vertices[end].first == vertices[i].first) ++end;
    const std::size_t group = unique.size();
    for (std::size_t k = i; k < end; ++k) append_unique<Kernel>(unique, group, std::move(vertices[k]));
    i = end;
  }
  return unique;
}

template std::vector<Found_vertex> far_vertices<Certified_kernel>(const std::vector<Site>&, const std::vector<Site_index>&,
                                                                 const std::array<double, 3>&, double, const Axis_box&);
template std::vector<Found_vertex> far_vertices<Floating_kernel>(const std::vector<Site>&, const std::vector<Site_index>&,
                                                                const std::array<double, 3>&, double, const Axis_box&);

}  // namespace apollonius
