// An orthonormal frame around a unit vector, in doubles: for coordinates and quadrature only, never a
// decision. Shared by the measures (exit_regions.h) and the mesh (bisector_frame.h).
#pragma once

#include <array>
#include <cmath>
#include <utility>

namespace apollonius {

// Two unit vectors (u1, u2) with (u1, u2, n) orthonormal and right-handed, n a unit vector: u1 is the axis
// direction least aligned with n, made orthogonal to it; u2 = n x u1.
inline std::pair<std::array<double, 3>, std::array<double, 3>> orthonormal_complement(const std::array<double, 3>& n) {
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(n[i]) < std::abs(n[k])) k = i;
  std::array<double, 3> u1{0, 0, 0};
  u1[k] = 1;
  const double along = n[k];
  u1 = {u1[0] - along * n[0], u1[1] - along * n[1], u1[2] - along * n[2]};
  const double length = std::sqrt(u1[0] * u1[0] + u1[1] * u1[1] + u1[2] * u1[2]);
  u1 = {u1[0] / length, u1[1] / length, u1[2] / length};
  return {u1, {n[1] * u1[2] - n[2] * u1[1], n[2] * u1[0] - n[0] * u1[2], n[0] * u1[1] - n[1] * u1[0]}};
}

}  // namespace apollonius
