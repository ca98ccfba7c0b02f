#include "centroidal/median_step.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace apollonius {

Median_steps median_steps(const std::vector<Site>& sites, const std::vector<Cell_measure>& measures,
                          const Axis_box& domain) {
  Median_steps result;
  result.step.assign(sites.size(), Vector3{0, 0, 0});
  for (std::size_t i = 0; i < sites.size(); ++i) {
    const Cell_measure& m = measures[i];
    if (!(m.volume > 0)) continue;
    const std::array<double, 6>& h = m.median_hessian;  // xx yy zz xy xz yz
    Eigen::Matrix3d hessian;
    hessian << h[0], h[3], h[4], h[3], h[1], h[5], h[4], h[5], h[2];
    const Eigen::Vector3d gradient(m.direction_integral[0], m.direction_integral[1], m.direction_integral[2]);
    const Eigen::Vector3d newton = hessian.ldlt().solve(gradient);
    if (!newton.allFinite()) continue;
    // The largest fraction of the step that keeps the site nine tenths of the way at most to each wall.
    const Vector3 x{sites[i].x, sites[i].y, sites[i].z};
    double fraction = 1;
    for (int a = 0; a < 3; ++a) {
      if (newton[a] > 0) fraction = std::min(fraction, 0.9 * (domain.hi[a] - x[a]) / newton[a]);
      if (newton[a] < 0) fraction = std::min(fraction, 0.9 * (domain.lo[a] - x[a]) / newton[a]);
    }
    fraction = std::max(fraction, 0.0);
    if (fraction < 1) result.shortened.push_back(static_cast<Site_index>(i));
    for (int a = 0; a < 3; ++a) result.step[i][a] = fraction * newton[a];
  }
  return result;
}

double median_residual(const Cell_measure& m) {
  if (!(m.volume > 0)) return 0;
  const double norm = std::sqrt(dot(m.direction_integral, m.direction_integral));
  return (norm + m.direction_error) / m.volume;
}

}  // namespace apollonius
