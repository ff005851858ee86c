// interpolation.linear: straight-line interpolation between keyframes (seed, "Linear
// Interpolation between Keyframes"), the directed angle rule for angles, and slerp for the
// camera's rotation.
#pragma once

#include "segments.hpp"

#include <cstdint>

namespace interp {

// prev + s (next - prev): the seed's center = prev.center + t (next.center - prev.center).
double lerp(double prev, double next, double s);

// The angle a fraction s of the way from prev to next (degrees in [0, 360)) travelling in the
// direction `turn` (see turn_delta), wrapped into [0, 360).
double lerp_angle(double prev, double next, double turn, double s);

// A validated channel of any kind on its linear curve at `count` sorted times (evaluate_curve;
// the curve made on the stack: the host asks for every model's start, one call a channel).
void evaluate_linear(const ani_channel &channel, const double *times, uint32_t count, double *values,
                     double *rates);

} // namespace interp
