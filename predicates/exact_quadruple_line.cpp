#include "predicates/exact_quadruple_line.h"

#include <cmath>
#include <optional>

#include "predicates/rounding_guard.h"

namespace apollonius {
namespace {

// n and Q exactly, if intervals computed every one of them as a point (and decided the pivot).
std::optional<Quadruple_line<Exact>> line_from_point_minors(const std::array<Site, 4>& sites) {
  const Rounding_guard guard;
  Quadruple_line<Interval> line;
  try {
    line = quadruple_line<Interval>(sites);
  } catch (const Uncertain_sign&) {
    return std::nullopt;  // a minor's interval straddles 0: not a point
  }
  // [x, x] with x finite (an overflow rounds outward to [DBL_MAX, inf], never to a point at infinity).
  const auto point = [](const Interval& x) { return x.inf() == x.sup() && std::isfinite(x.inf()); };
  Quadruple_line<Exact> exact;
  exact.pivot = line.pivot;
  for (int j = 0; j < 4; ++j) {
    // Q is only formed past the pivot (quadruple_line.h); its intervals are then checked too.
    if (!point(line.n[j])) return std::nullopt;
    if (line.pivot >= 0 && !point(line.Q[j])) return std::nullopt;
    exact.n[j] = Exact(line.n[j].inf());
    if (line.pivot >= 0) exact.Q[j] = Exact(line.Q[j].inf());
  }
  return exact;
}

}  // namespace

Quadruple_line<Exact> exact_quadruple_line(const std::array<Site, 4>& sites) {
  std::optional<Quadruple_line<Exact>> line = line_from_point_minors(sites);
  if (!line) return quadruple_line<Exact>(sites);
  if (line->pivot >= 0) set_cone_terms(*line);
  return *line;
}

}  // namespace apollonius
