// The points where the line of a quadruple meets the cone (quadruple_line.h): the roots of
// A lambda^2 + 2 B lambda + C = 0 and the coordinates X = (Q + lambda n) / n_k they give.
#pragma once

#include <boost/container/static_vector.hpp>
#include <cmath>
#include <optional>

#include "predicates/vertex.h"

namespace apollonius {

// What the cone equation leaves of the line: isolated roots, or the whole line (a curve of equidistant
// points: no isolated vertex).
template <class NT>
struct Line_roots {
  bool whole_line_on_cone = false;
  boost::container::static_vector<Line_root<NT>, 2> roots;  // in the order MINUS, PLUS, or one SINGLE
};

// The root lambda = (a + b sqrt d) / denominator over a positive denominator, whose sign is known.
template <class NT>
Root_number<NT> positive_denominator(NT a, NT b, NT d, NT denominator, Sign denominator_sign) {
  if (denominator_sign == Sign::NEGATIVE) return {-a, -b, d, -denominator};
  return {a, b, d, denominator};
}

// Precondition: line.pivot >= 0. Nothing when a sign it needs is uncertain (filter number types only):
// most quadruples a filter leaves undecided fail here, and an exception cost more than the filter.
template <class NT>
std::optional<Line_roots<NT>> line_roots(const Quadruple_line<NT>& line) {
  Line_roots<NT> result;
  const NT zero(0);
  const std::optional<Sign> a = sign_if_certain(line.A);
  if (!a) return std::nullopt;
  if (*a != Sign::ZERO) {
    const std::optional<Sign> s = sign_if_certain(line.discriminant);
    if (!s) return std::nullopt;
    if (*s == Sign::ZERO) {
      result.roots.push_back({Root::SINGLE, positive_denominator(-line.B, zero, zero, line.A, *a)});
    } else if (*s == Sign::POSITIVE) {
      for (Root r : {Root::MINUS, Root::PLUS})
        result.roots.push_back(
            {r, positive_denominator(-line.B, NT(static_cast<int>(r)), line.discriminant, line.A, *a)});
    }
    return result;
  }
  const std::optional<Sign> b = sign_if_certain(line.B);
  if (!b) return std::nullopt;
  if (*b != Sign::ZERO) {
    result.roots.push_back({Root::SINGLE, positive_denominator(-line.C, zero, zero, NT(2) * line.B, *b)});
    return result;
  }
  const std::optional<Sign> c = sign_if_certain(line.C);
  if (!c) return std::nullopt;
  result.whole_line_on_cone = *c == Sign::ZERO;
  return result;
}

// X_j = (Q_j + lambda n_j) / n_k with lambda = (a + b sqrt d) / den, for the filter stages and the floating
// path (sqrt: CGAL's for Interval, double_with_error.h's, std::sqrt).
template <class NT>
Vertex_coordinates<NT> coordinates_on_line(const Quadruple_line<NT>& line, const Root_number<NT>& lambda) {
  using std::sqrt;
  using CGAL::sqrt;
  const NT l = (lambda.a + lambda.b * sqrt(lambda.d)) / lambda.denominator;
  const NT reciprocal = NT(1) / line.n[line.pivot];  // one division, not four: they dominated this function
  Vertex_coordinates<NT> V;
  for (int j = 0; j < 4; ++j) V.scaled[j] = (line.Q[j] + l * line.n[j]) * reciprocal;
  return V;
}

// The exact coordinates, over the common denominator den * |n_k|.
inline Vertex_coordinates<Exact> coordinates_on_line(const Quadruple_line<Exact>& line,
                                                     const Root_number<Exact>& lambda) {
  const Exact& nk = line.n[line.pivot];
  const bool flip = certain_sign(nk) == Sign::NEGATIVE;
  Vertex_coordinates<Exact> V;
  V.denominator = flip ? -(lambda.denominator * nk) : lambda.denominator * nk;
  V.discriminant = lambda.d;
  for (int j = 0; j < 4; ++j) {
    Exact a = line.Q[j] * lambda.denominator + line.n[j] * lambda.a;
    Exact b = line.n[j] * lambda.b;
    V.scaled[j] = flip ? Quadratic<Exact>{-a, -b} : Quadratic<Exact>{a, b};
  }
  return V;
}

}  // namespace apollonius
