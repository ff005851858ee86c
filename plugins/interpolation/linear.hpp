// interpolation.linear: straight-line interpolation between keyframes (seed, "Linear
// Interpolation between Keyframes"), the directed angle rule for angles, and slerp for the
// camera's rotation.
#pragma once

#include "segments.hpp"

#include <memory>

namespace interp {

// prev + s (next - prev): the seed's center = prev.center + t (next.center - prev.center).
double lerp(double prev, double next, double s);

// The angle a fraction s of the way from prev to next (degrees in [0, 360)) travelling in the
// direction `turn` (see turn_delta), wrapped into [0, 360).
double lerp_angle(double prev, double next, double turn, double s);

// The linear curve of a validated channel of any kind. Keeps pointers into the channel's keys.
std::unique_ptr<Curve> make_linear_curve(const ani_channel &channel);

} // namespace interp
