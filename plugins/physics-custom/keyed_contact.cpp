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
        // The step: the largest dt found over which the gap cannot close by more than half,
        // dt <= g / (2 s(dt)), s(dt) the bound of the closing speed over [t, t + dt] (it grows
        // with dt). From the speed now, or, at rest now, the whole window; where that is too
        // long, 0.5 g / s(that) is short enough, and a search between the two finds a longer
        // one (near an apex, where the speed now is nearly 0, the short one was a standstill).
        const double speed = approach.closing_speed(t, 0.0);
        double hi = speed > 0.0 ? 0.5 * g / speed : t1 - t;
        const double bound = approach.closing_speed(t, hi);
        if (!(bound > 0.0)) return {}; // nothing can close the gap
        double dt = hi;
        if (hi > 0.5 * g / bound) {
            double lo = 0.5 * g / bound;
            for (int k = 0; k < 30 && hi > 2.0 * lo; ++k) {
                const double mid = std::sqrt(lo * hi);
                if (mid <= 0.5 * g / approach.closing_speed(t, mid))
                    lo = mid;
                else
                    hi = mid;
            }
            dt = lo;
        }
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
