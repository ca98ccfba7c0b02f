#include "predicates/vertex.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include "predicates/correct_rounding.h"
#include "predicates/exact_quadruple_line.h"
#include "predicates/line_roots.h"
#include "predicates/rounding_guard.h"
#include "predicates/vertices_of.h"

namespace apollonius {
namespace {

// Whether x is finite and at most `relative_width` of its magnitude wide (0 is); at 2^-40, an enclosure worth
// keeping.
bool is_tight(const Interval& x, double relative_width = 0x1p-40) {
  const double magnitude = std::max(std::fabs(x.inf()), std::fabs(x.sup()));
  return std::isfinite(magnitude) && x.sup() - x.inf() <= magnitude * relative_width;
}

// An interval holding (a + b sqrt(d)) / denominator. Where a and b sqrt(d) have opposite signs it is taken
// as (a^2 - b^2 d) / (a - b sqrt(d)), whose numerator is exact and whose denominator adds two numbers of one
// sign, so that it stays a few ulps wide where the terms cancel (the vertex near its quadruple's sites
// while the other root is far). That form costs three products of the longest numbers, so the direct
// quotient is kept wherever it is a few ulps (2^-48 of its magnitude) wide already.
Interval enclose_root_number(const Exact& a, const Exact& b, const Exact& d, const Interval& root,
                             const Interval& denominator) {
  const Interval direct = (enclosing_interval(a) + enclosing_interval(b) * root) / denominator;
  const Sign sa = certain_sign(a), sb = certain_sign(b);
  if (sa == Sign::ZERO || sb == Sign::ZERO || sa == sb || is_tight(direct, 0x1p-48)) return direct;
  return enclosing_interval(a * a - b * b * d) / ((enclosing_interval(a) - enclosing_interval(b) * root) * denominator);
}

// Interval enclosure of X 2^-k from the exact value of X. Where D or d lies beyond the double range (sites
// one ulp off a lattice make both underflow, and the plain quotient unbounded, where X is of ordinary
// size), each X_j = (a_j + b_j sqrt(d)) / D is taken as (a_j + b_j 2^t sqrt(d 2^-2t)) / (D 2^-n) 2^-n,
// with exact powers of two that bring D, d, and then a_j and b_j 2^t near 1.
std::array<Interval, 4> enclose(const Vertex_coordinates<Exact>& X, long k = 0) {
  Rounding_guard guard;
  std::array<Interval, 4> box;
  std::array<bool, 4> tight{};  // box[j] is final
  if (k == 0) {  // first as they are: D and d are mostly well within the range
    const Interval root = CGAL::sqrt(enclosing_interval(X.discriminant));
    const Interval denominator = enclosing_interval(X.denominator);
    if (denominator.inf() >= 0x1p-900 && denominator.sup() <= 0x1p900 && root.sup() <= 0x1p900) {
      for (int j = 0; j < 4; ++j) {
        box[j] = enclose_root_number(X.scaled[j].a, X.scaled[j].b, X.discriminant, root, denominator);
        tight[j] = is_tight(box[j]);  // else some part underflowed or overflowed (a coordinate near 5e-324)
      }
      if (std::all_of(tight.begin(), tight.end(), [](bool t) { return t; })) return box;
    }
  }
  const int n = static_cast<int>(binary_exponent(X.denominator));  // D > 0
  const bool has_root = certain_sign(X.discriminant) != Sign::ZERO;
  const int t = has_root ? static_cast<int>(binary_exponent(X.discriminant) / 2) : 0;
  const Exact d = has_root ? times_power_of_two(X.discriminant, -2 * t) : Exact(0);
  const Interval root = CGAL::sqrt(enclosing_interval(d));
  const Interval denominator = enclosing_interval(times_power_of_two(X.denominator, -n));
  // An ordinary X_j has parts a and b sqrt(d) about as large as D: the shift that brings D near 1 brings them
  // near X_j, and their own exponents are needed only where that is not tight.
  // Only for the plain box (k = 0): the X_j of a scaled box lie beyond the double range.
  const Exact down = times_power_of_two(Exact(1), -n), root_down = times_power_of_two(Exact(1), t - n);
  for (int j = 0; j < 4; ++j) {
    if (tight[j]) continue;
    if (k == 0) {
      const Interval near_x = enclose_root_number(X.scaled[j].a * down, X.scaled[j].b * root_down, d, root, denominator);
      if (is_tight(near_x)) {
        box[j] = near_x;
        continue;
      }
    }
    // X_j = (a + b sqrt(d)) 2^(m - n) / D with a, b (a part each) brought near 1 by 2^-m as well.
    const Exact& a = X.scaled[j].a;
    const Exact b = times_power_of_two(X.scaled[j].b, t);
    long m = std::numeric_limits<long>::min();
    for (const Exact* part : {&a, &b})
      if (certain_sign(*part) != Sign::ZERO) m = std::max(m, binary_exponent(*part));
    if (m == std::numeric_limits<long>::min()) {  // X_j = 0
      box[j] = Interval(0);
      continue;
    }
    const int shift = static_cast<int>(m);
    const Interval near_one = enclose_root_number(times_power_of_two(a, -shift), times_power_of_two(b, -shift), d, root, denominator);
    box[j] = times_power_of_two(near_one, static_cast<int>(m - n - k));
  }
  return box;
}

// Where a plain box's products with site coordinates stop being normal doubles.
constexpr long kPlainRange = 500;

// X at the largest coordinate's exponent (MPFR), where that lies beyond 2^+-kPlainRange; else nothing.
std::optional<Scaled_box> scaled_enclosure(const Vertex_coordinates<Exact>& X) {
  std::optional<long> largest;
  for (const Quadratic<Exact>& x : X.scaled)
    if (const std::optional<long> e = binary_exponent(Root_number<Exact>{x.a, x.b, X.discriminant, X.denominator}))
      largest = std::max(largest.value_or(*e), *e);
  if (!largest || (*largest <= kPlainRange && *largest >= -kPlainRange)) return std::nullopt;
  return Scaled_box{*largest, enclose(X, *largest)};
}

}  // namespace

Vertex::Vertex(const Quadruple& quadruple, Root root, Vertex_coordinates<Exact> exact)
    : quadruple_(quadruple),
      root_(root),
      exact_(std::move(exact)) {
  enclose_exact();
}

void Vertex::enclose_exact() {
  box_.scaled = enclose(*exact_.get());
  double magnitude = 0;
  for (const Interval& x : box_.scaled) magnitude = std::max({magnitude, -x.inf(), x.sup()});
  scaled_box_on_demand_ = !(magnitude >= std::ldexp(1.0, -kPlainRange) && magnitude <= std::ldexp(1.0, kPlainRange));
}

const Scaled_box* Vertex::scaled_box() const {
  const std::optional<Scaled_box>* box =
      scaled_box_on_demand_ ? &scaled_box_.get_or_compute([&] { return scaled_enclosure(coordinates<Exact>()); })
                            : scaled_box_.get();
  return box != nullptr && *box ? &**box : nullptr;
}

template <>
const Vertex_coordinates<Exact>& Vertex::coordinates<Exact>() const {
  return exact_.get_or_compute([&] {
    const Quadruple_line<Exact> line = exact_quadruple_line(quadruple_.sites);
    if (line.pivot >= 0) {
      const Line_roots<Exact> roots = *line_roots(line);  // Exact signs are always certain
      for (const Line_root<Exact>& r : roots.roots)
        if (r.root == root_) return coordinates_on_line(line, r.lambda);
    }
    throw std::logic_error("vertex root vanished in exact recomputation");
  });
}

void Vertex::release_exact_values() {
  exact_.reset();
  ball_.reset();
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

// The plain box (infinite, or rounded outward into the subnormals, beyond the double range), and the
// scaled box at the largest coordinate's exponent where that lies beyond 2^+-500, as for exact coordinates.
Vertex make_vertex(const Quadruple& q, Root root, Vertex_coordinates<Wide_interval> X) {
  std::array<Interval, 4> box;
  std::optional<long> largest;
  for (int j = 0; j < 4; ++j) {
    box[j] = X.scaled[j].to_interval();
    const Interval& m = X.scaled[j].mantissa();
    if (m.inf() != 0 || m.sup() != 0) largest = std::max(largest.value_or(X.scaled[j].exponent()), X.scaled[j].exponent());
  }
  if (!largest || (*largest <= kPlainRange && *largest >= -kPlainRange)) return Vertex(q, root, box);
  Scaled_box scaled{*largest, {}};
  for (int j = 0; j < 4; ++j) scaled.scaled[j] = X.scaled[j].scaled_down(*largest);
  return Vertex(q, root, box, scaled);
}

Vertex make_vertex(const Quadruple& q, Root root, Vertex_coordinates<Exact> X) {
  return Vertex(q, root, std::move(X));
}

Quadruple make_quadruple(std::array<Site_index, 4> indices, const std::vector<Site>& sites) {
  std::sort(indices.begin(), indices.end());
  Quadruple q;
  q.indices = indices;
  for (int m = 0; m < 4; ++m) q.sites[m] = sites.at(indices[m]);
  return q;
}

}  // namespace apollonius
