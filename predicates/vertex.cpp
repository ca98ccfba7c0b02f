#include "predicates/vertex.h"

#include <algorithm>
#include <stdexcept>

#include "predicates/line_roots.h"
#include "predicates/rounding_guard.h"
#include "predicates/vertices_of.h"

namespace apollonius {
namespace {

// Interval enclosure of X from its exact value.
Vertex_coordinates<Interval> enclose(const Vertex_coordinates<Exact>& X) {
  Rounding_guard guard;
  Vertex_coordinates<Interval> box;
  const Interval root = CGAL::sqrt(enclosing_interval(X.discriminant));
  const Interval denominator = enclosing_interval(X.denominator);
  for (int j = 0; j < 4; ++j)
    box.scaled[j] = (enclosing_interval(X.scaled[j].a) + enclosing_interval(X.scaled[j].b) * root) / denominator;
  return box;
}

}  // namespace

Vertex::Vertex(const Quadruple& quadruple, Root root, std::shared_ptr<const Vertex_coordinates<Exact>> exact)
    : quadruple_(quadruple), root_(root), box_(enclose(*exact)), exact_(std::move(exact)) {}

template <>
const Vertex_coordinates<Exact>& Vertex::coordinates<Exact>() const {
  if (!exact_) {
    const Quadruple_line<Exact> line = quadruple_line<Exact>(quadruple_.sites);
    if (line.pivot >= 0) {
      for (const Line_root<Exact>& r : line_roots(line).roots)
        if (r.root == root_) exact_ = std::make_shared<const Vertex_coordinates<Exact>>(coordinates_on_line(line, r.lambda));
    }
    if (!exact_) throw std::logic_error("vertex root vanished in exact recomputation");
  }
  return *exact_;
}

std::array<Interval, 4> Vertex::point_interval() const {
  Rounding_guard guard;
  const Site& o = origin();
  const Interval half(0.5);
  return {Interval(o.x) + box_.scaled[0] * half, Interval(o.y) + box_.scaled[1] * half,
          Interval(o.z) + box_.scaled[2] * half, box_.scaled[3] * half - Interval(o.w)};
}

std::array<Root_number<Exact>, 4> exact_point(const Vertex& v) {
  const Vertex_coordinates<Exact>& X = v.coordinates<Exact>();
  const Site& o = v.origin();
  const Exact twice_denominator = X.denominator * Exact(2);
  // v_j = o_j + X_j / 2 and r = X_3 / 2 - w_0, over the denominator 2 D.
  std::array<Root_number<Exact>, 4> p;
  const double offset[4] = {o.x, o.y, o.z, -o.w};
  for (int j = 0; j < 4; ++j)
    p[j] = {X.scaled[j].a + Exact(offset[j]) * twice_denominator, X.scaled[j].b, X.discriminant, twice_denominator};
  return p;
}

Vertex make_vertex(const Quadruple& q, Root root, Vertex_coordinates<Interval> X) { return Vertex(q, root, X.scaled); }

// The floating path's point, as a point interval. A coordinate that overflowed stays infinite (or NaN):
// the two-bound constructor admits both, where Interval(double) asserts a finite value.
Vertex make_vertex(const Quadruple& q, Root root, Vertex_coordinates<double> X) {
  const auto point = [](double x) { return Interval(x, x); };
  return Vertex(q, root, {point(X.scaled[0]), point(X.scaled[1]), point(X.scaled[2]), point(X.scaled[3])});
}

Vertex make_vertex(const Quadruple& q, Root root, Vertex_coordinates<Double_with_error> X) {
  return Vertex(q, root, {enclosing_interval(X.scaled[0]), enclosing_interval(X.scaled[1]), enclosing_interval(X.scaled[2]),
                          enclosing_interval(X.scaled[3])});
}

Vertex make_vertex(const Quadruple& q, Root root, Vertex_coordinates<Exact> X) {
  return Vertex(q, root, std::make_shared<const Vertex_coordinates<Exact>>(std::move(X)));
}

Quadruple make_quadruple(std::array<Site_index, 4> indices, const std::vector<Site>& sites) {
  std::sort(indices.begin(), indices.end());
  Quadruple q;
  q.indices = indices;
  for (int m = 0; m < 4; ++m) q.sites[m] = sites.at(indices[m]);
  return q;
}

}  // namespace apollonius
