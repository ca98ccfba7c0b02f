// A Gauss-Kronrod pair on [-1, 1] as plain arrays, from Boost.Math's tables: the (2n+1)-point Kronrod rule
// and the n-point Gauss rule on a subset of its nodes (weight 0 elsewhere), n odd. |Kronrod - Gauss|
// estimates the error of the Gauss rule, so it overestimates that of the Kronrod rule on smooth integrands.
#pragma once

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <vector>

namespace apollonius {

struct Gauss_kronrod_rule {
  std::vector<double> node, kronrod, gauss;
};

// N = 2n + 1 Kronrod nodes with n odd (15, 31, ...): Boost stores the non-negative half, and the Gauss
// nodes are those of even index there (0 included).
template <unsigned N>
Gauss_kronrod_rule make_gauss_kronrod_rule() {
  static_assert(((N - 1) / 2) % 2 == 1, "the Gauss order must be odd");
  using Kronrod = boost::math::quadrature::gauss_kronrod<double, N>;
  using Gauss = boost::math::quadrature::gauss<double, (N - 1) / 2>;
  Gauss_kronrod_rule rule;
  const auto& x = Kronrod::abscissa();
  const auto& wk = Kronrod::weights();
  const auto& wg = Gauss::weights();
  for (unsigned i = 0; i < x.size(); ++i) {
    const double gauss_weight = i % 2 == 0 ? wg[i / 2] : 0.0;
    rule.node.push_back(x[i]), rule.kronrod.push_back(wk[i]), rule.gauss.push_back(gauss_weight);
    if (i > 0) rule.node.push_back(-x[i]), rule.kronrod.push_back(wk[i]), rule.gauss.push_back(gauss_weight);
  }
  return rule;
}

}  // namespace apollonius
