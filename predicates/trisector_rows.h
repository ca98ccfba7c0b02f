// Which trisectors can be closed, from the sites' pairwise power gaps alone (a filter before trisector.h's
// classification, for the many candidate triples of the whole diagram's vertex-free parts).
//
// In trisector.h's coordinates the curve lies in the plane L = {X : R_b . X = h_b, R_c . X = h_c}, and is an
// ellipse (or a point) only if the Lorentz product is definite on L's directions W = {R_b, R_c}^perp
// (Euclidean). Then W is positive definite (<,> has signature (3, 1)), so its Lorentz-orthogonal
// complement J W^perp = span(J R_b, J R_c), J = diag(1, 1, 1, -1), has signature (1, 1): the Gram matrix
// of J R_b, J R_c, which is G = [<R_i, R_j>], has det G < 0. Conversely det G > 0 makes W indefinite:
// the curve is a hyperbola (one branch on the sheet). With <R_m, R_m> = h_m = gap(a, m) and
// 2 <R_b, R_c> = gap(a, b) + gap(a, c) - gap(b, c), where gap(x, y) = |p_x - p_y|^2 - (w_x - w_y)^2:
//     4 det G = 4 gap(a, b) gap(a, c) - (gap(a, b) + gap(a, c) - gap(b, c))^2,
// symmetric in the three sites (Heron's form: positive iff the square roots of the gaps make a triangle).
#pragma once

#include "predicates/quadruple_line.h"
#include "predicates/site.h"

namespace apollonius {

// |p_x - p_y|^2 - (w_x - w_y)^2, positive for two sites neither of which hides the other.
template <class NT>
NT power_gap(const Site& x, const Site& y) {
  return relative_site<NT>(x, y).rhs;
}

// 4 det G for the trisector of sites a, b, c from gap(a, b), gap(a, c), gap(b, c) (any order of the three).
template <class NT>
NT rows_gram_determinant(const NT& ab, const NT& ac, const NT& bc) {
  const NT s = ab + ac - bc;
  return NT(4) * ab * ac - s * s;
}

}  // namespace apollonius
