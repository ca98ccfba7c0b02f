// Anderson acceleration (type II, D. G. Anderson 1965; H. F. Walker, P. Ni 2011) of a fixed-point
// iteration x <- x + f(x): the plain site step converges linearly like Lloyd's method (about a factor 0.85
// per iteration on the 6-site example, far too slow for 1e-6 in 20 iterations); mixing the last few steps
// by least squares converges much faster. Safeguard: the history restarts when the residual grows, and
// the caller falls back to the plain step when the mixed one fails its checks.
#pragma once

#include <deque>
#include <vector>

namespace apollonius {

class Anderson_acceleration {
 public:
  explicit Anderson_acceleration(std::size_t depth) : depth_(depth) {}

  // The accelerated step from x with the plain step f (same length). Records x and f.
  std::vector<double> step(const std::vector<double>& x, const std::vector<double>& f);

  void restart() { xs_.clear(), fs_.clear(); }

 private:
  std::size_t depth_;
  std::deque<std::vector<double>> xs_, fs_;  // the last depth + 1 iterates and plain steps
};

}  // namespace apollonius
