// The affine span of the lifts (x, y, z, w) of a set of sites (predicates/lift_outside_span.h), grown one
// site at a time. Sites whose lifts span at most a plane have no vertex among themselves; four sites whose
// lifts span a 3-space are a quadruple with a discrete set of roots.
#pragma once

#include <algorithm>
#include <array>
#include <vector>

#include "predicates/lift_outside_span.h"
#include "predicates/site.h"

namespace apollonius {

// Invariant: basis() holds affinely independent lifts whose span contains the lift of every site added;
// dimension() = basis().size - 1 (-1 when empty). Kernel: kernels.h.
template <class Kernel>
class Lift_span {
 public:
  // Adds s; returns whether the span grew.
  bool add(const Site& s) {
    if (!Kernel::outside_lift_span(basis_, s)) return false;
    basis_.sites[basis_.size++] = s;
    return true;
  }
  int dimension() const { return static_cast<int>(basis_.size) - 1; }
  const Lift_basis& basis() const { return basis_; }

 private:
  Lift_basis basis_;
};

}  // namespace apollonius

namespace apollonius {

// The dimension of the span of the lifts of sites[i], i in [begin, end), up to 4, and in `basis` (ascending)
// the first four sites of an affine basis taken greedily by descending weight. Such a basis maximizes its
// least weight among all bases (the greedy bottleneck basis of a matroid): if a point with radius r is not
// a valid root of its quadruple (r + w < 0 for some site of it), it is a valid root of no quadruple of
// four of the sites whose lifts span the same 3-space. Cost: O(k log k) and O(k) lift_outside_span calls.
template <class Kernel, class Iterator>
int heaviest_lift_basis(const std::vector<Site>& sites, Iterator begin, Iterator end, std::array<Site_index, 4>& basis) {
  std::vector<Site_index> by_weight(begin, end);
  std::stable_sort(by_weight.begin(), by_weight.end(), [&](Site_index a, Site_index b) { return sites[a].w > sites[b].w; });
  Lift_span<Kernel> span;
  basis = {};
  for (Site_index s : by_weight) {
    if (span.add(sites[s]) && span.dimension() <= 3) basis[static_cast<std::size_t>(span.dimension())] = s;
    if (span.dimension() == 4) break;
  }
  std::sort(basis.begin(), basis.begin() + std::min(span.dimension() + 1, 4));
  return span.dimension();
}

}  // namespace apollonius
