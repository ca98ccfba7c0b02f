// Predicate vertex_conflict(v, s): the sign of d_s(v) - r(v). NEGATIVE means s is strictly closer than the
// vertex's own sites (the vertex is not in the diagram), ZERO means s ties with them.
//
// If r + w_s < 0, then d_s(v) >= -w_s > r: POSITIVE. Otherwise the sign is that of
// |v - p_s|^2 - (r + w_s)^2, which on the cone |U| = X_3 (quadruple_line.h) is the linear form
// |a_s|^2 - b_s^2 - <(a_s, b_s), X>  with a_s = p_s - p_0, b_s = w_s - w_0: one square root, one squaring.
#pragma once

#include "predicates/filtered_predicate.h"
#include "predicates/vertex.h"

namespace apollonius {

struct Vertex_conflict_predicate {
  static constexpr const char* name = "vertex_conflict";

  template <class NT>
  static Sign evaluate(const Vertex& v, const Site& s) {
    const auto& X = coordinates_for<NT>(v);
    const Relative_site<NT> a = relative_site<NT>(v.origin(), s);
    if (X.sign(X.scaled[3] + X.denominator * (NT(2) * a.row[3])) == Sign::NEGATIVE) return Sign::POSITIVE;
    return X.sign(X.denominator * a.rhs - (X.scaled[0] * a.row[0] + X.scaled[1] * a.row[1] +
                                           X.scaled[2] * a.row[2] + X.scaled[3] * a.row[3]));
  }
};

inline const Filtered_predicate<Vertex_conflict_predicate> vertex_conflict{};

}  // namespace apollonius
