#include "diagram/scale_normalization.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "predicates/rounding_guard.h"
#include "predicates/vertices_of.h"

namespace apollonius {
namespace {

constexpr int kModerateExponent = 32;

bool scales_exactly(double value, int exponent) {
  const double scaled = std::ldexp(value, -exponent);
  return std::isfinite(scaled) && std::ldexp(scaled, exponent) == value;
}

}  // namespace

int normalizing_exponent(const std::vector<Site>& sites, const std::vector<Site_index>& active) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  double lo[3] = {inf, inf, inf}, hi[3] = {-inf, -inf, -inf}, weight = 0;
  for (Site_index i : active) {
    const double c[3] = {sites[i].x, sites[i].y, sites[i].z};
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], c[a]), hi[a] = std::max(hi[a], c[a]);
    weight = std::max(weight, std::fabs(sites[i].w));
  }
  // The spread rounded up is enough to choose the exponent; an infinite spread only needs a large one.
  double extent = weight;
  for (int a = 0; a < 3; ++a) extent = std::max(extent, hi[a] - lo[a]);
  if (!(extent > 0)) return 0;
  int exponent = std::numeric_limits<double>::max_exponent;
  if (std::isfinite(extent)) std::frexp(extent, &exponent);  // extent in [2^(exponent-1), 2^exponent)
  exponent -= 1;
  if (std::abs(exponent) <= kModerateExponent) return 0;
  for (Site_index i : active)
    for (double v : {sites[i].x, sites[i].y, sites[i].z, sites[i].w})
      if (!scales_exactly(v, exponent)) return 0;
  return exponent;
}

std::vector<Site> scaled_sites(const std::vector<Site>& sites, int exponent) {
  std::vector<Site> scaled(sites.size());
  for (std::size_t i = 0; i < sites.size(); ++i)
    scaled[i] = scaled_by_power_of_two(sites[i], -exponent);
  return scaled;
}

Vertex unscaled_vertex(const Vertex& scaled, const std::vector<Site>& sites, int exponent) {
  // X = 2 (v - p_0, r + w_0) scales with the sites; an enclosure times 2^exponent is one (an overflow
  // to infinity included).
  Rounding_guard guard;
  std::array<Interval, 4> box = scaled.coordinates<Interval>().scaled;
  const Interval factor(std::ldexp(1.0, exponent));
  for (Interval& x : box) x = x * factor;
  return Vertex(make_quadruple(scaled.sites(), sites), scaled.root(), box);
}

}  // namespace apollonius
