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

// The minor n_k is (+-) of, from the site differences alone.
template <class NT>
NT null_vector_minor(const std::array<Site, 4>& sites, int k) {
  std::array<std::array<NT, 3>, 3> rows;
  for (int m = 0; m < 3; ++m) {
    const Relative_site<NT> r = relative_site<NT>(sites[0], sites[m + 1]);
    for (int j = 0, t = 0; j < 4; ++j)
      if (j != k) rows[m][t++] = r.row[j];
  }
  return rows[0][0] * (rows[1][1] * rows[2][2] - rows[1][2] * rows[2][1]) -
         rows[0][1] * (rows[1][0] * rows[2][2] - rows[1][2] * rows[2][0]) +
         rows[0][2] * (rows[1][0] * rows[2][1] - rows[1][1] * rows[2][0]);
}

}  // namespace

// Intervals first: on a lattice the minor is computed exactly, a point, and [0, 0] is a certain zero.
bool null_vector_entry_nonzero(const std::array<Site, 4>& sites, int k) {
  {
    const Rounding_guard guard;
    if (const std::optional<Sign> s = sign_if_certain(null_vector_minor<Interval>(sites, k))) return *s != Sign::ZERO;
  }
  return certain_sign(null_vector_minor<Exact>(sites, k)) != Sign::ZERO;
}

Sign null_vector_entry_sign(const std::array<Site, 4>& sites, int k) {
  const Sign parity = k % 2 == 0 ? Sign::POSITIVE : Sign::NEGATIVE;  // n_k = (-1)^k times the minor
  {
    const Rounding_guard guard;
    if (const std::optional<Sign> s = sign_if_certain(null_vector_minor<Interval>(sites, k))) return parity * *s;
  }
  return parity * certain_sign(null_vector_minor<Exact>(sites, k));
}

Quadruple_line<Exact> exact_quadruple_line(const std::array<Site, 4>& sites) {
  std::optional<Quadruple_line<Exact>> line = line_from_point_minors(sites);
  if (!line) return quadruple_line<Exact>(sites);
  if (line->pivot >= 0) set_cone_terms(*line);
  return *line;
}

}  // namespace apollonius
