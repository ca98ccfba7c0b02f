#include "centroidal/anderson_acceleration.h"

#include <Eigen/Dense>

namespace apollonius {

std::vector<double> Anderson_acceleration::step(const std::vector<double>& x, const std::vector<double>& f) {
  const auto norm2 = [](const std::vector<double>& v) {
    double s = 0;
    for (double e : v) s += e * e;
    return s;
  };
  if (!fs_.empty() && (fs_.back().size() != f.size() || norm2(f) > norm2(fs_.back()))) restart();
  xs_.push_back(x), fs_.push_back(f);
  if (xs_.size() > depth_ + 1) xs_.pop_front(), fs_.pop_front();
  const std::size_t m = xs_.size() - 1, n = f.size();
  if (m == 0) return f;
  // min over gamma of |f - dF gamma|, dF's columns the differences of successive steps; the step is then
  // f - (dX + dF) gamma.
  Eigen::MatrixXd dF(n, m), dX(n, m);
  for (std::size_t k = 0; k < m; ++k)
    for (std::size_t i = 0; i < n; ++i) {
      dF(i, k) = fs_[k + 1][i] - fs_[k][i];
      dX(i, k) = xs_[k + 1][i] - xs_[k][i];
    }
  const Eigen::Map<const Eigen::VectorXd> fv(f.data(), static_cast<Eigen::Index>(n));
  const Eigen::VectorXd gamma = dF.colPivHouseholderQr().solve(fv);
  if (!gamma.allFinite()) {
    restart();
    return f;
  }
  const Eigen::VectorXd mixed = fv - (dX + dF) * gamma;
  return std::vector<double>(mixed.data(), mixed.data() + n);
}

}  // namespace apollonius
