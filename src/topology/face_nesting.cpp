#include "topology/face_nesting.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <optional>
#include <numeric>
#include <stdexcept>
#include <type_traits>
#include <variant>

#include "predicates/rational_between.h"
#include "predicates/rounding_guard.h"
#include "predicates/trisector_predicates.h"

namespace apollonius {
namespace {

using Vector3 = std::array<Rational, 3>;

Vector3 cross(const Vector3& x, const Vector3& y) {
  return {x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
}

bool is_zero(const Vector3& x) {
  return certain_sign(x[0]) == Sign::ZERO && certain_sign(x[1]) == Sign::ZERO && certain_sign(x[2]) == Sign::ZERO;
}

// One edge of the pair, with its curve.
struct Pair_edge {
  std::size_t component;
  const Diagram_edge* edge;
  std::unique_ptr<Trisector> trisector;
  Trisector_kind kind;
};

// The 4D cross product of x, y, z: Euclidean-orthogonal to all three.
Vector4<Rational> orthogonal_direction(const Vector4<Rational>& x, const Vector4<Rational>& y, const Vector4<Rational>& z) {
  Vector4<Rational> n;
  for (int i = 0; i < 4; ++i) {
    std::array<int, 3> c{};
    for (int j = 0, k = 0; j < 4; ++j)
      if (j != i) c[k++] = j;
    const Rational minor = x[c[0]] * (y[c[1]] * z[c[2]] - y[c[2]] * z[c[1]]) - x[c[1]] * (y[c[0]] * z[c[2]] - y[c[2]] * z[c[0]]) +
                           x[c[2]] * (y[c[0]] * z[c[1]] - y[c[1]] * z[c[0]]);
    n[i] = i % 2 == 0 ? minor : -minor;
  }
  return n;
}

// The hyperplane e . v = y in a trisector's frame X = 2 (v - p_o, .): (e / 2) . X = y - e . p_o.
Vector4<Rational> level_cut(const Vector3& e) { return {e[0] / 2, e[1] / 2, e[2] / 2, Rational(0)}; }
Rational level_offset(const Vector3& e, const Site& o, const Rational& y) {
  return y - (e[0] * Rational(o.x) + e[1] * Rational(o.y) + e[2] * Rational(o.z));
}

// A rational direction e, its levels' cut (level_cut) and an interval enclosure of it: a level's enclosure
// costs no rational arithmetic.
struct Level_direction {
  Vector3 exact;
  Vector4<Rational> cut;
  std::array<Interval, 3> enclosure;  // holds exact
  explicit Level_direction(const Vector3& e) : exact(e), cut(level_cut(e)) {
    for (int k = 0; k < 3; ++k) enclosure[k] = Interval(CGAL::to_interval(e[k]));
  }
};

// e . v at a point of a trisector (a vertex on it, or a curve point of it): an interval enclosure first
// (the whole line when intervals fail), the exact value on first need, when two enclosures overlap.
class Level_value {
 public:
  template <class P>
  Level_value(const Trisector& t, const P& p, const Level_direction& e) : trisector_(&t), direction_(&e) {
    if constexpr (std::is_same_v<P, Vertex>)
      point_ = &p;
    else
      point_ = p;
    const Site& o = t.origin();
    Rounding_guard guard;
    try {
      const std::array<Interval, 3>& x = e.enclosure;
      const Vector4<Interval> y{x[0] / 2, x[1] / 2, x[2] / 2, Interval(0)};
      const Interval offset = x[0] * Interval(o.x) + x[1] * Interval(o.y) + x[2] * Interval(o.z);
      enclosure_ = euclidean_value(field_point_on<Interval>(t, p), y, offset);
    } catch (const Uncertain_sign&) {
      enclosure_ = Interval::largest();
    }
  }

  const Interval& enclosure() const { return enclosure_; }
  const Root_number<Rational>& exact() const {
    if (!value_) {
      const Site& o = trisector_->origin();
      const Vector3& e = direction_->exact;
      const Rational offset = e[0] * Rational(o.x) + e[1] * Rational(o.y) + e[2] * Rational(o.z);
      value_ = std::visit(
          [&](const auto& p) {
            if constexpr (std::is_pointer_v<std::decay_t<decltype(p)>>)
              return euclidean_value(field_point_on<Rational>(*trisector_, *p), direction_->cut, offset);
            else
              return euclidean_value(field_point_on<Rational>(*trisector_, p), direction_->cut, offset);
          },
          point_);
    }
    return *value_;
  }

 private:
  const Trisector* trisector_;
  const Level_direction* direction_;
  std::variant<const Vertex*, Curve_point> point_;  // a vertex of the diagram, which outlives this
  Interval enclosure_;
  mutable std::optional<Root_number<Rational>> value_;
};

bool finite(const Interval& x) { return std::isfinite(x.inf()) && std::isfinite(x.sup()); }

Sign compare_levels(const Level_value& x, const Level_value& y) {
  if (x.enclosure().sup() < y.enclosure().inf()) return Sign::NEGATIVE;
  if (y.enclosure().sup() < x.enclosure().inf()) return Sign::POSITIVE;
  return compare(x.exact(), y.exact());
}

// A rational strictly between x < y: a dyadic one between their enclosures when they separate (short, so
// the level lines stay cheap), else rational_between's.
Rational level_between(const Level_value& x, const Level_value& y) {
  if (finite(x.enclosure()) && finite(y.enclosure()) && x.enclosure().sup() < y.enclosure().inf())
    return (Rational(x.enclosure().sup()) + Rational(y.enclosure().inf())) / 2;
  return rational_between(x.exact(), y.exact());
}

// Of sorted distinct heights (at least two), the i whose gap to i + 1 is widest by their enclosures (the
// first where none is finite): a level there crosses the edges far from their vertices, where intervals
// order the crossings. A choice of line, not a decision: any level between two consecutive heights of a
// cycle's vertices lies strictly inside its range.
std::size_t widest_gap(const std::vector<Level_value>& heights) {
  std::size_t widest = 0;
  double width = -INFINITY;
  for (std::size_t i = 0; i + 1 < heights.size(); ++i) {
    const double w = heights[i + 1].enclosure().inf() - heights[i].enclosure().sup();
    if (std::isfinite(w) && w > width) widest = i, width = w;
  }
  return widest;
}

// A rational strictly below (side -1) or above (side +1) x.
Rational level_beyond(const Level_value& x, int side) {
  if (finite(x.enclosure()))
    return Rational(side < 0 ? x.enclosure().inf() : x.enclosure().sup()) + Rational(side);
  const Root_number<Rational>& v = x.exact();
  const Root_number<Rational> shifted{v.a + Rational(side) * v.denominator, v.b, v.d, v.denominator};
  return side < 0 ? rational_between(shifted, v) : rational_between(v, shifted);
}

// Whether the point lies strictly inside the edge, forward from its start to its end.
bool on_edge(const Pair_edge& pe, const Curve_point& p, const Diagram& diagram) {
  const Diagram_edge& e = *pe.edge;
  const Trisector& t = *pe.trisector;
  if (e.closed) return true;
  const auto order = [&](std::size_t v) { return compare_along_trisector(t, diagram.vertices[v].vertex, p); };
  if (pe.kind != Trisector_kind::ellipse)
    return (!e.start || order(*e.start) == Sign::NEGATIVE) && (!e.end || order(*e.end) == Sign::POSITIVE);
  const Sign after_start = order(*e.start), before_end = -order(*e.end);
  if (after_start == Sign::ZERO || before_end == Sign::ZERO) return false;
  const Sign start_to_end = *e.start == *e.end ? Sign::ZERO
                            : compare_along_trisector(t, diagram.vertices[*e.start].vertex, diagram.vertices[*e.end].vertex);
  if (start_to_end == Sign::NEGATIVE) return after_start == Sign::NEGATIVE && before_end == Sign::NEGATIVE;
  return after_start == Sign::NEGATIVE || before_end == Sign::NEGATIVE;  // wraps (or a loop at one vertex)
}

// Disjoint sets of components.
struct Union_find {
  std::vector<std::size_t> parent;
  explicit Union_find(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), std::size_t{0}); }
  std::size_t find(std::size_t x) { return parent[x] == x ? x : parent[x] = find(parent[x]); }
  void join(std::size_t x, std::size_t y) { parent[find(x)] = find(y); }
};

}  // namespace

Face_grouping group_components(const std::vector<Site>& sites, const Diagram& diagram,
                               const std::vector<Diagram_edge>& edges,
                               const std::vector<const Boundary_component*>& components,
                               const Cancellation* cancellation, Level_lines lines) {
  const Site_index a = components.front()->a, b = components.front()->b;
  std::vector<Pair_edge> pair_edges;
  for (std::size_t c = 0; c < components.size(); ++c)
    for (std::size_t id : components[c]->edges) {
      const Diagram_edge& e = edges[id];
      const std::array<Site_index, 3> triple{e.tie_set[0], e.tie_set[1], e.tie_set[2]};
      auto t = std::make_unique<Trisector>(triple, std::array<Site, 3>{sites[triple[0]], sites[triple[1]], sites[triple[2]]});
      const Trisector_kind kind = classify_trisector(*t).first;
      pair_edges.push_back({c, &e, std::move(t), kind});
    }

  // A direction e across the pair (orthogonal to p_b - p_a) whose level planes contain no edge's plane, and
  // the direction d along the levels on the sheet.
  const Vector3 n{Rational(sites[b].x) - Rational(sites[a].x), Rational(sites[b].y) - Rational(sites[a].y),
                  Rational(sites[b].z) - Rational(sites[a].z)};
  Vector3 e{}, d{};
  bool found = false;
  // Nor an asymptote of a hyperbola edge: a level limit along an end would be a critical height that no
  // vertex or extreme point gives, and the lines on its far side would miss the edge. Each edge's plane
  // rules out at most one direction e across the pair (its normal), and the axes (1, j, j^2) give pairwise
  // independent directions (two values of j at most); a level asymptote is a quartic in j, not zero
  // everywhere (the sheet is a graph over the plane across the pair, paper Theorem 3, so no asymptote is
  // parallel to p_b - p_a): some j among the first 6 k + 4 works.
  for (std::size_t j = 0; j < 6 * pair_edges.size() + 4 && !found; ++j) {
    const Vector3 axis{Rational(1), Rational(static_cast<long>(j)), Rational(static_cast<long>(j * j))};
    e = cross(n, axis);
    if (is_zero(e)) continue;
    found = std::none_of(pair_edges.begin(), pair_edges.end(), [&](const Pair_edge& pe) {
      return parallel_to_plane(*pe.trisector, level_cut(e)) || level_asymptote(*pe.trisector, level_cut(e));
    });
  }
  if (!found) throw std::logic_error("face nesting: no level direction crosses every edge of the pair");
  d = cross(n, e);

  const Level_direction across(e), along(d);
  const auto sort_and_merge = [](std::vector<Level_value>& heights) {
    std::sort(heights.begin(), heights.end(),
              [](const Level_value& x, const Level_value& y) { return compare_levels(x, y) == Sign::NEGATIVE; });
    const auto tie = [](const Level_value& x, const Level_value& y) { return compare_levels(x, y) == Sign::ZERO; };
    heights.erase(std::unique(heights.begin(), heights.end(), tie), heights.end());
  };
  // One line, sorted along d: the crossings of the pair's edges with the level e . v = y on the sheet.
  struct Crossing {
    Level_value abscissa;
    std::size_t edge;
    Curve_point point;
  };
  const auto crossings_at = [&](const Rational& y) {
    std::vector<Crossing> crossings;
    for (std::size_t i = 0; i < pair_edges.size(); ++i) {
      const Trisector& t = *pair_edges[i].trisector;
      for (const Curve_point& p : curve_points(t, across.cut, level_offset(e, t.origin(), y)))
        if (on_sheet(p) && on_edge(pair_edges[i], p, diagram)) crossings.push_back({Level_value(t, p, along), i, p});
    }
    std::sort(crossings.begin(), crossings.end(),
              [](const Crossing& x, const Crossing& y) { return compare_levels(x.abscissa, y.abscissa) == Sign::NEGATIVE; });
    return crossings;
  };
  // Whether the face lies on the +d side of a line's first crossing.
  const auto face_after = [&](const Crossing& first_crossing) {
    const Pair_edge& first = pair_edges[first_crossing.edge];
    Site_index third = a;
    for (Site_index s : first.edge->tie_set)
      if (s != a && s != b) third = s;
    return face_side(first_crossing.point, sites[a], sites[b], sites[third], e, d) == Sign::POSITIVE;
  };
  // One closed cycle alone (the usual nested pair: a ball between a and b cuts a hole in their face, or
  // their face is a disc): the face is its inside or its outside. A level strictly between the cycle's
  // lowest and highest points crosses it (it is connected); at a level that is no critical height the line
  // passes from one side to the other at every crossing, and its two ends lie outside the cycle. The face is
  // bounded exactly when the line enters it at its first crossing: one line instead of one per slab (the
  // tests check the sweep below agrees: lines = every_slab).
  const bool one_cycle = lines == Level_lines::fewest && components.size() == 1 && components.front()->closed;
  const auto one_face = [&](const std::vector<Crossing>& crossings) {
    if (crossings.size() < 2 || crossings.size() % 2 != 0)
      throw std::logic_error("face nesting: a level line inside a closed cycle does not cross it in pairs");
    Face_grouping grouping;
    grouping.faces.push_back({0});
    grouping.bounded.push_back(face_after(crossings.front()));
    return grouping;
  };

  // Critical heights: the vertices', then the extreme points'.
  std::vector<Level_value> heights;
  std::vector<std::size_t> vertices_seen;  // a vertex ends several edges: one height
  for (const Pair_edge& pe : pair_edges) {
    throw_if_cancelled(cancellation);
    for (const std::optional<std::size_t>& v : {pe.edge->start, pe.edge->end}) {
      if (!v || std::find(vertices_seen.begin(), vertices_seen.end(), *v) != vertices_seen.end()) continue;
      vertices_seen.push_back(*v);
      heights.emplace_back(*pe.trisector, diagram.vertices[*v].vertex, across);
    }
  }
  sort_and_merge(heights);
  // A cycle through vertices at two heights or more: a level between the lowest two lies strictly inside the
  // cycle's range, and it is no vertex's height. It is no extreme point's either when the line touches no
  // edge (a double root, SINGLE; a transversal single root, where the cut's quadratic is linear, is taken
  // as one too): then the extreme points, rational constructions that were most of this function's time,
  // are not needed.
  if (one_cycle && heights.size() >= 2) {
    const std::size_t gap = widest_gap(heights);
    const std::vector<Crossing> crossings = crossings_at(level_between(heights[gap], heights[gap + 1]));
    const auto touches = [](const Crossing& c) { return c.point.root() == Root::SINGLE; };
    if (std::none_of(crossings.begin(), crossings.end(), touches)) return one_face(crossings);
  }
  for (const Pair_edge& pe : pair_edges) {
    const Trisector& t = *pe.trisector;
    // Where the tangent is level: the tangent at X is the direction of L Lorentz-orthogonal to X
    // (trisector.h), and the level direction of L is N, Euclidean-orthogonal to R_b, R_c and (e / 2, 0)
    // (one direction: L is not parallel to the levels); so <X, N> = 0, a cut from the input alone.
    const Vector4<Rational> N = orthogonal_direction(relative_site<Rational>(t.origin(), t.sites()[1]).row,
                                                     relative_site<Rational>(t.origin(), t.sites()[2]).row,
                                                     across.cut);
    for (const Curve_point& p : curve_points(t, {N[0], N[1], N[2], -N[3]}, Rational(0)))
      if (on_sheet(p) && on_edge(pe, p, diagram)) heights.emplace_back(t, p, across);
  }
  sort_and_merge(heights);
  // Every slab lies strictly between the cycle's lowest and highest points, at no critical height.
  if (one_cycle && heights.size() >= 2) {
    const std::size_t gap = widest_gap(heights);
    return one_face(crossings_at(level_between(heights[gap], heights[gap + 1])));
  }

  std::vector<Rational> levels;
  if (heights.empty()) {
    levels.push_back(0);
  } else {
    levels.push_back(level_beyond(heights.front(), -1));
    for (std::size_t i = 0; i + 1 < heights.size(); ++i) levels.push_back(level_between(heights[i], heights[i + 1]));
    levels.push_back(level_beyond(heights.back(), +1));
  }

  Union_find sets(components.size());
  std::vector<bool> unbounded(components.size(), false), crossed(components.size(), false);
  // The far ends of the lines: no edge's level stays bounded along its ends (no level asymptote, above), so
  // beyond all crossings, on the left of the lines (d -> -infinity) between any two levels, no edge
  // passes: the left ends of all lines lie in one piece of the face or all outside it, and so do the right
  // ends. A line that no edge crosses joins its two ends.
  std::optional<std::size_t> far_left, far_right;  // a component next to the far left (right) in the face
  std::optional<bool> left_in_face;                 // whether the far left is in the face
  bool crossing_free_line = false;
  for (std::size_t l = 0; l < levels.size(); ++l) {
    throw_if_cancelled(cancellation);
    const std::vector<Crossing> crossings = crossings_at(levels[l]);
    if (crossings.empty()) {
      crossing_free_line = true;
      continue;
    }
    // The face at the first crossing: on its +d side or before it; then it alternates.
    const bool after_first = face_after(crossings.front());
    const bool outermost = l == 0 || l + 1 == levels.size();
    bool inside = !after_first;  // before the first crossing
    if (left_in_face && *left_in_face != inside)
      throw std::logic_error("face nesting: the far ends of the level lines are not all on one side");
    left_in_face = inside;
    std::optional<std::size_t> left;  // the component at the interval's left end
    for (std::size_t k = 0; k <= crossings.size(); ++k) {
      const std::optional<std::size_t> right =
          k < crossings.size() ? std::optional<std::size_t>(pair_edges[crossings[k].edge].component) : std::nullopt;
      if (right) crossed[*right] = true;
      if (inside) {
        if (left && right) sets.join(*left, *right);
        for (auto [end, far] : {std::pair{right, &far_left}, std::pair{left, &far_right}})
          if (end && !(left && right)) {
            if (*far) sets.join(**far, *end);
            *far = end;
          }
        for (const std::optional<std::size_t>& end : {left, right})
          if (end && (!left || !right || outermost)) unbounded[*end] = true;
      }
      left = right;
      inside = !inside;
    }
  }
  if (crossing_free_line && far_left && far_right) sets.join(*far_left, *far_right);
  for (std::size_t c = 0; c < components.size(); ++c)
    if (!crossed[c]) throw std::logic_error("face nesting: a boundary component no level line crosses");

  Face_grouping grouping;
  std::vector<std::size_t> face_of(components.size(), static_cast<std::size_t>(-1));
  for (std::size_t c = 0; c < components.size(); ++c) {
    const std::size_t root = sets.find(c);
    if (face_of[root] == static_cast<std::size_t>(-1)) {
      face_of[root] = grouping.faces.size();
      grouping.faces.emplace_back();
      grouping.bounded.push_back(true);
    }
    grouping.faces[face_of[root]].push_back(c);
    if (unbounded[c] || !components[c]->closed) grouping.bounded[face_of[root]] = false;
  }
  return grouping;
}

}  // namespace apollonius
