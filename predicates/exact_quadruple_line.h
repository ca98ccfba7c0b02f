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

// Whether n_k, a 3x3 minor of the site differences, is nonzero, exactly: a few dozen Mpzf operations.
bool null_vector_entry_nonzero(const std::array<Site, 4>& sites, int k);

// The sign of n_k, exactly: intervals first, then the minor in Exact.
Sign null_vector_entry_sign(const std::array<Site, 4>& sites, int k);

// quadruple_line.h's pivot rule for number types that never certify a zero (Double_with_magnitude,
// double-double balls): an entry NT shows nonzero is; one it cannot tell is decided exactly. Sites on a
// lattice make exact zeros often (four centres in one plane, the weight column of equal balls), where
// certain_sign would throw and send the quadruple on to the next stage.
struct Pivot_exact_where_uncertain {
  template <class NT>
  int operator()(const Vector4<NT>& n, const std::array<Site, 4>& sites) const {
    for (int k : {3, 0, 1, 2})
      if (certainly_nonzero(n[k]) || null_vector_entry_nonzero(sites, k)) return k;
    return -1;
  }
};

}  // namespace apollonius
