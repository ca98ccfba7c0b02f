#include "predicates/vertex_rounding.h"

#include <cmath>
#include <limits>

#include "predicates/correct_rounding.h"
#include "predicates/double_double_ball.h"
#include "predicates/vertex_ball.h"

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

}  // namespace

// v_j = o_j + X_j / 2 and r = X_3 / 2 - w_0 from the vertex's balls (vertex_ball.h). Balls computed here
// are not kept: most vertices are rounded once, for output, and would hold them to the end.
std::array<std::optional<double>, 4> certified_roundings(const Vertex& v) {
  std::optional<Ball_coordinates> computed;
  const Ball_coordinates* X = v.ball_coordinates_if_computed();
  if (X == nullptr) {
    computed = ball_coordinates_of(v.quadruple(), v.root());
    if (!computed) return {};
    X = &*computed;
  }
  const Nearest_rounding_guard nearest;
  std::array<std::optional<double>, 4> result;
  for (int j = 0; j < 4; ++j) result[j] = certified_rounding(absolute_coordinate(v.origin(), *X, j));
  return result;
}

const std::array<double, 4>& Vertex::rounded() const {
  return rounded_.get_or_compute([&] { return rounded_coordinates(*this); });
}

const std::array<Sign, 3>& Vertex::rounding_sides() const {
  return sides_.get_or_compute([&] {
    const std::array<double, 4>& r = rounded();
    const Ball_coordinates* X = ball_coordinates();
    std::optional<std::array<Root_number<Exact>, 4>> p;  // exact, where the balls cannot tell
    std::array<Sign, 3> sides;
    // A coordinate beyond the double range rounds to an infinity, which no box bound equals: never asked.
    for (int a = 0; a < 3; ++a) {
      if (!std::isfinite(r[a])) {
        sides[a] = Sign::ZERO;
        continue;
      }
      if (X != nullptr) {
        const Nearest_rounding_guard nearest;
        if (const std::optional<Sign> side = sign_if_certain(absolute_coordinate(origin(), *X, a) - Double_double_ball(r[a]))) {
          sides[a] = *side;
          continue;
        }
      }
      if (!p) p = exact_point(*this);
      sides[a] = compare((*p)[a], Root_number<Exact>{Exact(r[a]), Exact(0), Exact(0), Exact(1)});
    }
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
