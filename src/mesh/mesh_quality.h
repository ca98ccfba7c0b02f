// The five triangle quality measures of the paper's Table 1 (after [RPH03]), each 1 for an equilateral
// triangle: 3 a_min / pi, l_min / l_max, 4 sqrt(3) S / (l1^2 + l2^2 + l3^2), 2 r / R, 2 sqrt(3) r / l_min
// (a_min the least angle, S the area, r and R the inscribed and circumscribed radii).
#pragma once

#include <array>
#include <cstddef>

#include "mesh/diagram_mesh.h"

namespace apollonius {

struct Triangle_quality {
  std::array<double, 5> values;  // in the order above
};

inline constexpr std::array<const char*, 5> kQualityNames{"3 a_min / pi", "l_min / l_max", "4 sqrt3 S / sum l^2",
                                                          "2 r / R", "2 sqrt3 r / l_min"};

Triangle_quality triangle_quality(const Point3& a, const Point3& b, const Point3& c);

// Minimum and mean of each measure over the faces' triangles (walls left out).
struct Mesh_quality {
  std::array<double, 5> minimum{}, mean{};
  std::size_t triangles = 0;
};

Mesh_quality mesh_quality(const Diagram_mesh& mesh);

}  // namespace apollonius
