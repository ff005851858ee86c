// Contacts with models that move under their keyframes. A keyed model's pose is known only by
// evaluating the host's interpolation at a time, not as a polynomial, so its time of impact is
// found by conservative advancement (Mirtich; Zhang et al., "Continuous collision detection for
// articulated models using Taylor models and temporal culling", 2007): from a moment when the
// gap between the two is g and it cannot close faster than c, no contact can happen for g / c,
// so time advances by that much and the gap is measured again, until it is within a tolerance.
// A step that finds the gap closed (the bound was exceeded) is bisected back to the crossing.
#pragma once

#include <functional>

namespace physics_custom {

struct Approach {
    // The gap between the two at time t: > 0 apart, <= 0 touching or overlapping.
    std::function<double(double t)> gap;
    // An upper bound of how fast the gap can close over [t, t + dt] (>= 0).
    std::function<double(double t, double dt)> closing_speed;
};

struct ApproachOutcome {
    enum Kind {
        kNone,        // no contact within [t0, t1]
        kContact,     // contact at t (gap within tolerance, and closing)
        kOverlapping, // the gap is already <= 0 at t0 (and not within tolerance of a touch)
        kUndecided    // still within 100 tolerances of each other after many steps: ask again at t
    } kind = kNone;
    double t = 0.0;
};

// The first contact in [t0, t1]: the first time the gap reaches `tolerance` while closing.
ApproachOutcome advance_to_contact(const Approach &approach, double t0, double t1,
                                   double tolerance);

} // namespace physics_custom
