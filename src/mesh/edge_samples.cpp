#include "mesh/edge_samples.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace apollonius {

double distance(const Point3& a, const Point3& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

std::vector<double> sample_parameters(const Conic_curve& curve, double t0, double t1, const Local_step& step,
                                      std::size_t least_segments) {
  // A fine walk (chords of about an eighth of the local step) tabulates sigma = integral of ds / step, then
  // the samples divide sigma evenly.
  std::vector<double> ts{t0}, sigma{0};
  double t = t0, dt = (t1 - t0) / 64;
  Point3 x = curve.position(t0);
  while (t < t1) {
    dt = std::min(dt, t1 - t);
    const Point3 y = curve.position(t + dt);
    const double h = step(x), chord = distance(x, y);
    if (chord > h / 6 && dt > (t1 - t0) * 1e-12) {
      dt /= 2;
      continue;
    }
    t = (dt == t1 - t) ? t1 : t + dt;
    sigma.push_back(sigma.back() + chord / h);
    ts.push_back(t);
    x = y;
    if (chord < h / 16) dt *= 1.5;
  }
  const double total = sigma.back();
  const std::size_t n = std::max<std::size_t>(least_segments, static_cast<std::size_t>(std::lround(total)));
  std::vector<double> out{t0};
  std::size_t k = 0;
  for (std::size_t i = 1; i < n; ++i) {
    const double target = total * static_cast<double>(i) / static_cast<double>(n);
    while (sigma[k + 1] < target) ++k;
    const double f = (target - sigma[k]) / (sigma[k + 1] - sigma[k]);
    out.push_back(ts[k] + f * (ts[k + 1] - ts[k]));
  }
  out.push_back(t1);
  return out;
}

double walk_until(const Conic_curve& curve, double t0, int direction, const Local_step& step,
                  const std::function<bool(const Point3&)>& far, int max_steps) {
  double t = t0, dt = 1e-3;
  Point3 x = curve.position(t);
  for (int i = 0; i < max_steps; ++i) {
    if (far(x)) return t;
    const double h = step(x);
    // Grow or shrink dt until the chord is about one local step.
    for (int k = 0; k < 200; ++k) {
      const double chord = distance(x, curve.position(t + direction * dt));
      if (chord > 2 * h)
        dt /= 2;
      else if (chord < h / 2)
        dt *= 2;
      else
        break;
    }
    t += direction * dt;
    x = curve.position(t);
  }
  throw std::runtime_error("mesh: an infinite edge did not leave the region to mesh");
}

}  // namespace apollonius
