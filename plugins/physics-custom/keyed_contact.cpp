#include "keyed_contact.hpp"

#include <algorithm>
#include <cmath>

namespace physics_custom {

namespace {

constexpr int kMaxSteps = 100000;

// A root of the gap between a (gap > tolerance) and b (gap < tolerance), to the last bit.
double bisect(const Approach &approach, double a, double b, double tolerance) {
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (a + b);
        if (mid <= a || mid >= b) break;
        if (approach.gap(mid) > tolerance)
            a = mid;
        else
            b = mid;
    }
    return b;
}

} // namespace

ApproachOutcome advance_to_contact(const Approach &approach, double t0, double t1,
                                   double tolerance) {
    double t = t0;
    double g = approach.gap(t);
    if (g <= 0.0 && g < -tolerance) return {ApproachOutcome::kOverlapping, t0};
    double probe_step = std::max(1e-9, 1e-12 * std::abs(t0));
    for (int step = 0; step < kMaxSteps; ++step) {
        if (g <= tolerance) {
            // Touching: a contact only if they are closing (a body leaving a surface it just
            // bounced off is not in contact with it).
            const double probe = std::min(t1, t + probe_step);
            if (probe > t && approach.gap(probe) < g) return {ApproachOutcome::kContact, t};
            // Moving apart or along: step past the touch, in steps that double while they
            // stay touching (two models resting against each other).
            if (probe >= t1) return {};
            t = probe;
            probe_step *= 2.0;
            g = approach.gap(t);
            if (g < -tolerance) return {ApproachOutcome::kOverlapping, t};
            continue;
        }
        double speed = approach.closing_speed(t, 0.0);
        if (!(speed > 0.0)) {
            // Still at t, it may be about to move (a body dropped from rest): the bound over the
            // rest of the window. (Taking no speed for no motion let a ball dropped from rest
            // onto a resting box through it.)
            speed = approach.closing_speed(t, t1 - t);
            if (!(speed > 0.0)) return {}; // nothing can close the gap
        }
        double dt = 0.5 * g / speed;
        speed = std::max(speed, approach.closing_speed(t, dt)); // the bound over the step itself
        dt = 0.5 * g / speed;
        if (t + dt > t1) {
            // The last step: the end of the window, unless the gap closes before it.
            const double g1 = approach.gap(t1);
            if (g1 > tolerance) return {};
            return {ApproachOutcome::kContact, bisect(approach, t, t1, tolerance)};
        }
        const double next = t + dt;
        if (next <= t) return {ApproachOutcome::kUndecided, t};
        const double gn = approach.gap(next);
        if (gn <= tolerance) {
            // Closed faster than the bound said (the bound is an estimate for keyed motion): the
            // crossing is between t and next.
            return {ApproachOutcome::kContact,
                    gn < 0.0 ? bisect(approach, t, next, tolerance) : next};
        }
        t = next;
        g = gn;
    }
    return {ApproachOutcome::kUndecided, t};
}

} // namespace physics_custom
