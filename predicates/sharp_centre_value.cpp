#include "predicates/sharp_centre_value.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "predicates/centre_expansion.h"
#include "predicates/number_types.h"
#include "predicates/rounding_guard.h"
#include "predicates/unit_roundoff.h"

namespace apollonius {

Sharp_centre_value sharp_centre_value(const Site& s, const Box_frame& frame) {
  Sharp_centre_value result;
  if (!frame.usable) return result;
  const double site[3] = {s.x, s.y, s.z};
  // E from the halved offsets, which cannot overflow: max(|O_a|, |W|) 2^-E lies in [1, 2), or in (0, 2) when
  // the halving lost a subnormal bit (the scale then only needs to avoid overflow).
  double largest_half = std::fabs(s.w) / 2;
  for (int a = 0; a < 3; ++a) largest_half = std::max(largest_half, std::fabs(frame.centre[a] / 2 - site[a] / 2));
  if (!std::isfinite(largest_half)) return result;
  if (largest_half == 0) {  // c = x_s (to the last bit, halving aside) and w_s = 0: check exactly
    const bool at_centre = frame.centre[0] == s.x && frame.centre[1] == s.y && frame.centre[2] == s.z && s.w == 0;
    if (at_centre) result.known = true;
    return result;
  }
  const int exponent = std::ilogb(largest_half) + 1;
  std::array<Exact, 3> offset;
  for (int a = 0; a < 3; ++a) offset[a] = times_power_of_two(Exact(frame.centre[a]) - Exact(site[a]), -exponent);
  const Exact weight = times_power_of_two(Exact(s.w), -exponent);
  // d in box units is d' 2^(E - frame.exponent), d' the value at scale 2^-E.
  const int to_box_units = exponent - frame.exponent;

  Rounding_guard guard;
  Interval squares(0);
  for (int a = 0; a < 3; ++a) squares += CGAL::square(enclosing_interval(offset[a]));
  const Interval norm = CGAL::sqrt(squares);  // |O| 2^-E < 3.5, and |O| 2^-E + W 2^-E >= 1 when W > 0
  const Interval weight_interval = enclosing_interval(weight);
  Interval value;
  if (s.w <= 0) {
    value = times_power_of_two(norm - weight_interval, to_box_units);
  } else {
    const Exact numerator = offset[0] * offset[0] + offset[1] * offset[1] + offset[2] * offset[2] - weight * weight;
    value = enclosing_interval(times_power_of_two(numerator, to_box_units)) / (norm + weight_interval);
  }
  if (value.inf() >= kSharpValueClamp) {
    result.value = kSharpValueClamp;
  } else if (value.sup() <= -kSharpValueClamp) {
    result.value = -kSharpValueClamp;
  } else {
    if (!(std::fabs(value.inf()) < kSharpValueClamp && std::fabs(value.sup()) < kSharpValueClamp)) return result;
    // Rounded up (the guard): the midpoint's distance to either bound, plus 4u |value| that the centre
    // tests' subtraction needs (docs/ERROR_BOUNDS.md item 8), plus the smallest subnormal for underflow.
    const double middle = value.inf() / 2 + value.sup() / 2;
    const double radius = std::max(value.sup() - middle, middle - value.inf());
    result.value = middle;
    result.error = radius + 4 * kUnitRoundoff * std::fabs(middle) + 0x1p-1074;
  }
  result.known = true;
  return result;
}

}  // namespace apollonius
