// How far a claimed x y z r may lie from the exact vertex: the only tolerance of `certify`. It decides
// nothing about which points are vertices; it only tells "confirmed" from "coordinates off".
#pragma once

#include <array>
#include <vector>

#include "predicates/site.h"

namespace apollonius {

// The scale of an input: the largest |x|, |y|, |z|, |w| over all its sites (hidden ones included).
double input_scale(const std::vector<Site>& sites);

// A claimed value c of an exact value e (correctly rounded to the double E) is accepted when
//   |c - E| <= relative * max(scale, |E|):
// relative to the input's scale, and to the value itself for vertices far outside the input.
struct Coordinate_tolerance {
  double relative = 1e-9;
  double scale = 0;
};

// Over x, y, z, r: absolute = max |c - E|, relative = max |c - E| / max(scale, |E|). Equal values (also
// equal infinities) differ by 0; otherwise an infinite difference gives infinite errors. The absolute
// error is also the distance by which a claim is matched to the nearest of its candidate points.
struct Coordinate_error {
  double absolute = 0;
  double relative = 0;
};

Coordinate_error coordinate_error(const std::array<double, 4>& claimed, const std::array<double, 4>& rounded_exact,
                                  double scale);

inline bool within(const Coordinate_error& error, const Coordinate_tolerance& tolerance) {
  return error.relative <= tolerance.relative;
}

}  // namespace apollonius
