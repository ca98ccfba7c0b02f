// The quadruples that can have a vertex other than v in a box, when every candidate of the box ties at v
// (a tie-point leaf, box_refinement.cpp). Seen from v the candidates separate by direction.
//
// With e = x - v, D_k = |v - p_k| and n_k = (v - p_k) / D_k, every candidate k has d_k(x) = d(v) + tau_k
// with, exactly, tau_k = e.n_k + (|e|^2 - tau_k^2) / (2 D_k), and |tau_k| <= |e| gives
//     e.n_k <= tau_k <= e.n_k + |e|^2 / (2 D_k).
// Write x = v + s y with y on the surface of the cube [-1, 1]^3 and 0 < s <= S, S the largest max-norm
// distance from v to the box. Then d_c(x) - d_j(x) >= s [y.(n_c - n_j) - S |y|^2 / (2 D_j)], so c owns no
// point but v of a patch of directions where y.(n_c - n_j) > S |y|^2 / (2 D_j): a certain interval bound.
// The patches (squares on the faces of the cube) are refined until at most three candidates are left (no
// vertex in their cone but v), at most six (their quadruples are recorded), or the candidates left stop
// dropping. Then their lifts decide: spanning a plane, they have no vertex; spanning a 3-space, every
// quadruple of them with roots has the same line through (v, r) and the same polynomial on it, hence the
// same roots as points, and the heaviest basis (lift_span.h) is recorded alone; otherwise all their
// quadruples are recorded at kMaxStarDepth. Candidates
// that stop dropping tie to first order along some direction, where their n_k are cocircular: v is then
// a double root of each of their quadruples, so they span a 3-space or are separated further down.
//
// Every vertex w != v of the box lies in some patch's cone, and its tie set survives there: w is a root of
// a recorded quadruple. Termination: depth at most kMaxStarDepth; at most kPatchesPerCandidate patches and
// kQuadruplesPerCandidate recorded quadruples per candidate, past which the star gives up and the caller
// takes the 3-faces of the candidates' lifted triangulation (also exact; box_refinement.cpp).
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "predicates/axis_box.h"
#include "predicates/number_types.h"
#include "predicates/vertex.h"

namespace apollonius {

// Work space of one thread. Kernel: kernels.h.
template <class Kernel>
class Tie_point_star {
 public:
  explicit Tie_point_star(const std::vector<Site>& sites) : sites_(sites) {}

  // Replaces `quadruples` with quadruples (ascending sites) among whose roots are all vertices other than
  // v in the closed box, and returns true; or returns false when the star gives up. Precondition: every
  // site of candidates[0..k) ties at v, and they include every owner of a point of the closed box.
  bool quadruples_near(const Vertex& v, const Axis_box& box, const Site_index* candidates, std::size_t k,
                       std::vector<std::array<Site_index, 4>>& quadruples);

 private:
  struct Patch {
    int axis;     // the face of [-1, 1]^3: y[axis] = side
    double side;  // +1 or -1
    double s0, s1, t0, t1;  // the other two coordinates of y, in axis order
    int depth;
    int stagnant;  // levels since a candidate was last removed
  };
  bool refine(const Patch& p, const std::vector<std::size_t>& survivors);
  bool record(const std::vector<std::size_t>& survivors);  // false: too many recorded, give up

  const std::vector<Site>& sites_;
  const Site_index* candidates_ = nullptr;
  std::vector<std::array<Interval, 3>> n_;  // per candidate: encloses n_k
  std::vector<Interval> half_inverse_;       // per candidate: encloses 1 / (2 D_k)
  std::array<Interval, 3> tie_point_;        // encloses v
  Axis_box box_;
  double reach_ = 0;                         // S, rounded up
  std::size_t patches_ = 0;
  std::vector<std::array<Site_index, 4>>* quadruples_ = nullptr;
};

}  // namespace apollonius
