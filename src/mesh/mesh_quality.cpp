#include "mesh/mesh_quality.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "mesh/edge_samples.h"

namespace apollonius {

Triangle_quality triangle_quality(const Point3& a, const Point3& b, const Point3& c) {
  constexpr double pi = 3.14159265358979323846, sqrt3 = 1.7320508075688772;
  const double l1 = distance(b, c), l2 = distance(c, a), l3 = distance(a, b);
  const double l_min = std::min({l1, l2, l3}), l_max = std::max({l1, l2, l3});
  const Point3 u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const Point3 n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  const double area = 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  const double perimeter = l1 + l2 + l3;
  const double inradius = perimeter > 0 ? 2 * area / perimeter : 0;
  const double circumradius = area > 0 ? l1 * l2 * l3 / (4 * area) : std::numeric_limits<double>::infinity();
  // The least angle is opposite the shortest side; its sine is 2 S over the product of the other two.
  const double other = l_max * (perimeter - l_min - l_max);
  const double least_angle = other > 0 ? std::asin(std::min(1.0, 2 * area / other)) : 0;
  Triangle_quality q;
  q.values[0] = 3 * least_angle / pi;
  q.values[1] = l_max > 0 ? l_min / l_max : 0;
  q.values[2] = perimeter > 0 ? 4 * sqrt3 * area / (l1 * l1 + l2 * l2 + l3 * l3) : 0;
  q.values[3] = 2 * inradius / circumradius;
  q.values[4] = l_min > 0 ? 2 * sqrt3 * inradius / l_min : 0;
  return q;
}

Mesh_quality mesh_quality(const Diagram_mesh& mesh) {
  Mesh_quality out;
  out.minimum.fill(std::numeric_limits<double>::infinity());
  for (const Mesh_triangle& t : mesh.triangles) {
    if (t.is_wall()) continue;
    const Triangle_quality q =
        triangle_quality(mesh.points[t.vertices[0]], mesh.points[t.vertices[1]], mesh.points[t.vertices[2]]);
    for (int k = 0; k < 5; ++k) out.minimum[k] = std::min(out.minimum[k], q.values[k]), out.mean[k] += q.values[k];
    ++out.triangles;
  }
  if (out.triangles == 0) out.minimum.fill(0);
  for (double& m : out.mean) m /= std::max<std::size_t>(1, out.triangles);
  return out;
}

}  // namespace apollonius
