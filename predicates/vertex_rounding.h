// The printed coordinates of a vertex (docs/contract.md): the correctly rounded doubles of its exact x, y,
// z and r. Rounding to nearest is monotone and leaves doubles as they are, so they also order the vertex
// exactly against any double they differ from (vertex_in_box.h).
#pragma once

#include <array>
#include <optional>

#include "predicates/vertex.h"

namespace apollonius {

// x, y, z, r rounded to nearest (ties to even). A double-double evaluation with a certified error bound
// (double_double_ball.h) settles almost every coordinate; the others are rounded exactly
// (correct_rounding.h).
std::array<double, 4> rounded_coordinates(const Vertex& v);

// The double-double stage alone: the coordinates it can certify, nothing for the others. Exposed for
// the tests, which check it against the exact rounding.
std::array<std::optional<double>, 4> certified_roundings(const Vertex& v);

}  // namespace apollonius
