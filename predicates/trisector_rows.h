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

#include <cstddef>
#include <vector>

#include "predicates/number_types.h"
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

namespace apollonius {

// The power gaps of a few sites, pairwise, in intervals: whether three of them may have a closed
// trisector (an ellipse or a point), or certainly not (a positive Gram determinant). Needs the rounding
// mode of Rounding_guard while in use.
class Pairwise_gaps {
 public:
  void assign(const std::vector<Site>& sites, const Site_index* set, std::size_t size) {
    size_ = size;
    gaps_.resize(size_ * size_);
    for (std::size_t x = 0; x < size_; ++x)
      for (std::size_t y = x + 1; y < size_; ++y) gaps_[x * size_ + y] = power_gap<Interval>(sites[set[x]], sites[set[y]]);
  }
  template <class Set>
  void assign(const std::vector<Site>& sites, const Set& set) {
    assign(sites, set.data(), set.size());
  }
  // Positions i < j < k in the set.
  bool maybe_closed(std::size_t i, std::size_t j, std::size_t k) const {
    return !(rows_gram_determinant(gaps_[i * size_ + j], gaps_[i * size_ + k], gaps_[j * size_ + k]).inf() > 0);
  }

 private:
  std::size_t size_ = 0;
  std::vector<Interval> gaps_;  // of i < j at i * size_ + j
};

}  // namespace apollonius
