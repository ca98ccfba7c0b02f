#include "lipschitz_filter.h"

#include <algorithm>
#include <cmath>

namespace apollonius {
namespace {

constexpr double kUnit = 0x1p-53;  // unit roundoff of round-to-nearest doubles
// Sums of squares inside [kTiny, kHuge] (or exactly 0) keep the relative error bounds of
// ERROR_BOUNDS.md: underflowed terms are then negligible and nothing overflows.
constexpr double kTiny = 0x1p-960, kHuge = 0x1p960;

bool in_range(double sum_of_squares) { return sum_of_squares == 0 || (sum_of_squares >= kTiny && sum_of_squares <= kHuge); }

double squared_norm(double a, double b, double c) { return a * a + b * b + c * c; }

}  // namespace

Lipschitz_filter::Lipschitz_filter(const Axis_box& box, const Site& witness) : box_(box), witness_(witness) {
  double reach_squared = 0;
  for (int a = 0; a < 3; ++a) {
    centre_[a] = box.lo[a] + (box.hi[a] - box.lo[a]) / 2;  // any point of the box will do
    const double e = std::max(centre_[a] - box.lo[a], box.hi[a] - centre_[a]);
    reach_squared += e * e;
  }
  reach_ = std::sqrt(reach_squared);
  const double w2 = squared_norm(centre_[0] - witness.x, centre_[1] - witness.y, centre_[2] - witness.z);
  witness_distance_ = std::sqrt(w2);
  witness_rho_ = distance_to_box(witness);
  usable_ = in_range(reach_squared) && in_range(w2) && std::isfinite(witness.w) && std::fabs(witness.w) <= kHuge;
}

double Lipschitz_filter::distance_to_box(const Site& s) const {
  const double c[3] = {s.x, s.y, s.z};
  double sum = 0;
  for (int a = 0; a < 3; ++a) {
    const double d = c[a] < box_.lo[a] ? box_.lo[a] - c[a] : c[a] > box_.hi[a] ? c[a] - box_.hi[a] : 0;
    sum += d * d;
  }
  return in_range(sum) ? std::sqrt(sum) : -1;
}

bool Lipschitz_filter::witness_dominates(const Site& s) const {
  if (!usable_ || witness_rho_ < 0 || std::fabs(s.w) > kHuge) return false;
  const double a2 = squared_norm(centre_[0] - s.x, centre_[1] - s.y, centre_[2] - s.z);
  if (!in_range(a2)) return false;
  const double distance = std::sqrt(a2);
  const double gap = (distance - s.w) - (witness_distance_ - witness_.w);
  if (!(gap > 0)) return false;
  const double s2 = squared_norm(s.x - witness_.x, s.y - witness_.y, s.z - witness_.z);
  const double rho = distance_to_box(s);
  if (!in_range(s2) || rho < 0) return false;
  const double rho_sum = rho + witness_rho_;
  const double lipschitz = rho_sum > 0 ? std::min(2.0, 2 * std::sqrt(s2) / rho_sum) : 2.0;
  // ERROR_BOUNDS.md, "Lipschitz filter": both sides with their rounding errors, generously bounded.
  const double error = 16 * kUnit * (distance + witness_distance_ + std::fabs(s.w) + std::fabs(witness_.w) + gap);
  return gap > lipschitz * reach_ * (1 + 64 * kUnit) + error;
}

}  // namespace apollonius
