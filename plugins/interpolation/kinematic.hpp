// interpolation.kinematic: a model's center moving with constant acceleration between keys
// (seed, "Keyframe Interpolation with Kinematic Equations").
#pragma once

#include "hermite.hpp"
#include "segments.hpp"

#include <vector>

namespace interp {

// One component's motion over one segment: it leaves the segment's first key with velocity v0
// and accelerates steadily at a.
struct KinematicSegment {
    double v0;
    double a;
};

// The segments through `positions` at `times` (one component, at least one key) starting with
// `initial_velocity` (the model's initial velocity): for segment i, with dt = t[i+1] - t[i] and
// d = p[i+1] - p[i], a[i] = 2 (d - v0[i] dt) / dt^2 and v0[i+1] = v0[i] + a[i] dt, so each key
// is reached on time and the velocity is continuous across keys. n keys give n - 1 segments.
std::vector<KinematicSegment> kinematic_segments(const std::vector<double> &times,
                                                 const std::vector<double> &positions,
                                                 double initial_velocity);

// Position p0 + v0 tau + a tau^2 / 2 and velocity v0 + a tau, tau seconds into a segment that
// starts at p0.
ValueRate kinematic_at(double p0, const KinematicSegment &segment, double tau);

// A validated POSITION channel on its kinematic curve at `count` sorted times (evaluate_curve;
// the curve made on the stack).
void evaluate_kinematic(const ani_channel &channel, const double *times, uint32_t count, double *values,
                        double *rates);

} // namespace interp
