#include "centroidal/weight_step.h"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <cmath>

namespace apollonius {

std::vector<double> newton_weight_direction(const std::vector<Cell_measure>& measures,
                                            const std::vector<double>& target_volumes) {
  const std::size_t n = measures.size();
  std::vector<double> direction(n, 0.0);
  // The unknowns: the cells with a volume, but for the largest, which is pinned.
  std::vector<std::ptrdiff_t> unknown(n, -1);
  std::size_t pinned = n;
  for (std::size_t i = 0; i < n; ++i)
    if (measures[i].volume > 0 && (pinned == n || measures[i].volume > measures[pinned].volume)) pinned = i;
  if (pinned == n) return direction;
  std::ptrdiff_t count = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (measures[i].volume > 0 && i != pinned) unknown[i] = count++;
  if (count == 0) return direction;

  std::vector<Eigen::Triplet<double>> entries;
  std::vector<double> diagonal(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    for (const auto& [j, derivative] : measures[i].volume_derivatives) {
      if (measures[j].volume <= 0) continue;
      const double edge = -0.5 * derivative;  // half of -(d m_i / d w_j), the other half from row j
      diagonal[i] += edge, diagonal[j] += edge;
      if (unknown[i] >= 0 && unknown[j] >= 0) {
        entries.emplace_back(unknown[i], unknown[j], -edge);
        entries.emplace_back(unknown[j], unknown[i], -edge);
      }
    }
  }
  Eigen::VectorXd gradient(count);
  for (std::size_t i = 0; i < n; ++i) {
    if (unknown[i] < 0) continue;
    entries.emplace_back(unknown[i], unknown[i], diagonal[i]);
    gradient[unknown[i]] = target_volumes[i] - measures[i].volume;
  }
  Eigen::SparseMatrix<double> laplacian(count, count);
  laplacian.setFromTriplets(entries.begin(), entries.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(laplacian);
  Eigen::VectorXd solution;
  if (solver.info() == Eigen::Success) solution = solver.solve(gradient);
  if (solver.info() != Eigen::Success || !solution.allFinite()) {
    // A face graph split by quadrature noise: a gradient step scaled by the diagonal instead.
    solution = Eigen::VectorXd(count);
    for (std::size_t i = 0; i < n; ++i)
      if (unknown[i] >= 0) solution[unknown[i]] = diagonal[i] > 0 ? gradient[unknown[i]] / diagonal[i] : 0.0;
  }
  double mean = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (unknown[i] >= 0) direction[i] = solution[unknown[i]], mean += direction[i];
  mean /= static_cast<double>(count + 1);
  for (std::size_t i = 0; i < n; ++i)
    if (measures[i].volume > 0) direction[i] -= mean;
  return direction;
}

Directional_derivative directional_derivative(const std::vector<Cell_measure>& measures,
                                              const std::vector<double>& target_volumes,
                                              const std::vector<double>& direction) {
  Directional_derivative d{0, 0};
  for (std::size_t i = 0; i < measures.size(); ++i) {
    d.value += (target_volumes[i] - measures[i].volume) * direction[i];
    d.uncertainty += std::fabs(direction[i]) * measures[i].volume_error;
  }
  return d;
}

}  // namespace apollonius
