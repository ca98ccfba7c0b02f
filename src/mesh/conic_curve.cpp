#include "mesh/conic_curve.h"

#include <cmath>
#include <optional>
#include <stdexcept>

#include "predicates/rounding_guard.h"

namespace apollonius {
namespace {

template <class NT>
Vector4<double> to_doubles(const Vector4<NT>& x) {
  return {CGAL::to_double(x[0]), CGAL::to_double(x[1]), CGAL::to_double(x[2]), CGAL::to_double(x[3])};
}

double lorentz(const Vector4<double>& x, const Vector4<double>& y) { return lorentz_product(x, y); }

Vector4<double> difference(const Vector4<double>& x, const Vector4<double>& y) {
  return {x[0] - y[0], x[1] - y[1], x[2] - y[2], x[3] - y[3]};
}

}  // namespace

Conic_curve::Conic_curve(const Trisector& trisector) : origin_(trisector.origin()) {
  auto take = [&](const auto& g) {
    kind_ = g.kind;
    e1_ = to_doubles(g.e1);
    e2_ = to_doubles(g.e2);
    centre_ = to_doubles(g.centre);
    point_ = to_doubles(g.point);
    gamma1_ = CGAL::to_double(g.gamma1);
    gamma2_ = CGAL::to_double(g.gamma2);
    K_ = CGAL::to_double(g.K);
    branch_axis_ = g.branch_axis;
    branch_sign_ = g.branch_sign == Sign::NEGATIVE ? -1 : 1;
    return to_doubles(g.monotone);
  };
  std::optional<Trisector_geometry<Interval>> interval;
  {
    Rounding_guard guard;
    try {
      interval = trisector.geometry<Interval>();
    } catch (const Uncertain_sign&) {
    }
  }
  const Vector4<double> monotone = interval ? take(*interval) : take(trisector.geometry<Rational>());
  switch (kind_) {
    case Trisector_kind::ellipse:
      scale1_ = std::sqrt(K_ / gamma1_);
      scale2_ = std::sqrt(K_ / gamma2_);
      break;
    case Trisector_kind::hyperbola:
      scale1_ = std::sqrt(std::abs(K_ / gamma1_));
      scale2_ = std::sqrt(std::abs(K_ / gamma2_));
      break;
    case Trisector_kind::parabola:
      break;
    default:
      throw std::logic_error("mesh: an edge on a trisector that is no curve");
  }
  if (kind_ != Trisector_kind::ellipse) {
    // Forward is increasing <X, monotone>, which is monotone along the branch.
    direction_ = lorentz(raw(1), monotone) > lorentz(raw(-1), monotone) ? 1 : -1;
  }
}

Vector4<double> Conic_curve::raw(double u) const {
  double s = 0, t = 0;
  Vector4<double> base = centre_;
  switch (kind_) {
    case Trisector_kind::ellipse:
      s = scale1_ * std::cos(u);
      t = scale2_ * std::sin(u);
      break;
    case Trisector_kind::hyperbola:
      if (branch_axis_ == 1) {
        s = branch_sign_ * scale1_ * std::cosh(u);
        t = scale2_ * std::sinh(u);
      } else {
        t = branch_sign_ * scale2_ * std::cosh(u);
        s = scale1_ * std::sinh(u);
      }
      break;
    default: {  // parabola: <e1, e1> = <e1, e2> = 0, so <X, X> = 0 is linear in s
      base = point_;
      t = u;
      s = -(lorentz(point_, point_) + 2 * t * lorentz(point_, e2_) + gamma2_ * t * t) / (2 * lorentz(point_, e1_));
    }
  }
  return {base[0] + s * e1_[0] + t * e2_[0], base[1] + s * e1_[1] + t * e2_[1], base[2] + s * e1_[2] + t * e2_[2],
          base[3] + s * e1_[3] + t * e2_[3]};
}

Vector4<double> Conic_curve::coordinates(double t) const { return raw(direction_ * t); }

Point3 Conic_curve::position(double t) const {
  const Vector4<double> X = coordinates(t);
  return {origin_.x + X[0] / 2, origin_.y + X[1] / 2, origin_.z + X[2] / 2};
}

double Conic_curve::raw_parameter(const Vector4<double>& X) const {
  if (kind_ == Trisector_kind::parabola) return lorentz(difference(X, point_), e2_) / gamma2_;
  const Vector4<double> d = difference(X, centre_);
  const double s = lorentz(d, e1_) / gamma1_, t = lorentz(d, e2_) / gamma2_;
  if (kind_ == Trisector_kind::ellipse) return std::atan2(t / scale2_, s / scale1_);
  return branch_axis_ == 1 ? std::asinh(t / scale2_) : std::asinh(s / scale1_);
}

double Conic_curve::parameter(const std::array<double, 4>& p) const {
  const Vector4<double> X{2 * (p[0] - origin_.x), 2 * (p[1] - origin_.y), 2 * (p[2] - origin_.z), 2 * (p[3] + origin_.w)};
  return direction_ * raw_parameter(X);
}

}  // namespace apollonius
