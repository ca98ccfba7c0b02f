// The exact line of a quadruple (quadruple_line.h), from interval minors wherever they come out exact.
//
// On sites of a coarse grid (lattices, integer or dyadic inputs) every 3x3 minor n_j and Q_j is a double,
// and intervals compute it as a point: its exact value, at the cost of a few dozen double operations
// instead of a few hundred on GMP limbs. Only A, B, C and the discriminant, of twice the degree, are then
// formed in Exact. A point interval is rigorous (an enclosure of width zero), so the line is the one
// quadruple_line<Exact> computes, pivot included; any other quadruple takes quadruple_line<Exact>.
#pragma once

#include <array>

#include "predicates/number_types.h"
#include "predicates/quadruple_line.h"
#include "predicates/site.h"

namespace apollonius {

Quadruple_line<Exact> exact_quadruple_line(const std::array<Site, 4>& sites);

}  // namespace apollonius
