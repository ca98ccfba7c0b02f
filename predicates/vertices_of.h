// Predicate vertices_of(quadruple): the 0, 1 or 2 points equidistant to four sites with a valid r
// (r + w_m >= 0 for each of the four), i.e. the candidate Apollonius vertices of the quadruple (paper
// Theorem 4, without its non-coplanarity assumption).
#pragma once

#include <boost/container/static_vector.hpp>
#include <algorithm>
#include <cmath>
#include <optional>
#include <type_traits>
#include <vector>

#include "predicates/double_with_magnitude.h"
#include "predicates/exact_quadruple_line.h"
#include "predicates/filtered_predicate.h"
#include "predicates/line_roots.h"
#include "predicates/wide_interval.h"

namespace apollonius {

// Invariant: vertices is empty when rank_deficient or equidistant_curve.
struct Quadruple_vertices {
  bool rank_deficient = false;     // rank M < 3: the equidistant set is not discrete
  bool equidistant_curve = false;  // rank 3, but the whole line lies on the cone (a ray of ties)
  boost::container::static_vector<Vertex, 2> vertices;  // a quadratic has at most two roots
};

// X gives r + w_m >= 0 for m = 0..3: X_3 + 2 b_m >= 0 with b_0 = 0. The floating path's doubles can
// become NaN, which its signs would read as ties: such a root is no point.
template <class NT>
bool is_valid_root(const Vertex_coordinates<NT>& X, const Quadruple& q) {
  if constexpr (std::is_same_v<NT, double>)
    if (std::any_of(X.scaled.begin(), X.scaled.end(), [](double x) { return std::isnan(x); })) return false;
  if (X.sign(X.scaled[3]) == Sign::NEGATIVE) return false;
  for (int m = 1; m < 4; ++m) {
    const NT twice_b = NT(2) * (NT(q.sites[m].w) - NT(q.sites[0].w));
    if (X.sign(X.scaled[3] + X.denominator * twice_b) == Sign::NEGATIVE) return false;
  }
  return true;
}

Vertex make_vertex(const Quadruple& q, Root root, Vertex_coordinates<double> X);
Vertex make_vertex(const Quadruple& q, Root root, Vertex_coordinates<Double_with_error> X);
Vertex make_vertex(const Quadruple& q, Root root, Vertex_coordinates<Interval> X);
Vertex make_vertex(const Quadruple& q, Root root, Vertex_coordinates<Wide_interval> X);
Vertex make_vertex(const Quadruple& q, Root root, Vertex_coordinates<Exact> X);

// vertices_of's double-double stage: the vertices where the balls certify A != 0, the discriminant's sign,
// and each root's validity; nothing otherwise.
std::optional<Quadruple_vertices> vertices_from_balls(const Quadruple& q);

struct Vertices_of_predicate {
  static constexpr const char* name = "vertices_of";

  // The line's polynomials in doubles with an a priori bound, the rest with running bounds: a fraction of
  // the cost of intervals, and certain as often; the pivot's zeros exactly (exact_quadruple_line.h).
  static std::optional<Quadruple_vertices> static_filter(const Quadruple& q) {
    try {
      const auto bounded = [](const Double_with_magnitude& x) { return with_error(x); };
      return vertices_on_line_if_certain(
          converted_line<Double_with_error>(quadruple_line<Double_with_magnitude>(q.sites, Pivot_exact_where_uncertain{}), bounded), q);
    } catch (const Uncertain_sign&) {
      return std::nullopt;
    }
  }

  // Intervals, then intervals on the line parametrized by its largest entry (conditioned_vertices: nearly
  // coplanar centres), then wide intervals (wide_interval.h): sites spread over many binades (5e-324 to
  // 1e266) take the line's polynomials, of degree up to 14, out of the double range, where plain intervals
  // overflow or underflow and only the exact stage, with thousands of bits, decided.
  static std::optional<Quadruple_vertices> interval_stage(const Quadruple& q) {
    try {
      if (std::optional<Quadruple_vertices> certain = vertices_on_line_if_certain(quadruple_line<Interval>(q.sites), q))
        return certain;
    } catch (const Uncertain_sign&) {
    }
    if (std::optional<Quadruple_vertices> certain = conditioned_vertices(q)) return certain;
    if (!may_leave_double_range(q)) return std::nullopt;
    try {
      const Quadruple_line<Wide_interval> line = quadruple_line<Wide_interval>(q.sites);
      if (std::optional<Quadruple_vertices> certain = vertices_on_line_if_certain(line, q)) return certain;
    } catch (const Uncertain_sign&) {
    }
    const int origin = closest_pair_origin(q.sites);
    if (origin == 0) return std::nullopt;
    try {
      return wide_vertices_from_origin(q, origin);
    } catch (const Uncertain_sign&) {
      return std::nullopt;
    }
  }

  // The line in intervals parametrized by its largest entry k' of n instead of the pivot k (quadruple_line.h).
  // Centres nearly in one plane (sites 5e-324 off a lattice plane) make n_3 tiny: lambda = X_3 then barely
  // separates the two roots, mirror images across the plane, and no filter decides the discriminant; X_k'
  // separates them. A root's label is the pivot's: along X = P + t n, lambda_r = (-B + r sqrt D) / A
  // (line_roots.h) and X_k grows with t iff n_k > 0, so MINUS is the smaller t iff sign(A) sign(n_k) > 0;
  // A = <n, n> is the same for every pivot, so the labels under k' are those under k, swapped where n_k and
  // n_k' differ in sign. Precondition: a Rounding_guard.
  static std::optional<Quadruple_vertices> conditioned_vertices(const Quadruple& q) {
    try {
      int pivot = -1;
      // False where the largest entry is the pivot (or none is certain): the interval stage's line, which
      // failed. Returned rather than thrown, as exceptions are slow and this is common on lattices one ulp off.
      bool worth_trying = true;
      const auto largest_entry = [&](const Vector4<Interval>& n, const std::array<Site, 4>& sites) {
        pivot = Pivot_exact_where_uncertain{}(n, sites);
        if (pivot < 0) return -1;  // rank M < 3, decided exactly
        int largest = -1;
        for (int k = 0; k < 4; ++k)
          if (certainly_nonzero(n[k]) && (largest < 0 || magnitude(n[k]) > magnitude(n[largest]))) largest = k;
        worth_trying = largest >= 0 && largest != pivot;
        return worth_trying ? largest : -1;
      };
      const Quadruple_line<Interval> line = quadruple_line<Interval>(q.sites, largest_entry);
      if (!worth_trying) return std::nullopt;
      std::optional<Quadruple_vertices> result = vertices_on_line_if_certain(line, q);
      if (!result || line.pivot < 0) return result;
      // sign(n_k): the line's own interval n_k where it is certain (Pivot_exact_where_uncertain mostly took
      // k there), else exactly.
      const std::optional<Sign> pivot_entry = sign_if_certain(line.n[pivot]);
      if ((pivot_entry ? *pivot_entry : null_vector_entry_sign(q.sites, pivot)) == certain_sign(line.n[line.pivot]))
        return result;
      // Swapped labels; in reverse, MINUS comes first again.
      Quadruple_vertices relabelled;
      relabelled.equidistant_curve = result->equidistant_curve;
      for (auto v = result->vertices.rbegin(); v != result->vertices.rend(); ++v) {
        const Root opposite =
            v->root() == Root::MINUS ? Root::PLUS : v->root() == Root::PLUS ? Root::MINUS : Root::SINGLE;
        relabelled.vertices.push_back(make_vertex(q, opposite, v->coordinates<Interval>()));
      }
      return relabelled;
    } catch (const Uncertain_sign&) {
      return std::nullopt;
    }
  }

  static double magnitude(const Interval& x) { return std::min(std::fabs(x.inf()), std::fabs(x.sup())); }

  // The wide stage with site m of the quadruple as the origin of the line, its vertices moved back to
  // site 0 (move_origin, quadruple_line.h). M's rows relative to site m span the same space, so n
  // changes by a nonzero factor c: the pivot (the first k with n_k != 0) stays, A = <n, n> changes by
  // c^2 > 0, and X_k = lambda moves by a constant, so each root keeps its label (MINUS, PLUS, SINGLE).
  static std::optional<Quadruple_vertices> wide_vertices_from_origin(const Quadruple& q, int m) {
    std::array<Site, 4> sites = q.sites;
    std::swap(sites[0], sites[m]);
    // Validity is tested before the move (vertices_on_line_if_certain): r + w_j >= 0 does not depend on the
    // origin, and relative to site 0, far from the vertex, X_3 + 2 b_j would cancel 2 w_0 down to 2 (r + w_j).
    const auto move_back = [&](Vertex_coordinates<Wide_interval>& X) { move_origin(X.scaled, q.sites[m], q.sites[0]); };
    return vertices_on_line_if_certain(quadruple_line<Wide_interval>(sites), q, Quadruple{q.indices, sites}, move_back);
  }

  // Whether a relative coordinate (a_m, b_m: quadruple_line.h) lies beyond 2^64, or every one below
  // 2^-64, so that the line's polynomials may overflow or underflow as a whole. Elsewhere plain
  // intervals fail on nearly degenerate quadruples (sites one ulp off a lattice), where wide ones fail too.
  static bool may_leave_double_range(const Quadruple& q) {
    double largest = 0;
    for (int m = 1; m < 4; ++m)
      for (const double d : {q.sites[m].x - q.sites[0].x, q.sites[m].y - q.sites[0].y, q.sites[m].z - q.sites[0].z,
                             q.sites[m].w - q.sites[0].w})
        largest = std::max(largest, std::fabs(d));  // an overflowing difference is infinite, hence large
    return !(largest <= 0x1p64) || largest < 0x1p-64;
  }

  // Double-double balls (vertex_ball.h), for the quadruples of sites one ulp off a lattice, whose line's
  // polynomials cancel beyond what intervals tell; not where A or the discriminant may vanish.
  static std::optional<Quadruple_vertices> ball_stage(const Quadruple& q) { return vertices_from_balls(q); }

  // Throws Uncertain_sign where a filter number type is not certain.
  template <class NT>
  static Quadruple_vertices evaluate(const Quadruple& q) {
    std::optional<Quadruple_vertices> result;
    if constexpr (std::is_same_v<NT, Exact>) result = vertices_on_line_if_certain(exact_quadruple_line(q.sites), q);
    else result = vertices_on_line_if_certain(quadruple_line<NT>(q.sites), q);
    if (!result) throw Uncertain_sign();
    return *std::move(result);
  }

  // Nothing where the roots' signs are uncertain, the usual failure; the rarer ones after them throw.
  template <class NT>
  static std::optional<Quadruple_vertices> vertices_on_line_if_certain(const Quadruple_line<NT>& line,
                                                                       const Quadruple& q) {
    return vertices_on_line_if_certain(line, q, q, [](Vertex_coordinates<NT>&) {});
  }

  // The same for a line relative to the first site of line_sites (q's sites in another order): a root's
  // validity is tested there, then move_back takes X to q's origin.
  template <class NT, class Move_back>
  static std::optional<Quadruple_vertices> vertices_on_line_if_certain(const Quadruple_line<NT>& line,
                                                                       const Quadruple& q, const Quadruple& line_sites,
                                                                       Move_back move_back) {
    Quadruple_vertices result;
    if (line.pivot < 0) {
      result.rank_deficient = true;
      return result;
    }
    const std::optional<Line_roots<NT>> roots = line_roots(line);
    if (!roots) return std::nullopt;
    result.equidistant_curve = roots->whole_line_on_cone;
    for (const Line_root<NT>& root : roots->roots) {
      Vertex_coordinates<NT> X = coordinates_on_line(line, root.lambda);
      if (!is_valid_root(X, line_sites)) continue;
      move_back(X);
      result.vertices.push_back(make_vertex(q, root.root, std::move(X)));
    }
    return result;
  }
};

inline const Filtered_predicate<Vertices_of_predicate> vertices_of{};

// The quadruple of the given sites, in ascending index order.
Quadruple make_quadruple(std::array<Site_index, 4> indices, const std::vector<Site>& sites);

}  // namespace apollonius
