// The unit roundoff of round-to-nearest doubles, the one constant of every static error bound.
#pragma once

namespace apollonius {

// u: |fl(a op b) - (a op b)| <= u |a op b| for +, -, *, / and sqrt, without overflow or underflow
// (docs/ERROR_BOUNDS.md, "Notation").
inline constexpr double kUnitRoundoff = 0x1p-53;

}  // namespace apollonius
