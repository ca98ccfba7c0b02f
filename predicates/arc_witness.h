// A point strictly inside an arc of a trisector (a Curve_point, exact): the witness that decides whether
// the arc is in the diagram, since no site's tie with the trisector's sites changes inside an arc between
// consecutive vertices of the diagram. The arc runs forward (trisector_predicates.h) from `from` to `to`;
// a missing end is infinity on an open curve, and on a closed curve both missing means the whole curve.
// The witness is the curve's point at a rational value of its ordering coordinate (rational_between.h),
// or the point where the curve crosses its axis e1.
#pragma once

#include <memory>
#include <optional>
#include <variant>

#include "predicates/curve_point.h"

namespace apollonius {

// One end of an arc: a vertex on the curve, or a curve point of it.
using Arc_end = std::variant<const Vertex*, const Curve_point*>;

// Precondition: the trisector is an ellipse, hyperbola or parabola; the ends lie on it, in that order
// forward; on a closed curve from == to means the whole curve but that point.
Curve_point arc_witness(const Trisector& trisector, std::optional<Arc_end> from, std::optional<Arc_end> to);

}  // namespace apollonius
