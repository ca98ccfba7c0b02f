// A trisector as a parametrised curve in doubles, for sampling the edges on it (paper section 5.4: the
// boundary of a face is sampled along its edges). The parameter increases forward along the curve
// (trisector.h): the angle on an ellipse, the hyperbolic angle on a hyperbola branch, the coordinate along
// e2 on a parabola, negated where that runs backward. APPROXIMATE: the geometry is the exact one rounded to
// doubles; the decisions (which arcs are edges) were made exactly by the topology.
#pragma once

#include <array>

#include "mesh/bisector_frame.h"
#include "predicates/trisector.h"

namespace apollonius {

class Conic_curve {
 public:
  explicit Conic_curve(const Trisector& trisector);

  bool closed() const { return kind_ == Trisector_kind::ellipse; }

  // X(t) = 2 (v - p_a, r + w_a) (trisector.h), and the centre v.
  Vector4<double> coordinates(double t) const;
  Point3 position(double t) const;
  // The parameter of a point of the curve given by its centre and r (a vertex's rounded values).
  double parameter(const std::array<double, 4>& point) const;

 private:
  Trisector_kind kind_;
  Site origin_;
  Vector4<double> e1_, e2_, centre_, point_;
  double gamma1_ = 0, gamma2_ = 0, K_ = 0;
  double scale1_ = 0, scale2_ = 0;  // the semi-axes in (s, t)
  int branch_axis_ = 0;
  double branch_sign_ = 1;
  double direction_ = 1;  // +1 when the raw parameter runs forward
  Vector4<double> raw(double u) const;
  double raw_parameter(const Vector4<double>& X) const;
};

}  // namespace apollonius
