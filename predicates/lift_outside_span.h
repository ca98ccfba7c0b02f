// Predicate lift_outside_span(basis, s): whether the lift L_s = (x_s, y_s, z_s, w_s) in R^4 lies outside
// the affine span of the basis' lifts. The rows of a quadruple's matrix M (vertices_of.h) are L_b - L_a,
// so four sites are rank-deficient (rank M < 3: no isolated vertex) exactly when their lifts span at most
// a plane. Sites whose lifts all lie in one plane (equal weights on one circle; collinear centres with any
// weights) therefore have no vertex among themselves, however many they are.
#pragma once

#include <array>
#include <cstddef>

#include "predicates/filtered_predicate.h"
#include "predicates/site.h"

namespace apollonius {

// Up to five sites whose lifts are affinely independent; sites[0] is the origin of the differences.
struct Lift_basis {
  std::array<Site, 5> sites;
  std::size_t size = 0;
};

struct Lift_outside_span_predicate {
  static constexpr const char* name = "lift_outside_span";

  // With m = basis.size, the m rows L_b - L_0 (b = 1..m-1) and L_s - L_0 have rank m exactly when some
  // m x m minor is not zero (the first m - 1 rows are independent). Differences and products of doubles
  // need no division: Exact computes them exactly. With Interval, a minor certainly away from zero answers
  // at once; an uncertain one sends the predicate to Exact unless another minor answers.
  template <class NT>
  static bool evaluate(const Lift_basis& basis, const Site& s) {
    if (basis.size == 0) return true;
    if (basis.size == 5) return false;  // the lifts span R^4
    const Site& o = basis.sites[0];
    const auto row = [&](const Site& p) {
      return std::array<NT, 4>{NT(p.x) - NT(o.x), NT(p.y) - NT(o.y), NT(p.z) - NT(o.z), NT(p.w) - NT(o.w)};
    };
    const std::size_t m = basis.size;
    std::array<std::array<NT, 4>, 4> rows;
    for (std::size_t b = 1; b < m; ++b) rows[b - 1] = row(basis.sites[b]);
    rows[m - 1] = row(s);
    bool uncertain = false;
    for (unsigned columns = 0; columns < 16; ++columns) {
      if (static_cast<std::size_t>(__builtin_popcount(columns)) != m) continue;
      std::array<std::size_t, 4> c{};
      for (std::size_t j = 0, t = 0; j < 4; ++j)
        if (columns >> j & 1) c[t++] = j;
      try {
        if (certain_sign(minor<NT>(rows, c, m)) != Sign::ZERO) return true;
      } catch (const Uncertain_sign&) {
        uncertain = true;
      }
    }
    if (uncertain) throw Uncertain_sign();
    return false;
  }

  // The determinant of rows 0..m-1 restricted to the columns c[0..m), by cofactors (m <= 4).
  template <class NT>
  static NT minor(const std::array<std::array<NT, 4>, 4>& r, const std::array<std::size_t, 4>& c, std::size_t m) {
    const auto at = [&](std::size_t i, std::size_t j) -> const NT& { return r[i][c[j]]; };
    const auto det2 = [&](std::size_t i0, std::size_t i1, std::size_t j0, std::size_t j1) {
      return at(i0, j0) * at(i1, j1) - at(i0, j1) * at(i1, j0);
    };
    const auto det3 = [&](std::size_t i0, std::size_t i1, std::size_t i2, std::size_t j0, std::size_t j1, std::size_t j2) {
      return at(i0, j0) * det2(i1, i2, j1, j2) - at(i0, j1) * det2(i1, i2, j0, j2) + at(i0, j2) * det2(i1, i2, j0, j1);
    };
    switch (m) {
      case 1: return at(0, 0);
      case 2: return det2(0, 1, 0, 1);
      case 3: return det3(0, 1, 2, 0, 1, 2);
      default:
        return at(0, 0) * det3(1, 2, 3, 1, 2, 3) - at(0, 1) * det3(1, 2, 3, 0, 2, 3) + at(0, 2) * det3(1, 2, 3, 0, 1, 3) -
               at(0, 3) * det3(1, 2, 3, 0, 1, 2);
    }
  }
};

inline const Filtered_predicate<Lift_outside_span_predicate> lift_outside_span{};

}  // namespace apollonius
