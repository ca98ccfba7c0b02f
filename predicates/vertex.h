// A vertex held symbolically (docs/design.md, "Arithmetic"): its four defining sites and which root of their quadratic,
// never rounded coordinates. It caches an interval enclosure of X = 2 (v - p_0, r + w_0) (quadruple_line.h)
// for the filters, and computes its exact coordinates in Q(sqrt(discriminant)) on demand.
#pragma once

#include <array>
#include <optional>
#include <type_traits>

#include "predicates/computed_once.h"
#include "predicates/double_with_error.h"
#include "predicates/quadratic.h"
#include "predicates/quadruple_line.h"
#include "predicates/root_sign.h"
#include "predicates/vertex_ball.h"

namespace apollonius {

// Which root: lambda = (-B + sigma sqrt(discriminant)) / A for sigma = -1 or +1; SINGLE when the
// quadratic has one root (discriminant 0, or A = 0 and lambda = -C / 2B).
enum class Root : signed char { MINUS = -1, SINGLE = 0, PLUS = 1 };

// Four sites in ascending index order; sites[0] is the origin of the vertex algebra.
struct Quadruple {
  std::array<Site_index, 4> indices;
  std::array<Site, 4> sites;
};

// The coordinates X of a vertex, scaled by a positive denominator: X_j = scaled[j] / denominator.
// Formulas are written once against this interface (sign, +, -, * by NT). For the filter stages
// (Interval, Double_with_error) and the floating path (double) the denominator is 1.
template <class NT>
struct Vertex_coordinates {
  using Element = NT;
  std::array<NT, 4> scaled;
  NT denominator{1};
  Sign sign(const NT& e) const { return certain_sign(e); }
};

template <>
struct Vertex_coordinates<Exact> {
  using Element = Quadratic<Exact>;
  std::array<Element, 4> scaled;
  Exact denominator;   // > 0
  Exact discriminant;  // >= 0
  Sign sign(const Element& e) const { return sign_of_root_number(e.a, e.b, discriminant); }
};

// The root parameter lambda of the line, or nothing when that root does not exist.
template <class NT>
struct Line_root {
  Root root;
  Root_number<NT> lambda;
};

// X_j lies in scaled[j] * 2^exponent: the enclosure of a vertex whose X lies beyond the range where the
// plain box's products stay normal doubles (a vertex of nearly coplanar sites, 10^320 away, or one among
// subnormal sites), so that the filters can still compare it with sites of ordinary size.
struct Scaled_box {
  long exponent;
  std::array<Interval, 4> scaled;
};

class Vertex {
 public:
  Vertex(const Quadruple& quadruple, Root root, const std::array<Interval, 4>& box)
      : quadruple_(quadruple), root_(root), box_{box} {}
  Vertex(const Quadruple& quadruple, Root root, Vertex_coordinates<Exact> exact);
  // From the double-double stage (vertex_ball.h): `box` encloses `ball`.
  Vertex(const Quadruple& quadruple, Root root, const std::array<Interval, 4>& box, const Ball_coordinates& ball)
      : quadruple_(quadruple), root_(root), box_{box}, ball_(std::optional<Ball_coordinates>(ball)) {}
  // From a filter's enclosure of X beyond the double range: `box` is infinite there, `scaled` holds X.
  Vertex(const Quadruple& quadruple, Root root, const std::array<Interval, 4>& box, Scaled_box scaled)
      : quadruple_(quadruple), root_(root), box_{box}, scaled_box_(std::optional<Scaled_box>(std::move(scaled))) {}

  const Quadruple& quadruple() const { return quadruple_; }
  const std::array<Site_index, 4>& sites() const { return quadruple_.indices; }
  const Site& origin() const { return quadruple_.sites[0]; }
  Root root() const { return root_; }

  template <class NT>
  const Vertex_coordinates<NT>& coordinates() const;

  // Interval enclosure of the vertex centre (x, y, z) and r.
  std::array<Interval, 4> point_interval() const;

  // x, y, z, r correctly rounded (vertex_rounding.h), computed on first use.
  const std::array<double, 4>& rounded() const;
  // The same if computed already, else null.
  const std::array<double, 4>* rounded_if_computed() const { return rounded_.get(); }
  // The sign of x, y, z minus their rounded doubles (ZERO: the double is exact), computed exactly on first
  // use: with rounded(), it orders the vertex against any double at once (vertex_in_box.h), where a vertex
  // lying on box bounds (sites on a dyadic grid) would otherwise take an exact comparison per bound.
  const std::array<Sign, 3>& rounding_sides() const;
  const std::array<Sign, 3>* rounding_sides_if_computed() const { return sides_.get(); }

  // X as double-double balls (vertex_ball.h), computed on first use, in round-to-nearest; null where they
  // cannot follow the vertex's root (a single root with A near 0, a discriminant near 0, X out of range).
  const Ball_coordinates* ball_coordinates() const;
  const Ball_coordinates* ball_coordinates_if_computed() const {
    const std::optional<Ball_coordinates>* X = ball_.get();
    return X != nullptr && *X ? &**X : nullptr;
  }

  // Releases the exact coordinates and the balls, which coordinates<Exact>() and ball_coordinates() compute
  // again from the quadruple if asked: for a vertex stored in a diagram once rounded, which needs them
  // again only to order it against an equal rounding. On a near-degenerate input they are most of the
  // vertices' memory. Like any write, must not run beside other uses of the same object.
  void release_exact_values();

  // For a vertex made from its exact coordinates (vertices_of's exact stage; computed on first use) or from
  // wide intervals whose X lies beyond [2^-500, 2^500]; else null.
  const Scaled_box* scaled_box() const;

 private:
  // box_ from exact_, a few ulps wide; and whether X may lie out of range, so that scaled_box() computes
  // a scaled box when first asked.
  void enclose_exact();

  Quadruple quadruple_;
  Root root_;
  Vertex_coordinates<Interval> box_;  // holds X
  // Computed on first use, by any thread (computed_once.h).
  Computed_once<Vertex_coordinates<Exact>> exact_;
  Computed_once<std::array<double, 4>> rounded_;
  Computed_once<std::array<Sign, 3>> sides_;
  Computed_once<std::optional<Ball_coordinates>> ball_;
  // Set when made from wide intervals, if X is out of range. For a vertex made exact whose plain box leaves
  // [2^-500, 2^500], computed on first use: most are the far root of a line nearly parallel to the cone
  // (A near 0), which no box holds and no conflict test reads, and its exponents take MPFR. A Computed_once
  // for its size: one pointer, shared by copies.
  Computed_once<std::optional<Scaled_box>> scaled_box_;
  bool scaled_box_on_demand_ = false;
};

template <>
inline const Vertex_coordinates<Interval>& Vertex::coordinates<Interval>() const {
  return box_;
}
template <>
const Vertex_coordinates<Exact>& Vertex::coordinates<Exact>() const;

// The coordinates X of a vertex in the arithmetic NT: a reference for Interval and Exact, a value for double
// (the floating path's vertices, whose interval box is a point).
template <class NT>
decltype(auto) coordinates_for(const Vertex& v) {
  if constexpr (std::is_same_v<NT, double>) {
    const auto& box = v.coordinates<Interval>().scaled;
    return Vertex_coordinates<double>{{box[0].inf(), box[1].inf(), box[2].inf(), box[3].inf()}};
  } else {
    return v.coordinates<NT>();
  }
}

// X of the quadruple's root as double-double balls (vertex_ball.h), or nothing where they cannot follow it.
std::optional<Ball_coordinates> ball_coordinates_of(const Quadruple& quadruple, Root root);

// The exact centre and r of the vertex: x, y, z, r, each (a + b sqrt d) / denominator.
std::array<Root_number<Exact>, 4> exact_point(const Vertex& v);

}  // namespace apollonius
