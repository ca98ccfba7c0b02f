// d_s(c) = |c - x_s| - w_s at a box centre c, in box units, to a few units in the last place of its own
// size rather than of |c - x_s| + |w_s|. The centre expansion's plain doubles lose d_s(c) where the box
// centre lies near the sphere of a ball much larger than the box (|c - x_s| and w_s cancel), and leave it
// where a square overflows the box-unit range (a site 2^480 box sizes away): a ball 10^75 away whose
// sphere passes near a cluster could then neither be removed from the boxes there nor remove a site
// from them, and the boxes refined one level per binade (tests/data/regression/
// octree_boxes_explode_for_huge_sphere_near_cluster_*). The octree calls this only where the plain error
// exceeds the box (centre_expansion.h, sharpen), so ordinary inputs never reach it.
//
// How. With O = c - x_s and W = w_s, both scaled by the power of two 2^-E that brings max(|O_a|, |W|) to
// [1, 2) (exact, in Mpzf):
//  - W <= 0: d = |O| + |W|, a sum of non-negative terms, in intervals;
//  - W > 0:  d = (|O|^2 - W^2) / (|O| + W), the numerator exact (the cancellation happens there, exactly)
//    and the denominator at least 1, in intervals.
// Then d is brought to box units by a power of two, exactly in Mpzf before the last division. Every bound
// is an interval bound; docs/ERROR_BOUNDS.md ("Centre expansion", item 8) shows what the centre tests need
// of `error`.
#pragma once

#include "predicates/axis_box.h"
#include "predicates/site.h"

namespace apollonius {

struct Box_frame;

// Invariant when known: |value - d_s(c)| <= error in box units, where the clamp below allows it.
// |d_s(c)| beyond 2^1000 box units is clamped: value = +-2^1000 with error 0, which bounds d_s(c) on the
// side that keeps the centre tests sound (docs/ERROR_BOUNDS.md item 8).
struct Sharp_centre_value {
  double value = 0, error = 0;
  bool known = false;
};

Sharp_centre_value sharp_centre_value(const Site& s, const Box_frame& frame);

// The clamp of Sharp_centre_value, in box units.
constexpr double kSharpValueClamp = 0x1p1000;

}  // namespace apollonius
