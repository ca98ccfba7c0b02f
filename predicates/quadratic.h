// Elements a + b sqrt(d) of Q(sqrt(d)) whose d is known from context (the vertex they belong to), with the
// ring operations the vertex predicates need. Signs go through sign_of_root_number (root_sign.h).
#pragma once

namespace apollonius {

template <class NT>
struct Quadratic {
  NT a, b;

  friend Quadratic operator+(const Quadratic& x, const Quadratic& y) { return {x.a + y.a, x.b + y.b}; }
  friend Quadratic operator-(const Quadratic& x, const Quadratic& y) { return {x.a - y.a, x.b - y.b}; }
  friend Quadratic operator*(const Quadratic& x, const NT& s) { return {x.a * s, x.b * s}; }
  friend Quadratic operator+(const Quadratic& x, const NT& s) { return {x.a + s, x.b}; }
  friend Quadratic operator-(const NT& s, const Quadratic& x) { return {s - x.a, -x.b}; }
};

}  // namespace apollonius
