#include "predicates/vertex_rounding.h"

#include <cmath>
#include <limits>

#include "predicates/correct_rounding.h"
#include "predicates/double_double_ball.h"
#include "predicates/quadruple_line.h"

namespace apollonius {
namespace {

// The double nearest to every number of [centre + offset - error, centre + offset + error], if one double
// is, for a double centre: every such number lies strictly between the midpoints around the centre.
std::optional<double> rounding_around(double centre, double offset_magnitude, double error) {
  if (!std::isfinite(centre) || !(std::fabs(centre) >= 0x1p-1000)) return std::nullopt;
  constexpr double inf = std::numeric_limits<double>::infinity();
  const double up = std::nextafter(centre, inf) - centre, down = centre - std::nextafter(centre, -inf);
  if ((offset_magnitude + error) * (1 + 8 * kUnitRoundoff) < std::fmin(up, down) / 2) return centre;
  return std::nullopt;
}

std::optional<double> certified_rounding(const Double_double_ball& x) {
  if (!x.usable()) return std::nullopt;
  return rounding_around(x.hi, std::fabs(x.lo), x.error);
}

Double_double_ball half(const Double_double_ball& x) { return {x.hi / 2, x.lo / 2, x.error / 2}; }

// v_j = o_j + X_j / 2 and r = X_3 / 2 - w_0 with X_j = (Q_j A - B n_j + sigma n_j sqrt(discriminant)) / (A n_k)
// (quadruple_line.h); throws Uncertain_sign when double-double precision cannot tell the structure.
std::array<std::optional<double>, 4> certified_roundings_or_throw(const Vertex& v) {
  using Ball = Double_double_ball;
  const Quadruple_line<Ball> line = quadruple_line<Ball>(v.quadruple().sites);
  if (line.pivot < 0) throw Uncertain_sign();
  certain_sign(line.A);  // a single root with A = 0 (or an unsure A) goes to the exact stage
  const Ball root_term = v.root() == Root::SINGLE ? Ball(0) : square_root(line.discriminant);
  const Ball reciprocal = quotient(Ball(1), line.A * line.n[line.pivot]);
  const Site& o = v.origin();
  const double offset[4] = {o.x, o.y, o.z, -o.w};
  std::array<std::optional<double>, 4> result;
  for (int j = 0; j < 4; ++j) {
    Ball numerator = line.Q[j] * line.A - line.B * line.n[j];
    if (v.root() == Root::PLUS) numerator = numerator + line.n[j] * root_term;
    if (v.root() == Root::MINUS) numerator = numerator - line.n[j] * root_term;
    result[j] = certified_rounding(Ball(offset[j]) + half(numerator * reciprocal));
  }
  return result;
}

}  // namespace

std::array<std::optional<double>, 4> certified_roundings(const Vertex& v) {
  try {
    return certified_roundings_or_throw(v);
  } catch (const Uncertain_sign&) {
    return {};
  }
}

const std::array<double, 4>& Vertex::rounded() const {
  return rounded_.get_or_compute([&] { return rounded_coordinates(*this); });
}

const std::array<Sign, 3>& Vertex::rounding_sides() const {
  return sides_.get_or_compute([&] {
    const std::array<double, 4>& r = rounded();
    const std::array<Root_number<Exact>, 4> p = exact_point(*this);
    std::array<Sign, 3> sides;
    // A coordinate beyond the double range rounds to an infinity, which no box bound equals: never asked.
    for (int a = 0; a < 3; ++a)
      sides[a] = std::isfinite(r[a]) ? compare(p[a], Root_number<Exact>{Exact(r[a]), Exact(0), Exact(0), Exact(1)}) : Sign::ZERO;
    return sides;
  });
}

std::array<double, 4> rounded_coordinates(const Vertex& v) {
  const std::array<std::optional<double>, 4> fast = certified_roundings(v);
  std::array<double, 4> rounded;
  bool all = true;
  for (int j = 0; j < 4; ++j) {
    if (fast[j]) rounded[j] = *fast[j];
    all = all && fast[j].has_value();
  }
  if (all) return rounded;
  const std::array<Root_number<Exact>, 4> exact = exact_point(v);
  for (int j = 0; j < 4; ++j)
    if (!fast[j]) rounded[j] = to_nearest_double(exact[j]);
  return rounded;
}

}  // namespace apollonius
