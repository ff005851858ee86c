// Euler angles in degrees, stored in [0, 360), and the direction rule that decides which way an
// angle travels between two keys (seed, "Linear Interpolation between Keyframes").
#pragma once

#include <vector>

namespace interp {

// x mapped into [0, 360). Never returns 360.0 (a value that rounds up to 360 becomes 0) and
// never -0.0.
double wrap_degrees(double x);

// How far, in degrees, an angle travels from `prev` to `next` (both in [0, 360)) when the user
// turned towards `next` in direction `turn`: < 0 counter-clockwise (the angle increases), > 0
// clockwise (it decreases), 0 the shorter way.
double turn_delta(double prev, double next, double turn);

// Angles (one axis, in [0, 360)) made continuous so a smooth curve can run through them: the
// first is kept and each next one is its predecessor plus turn_delta(prev, next, turns[k]), with
// the turn recorded on the key it goes to (turns[0] is unused). May leave [0, 360).
std::vector<double> unwrap_angles(const std::vector<double> &angles, const std::vector<double> &turns);

} // namespace interp
