// A certified filter for removing candidates from a box: site j (the witness) is strictly closer than
// site i on the whole box if, at a point c of the box,
//     d_i(c) - d_j(c) > L H,   L = min(2, 2 |x_i - x_j| / (rho_i + rho_j)),
// where H bounds |x - c| over the box and rho_k is the distance from x_k to the box. f = d_i - d_j has
// gradient u_i - u_j (unit vectors from the sites), and |u_i - u_j| <= 2 |x_i - x_j| / (|x - x_i| + |x - x_j|)
// (Dunkl-Williams in an inner product space), so |f(x) - f(c)| <= L H on the box. Unlike paper Theorem 6,
// which needs d_i(c) - d_j(c) > 2H, this scales with the distance to the sites, so far boxes need not be
// small.
//
// Evaluated in plain doubles with a static error bound (the derivation is in predicates/ERROR_BOUNDS.md),
// so it changes no rounding mode. When it cannot certify, the exact predicate dominates_on_box decides,
// and a site that neither removes stays a candidate, which is always safe.
#pragma once

#include "axis_box.h"
#include "site.h"

namespace apollonius {

class Lipschitz_filter {
 public:
  Lipschitz_filter(const Axis_box& box, const Site& witness);

  // True only if the witness is certainly strictly closer than `s` at every point of the box.
  bool witness_dominates(const Site& s) const;

 private:
  double distance_to_box(const Site& s) const;

  Axis_box box_;
  double centre_[3];
  double reach_;  // computed H: the distance from c to the farthest corner
  Site witness_;
  double witness_distance_;  // computed |c - x_j|
  double witness_rho_;       // computed rho_j
  bool usable_;              // every magnitude lies where the error bound holds
};

}  // namespace apollonius
