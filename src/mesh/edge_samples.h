// Where an edge is sampled: parameters along its curve (conic_curve.h) about one local step apart in R^3
// (paper section 6.3: a step of 2% of the box diagonal). The local step may grow away from the box, where
// the samples only bound the part of a face that is cut off.
#pragma once

#include <functional>
#include <vector>

#include "mesh/conic_curve.h"

namespace apollonius {

using Local_step = std::function<double(const Point3&)>;

// Parameters t0 = q_0 < ... < q_N = t1 whose chords are each about one local step (N >= least_segments).
std::vector<double> sample_parameters(const Conic_curve& curve, double t0, double t1, const Local_step& step,
                                      std::size_t least_segments = 1);

// From t0, walking forward (direction +1) or backward (-1), the first parameter where `far` holds, at most
// `max_steps` local steps on; throws std::runtime_error if it is not reached.
double walk_until(const Conic_curve& curve, double t0, int direction, const Local_step& step,
                  const std::function<bool(const Point3&)>& far, int max_steps = 1000000);

double distance(const Point3& a, const Point3& b);

}  // namespace apollonius
