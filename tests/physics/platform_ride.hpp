// The closed form of assets/animations/platform_ride.ani (docs/physics.md, "Riding a keyed
// platform"), shared by tests/physics/carrier_test.cpp and bench/rest.cpp. The platform's linear
// keys move it from x = -3 to 3 over [0, 2] s, hold it over [2, 4] and bring it back over [4, 6]:
// its velocity u is 3, 0, -3 m/s on those spans, and 0 after its last key. Between keys its frame
// is inertial, so the box (mu = 0.5 against it) slides on it as on a floor: friction a = mu g
// takes its velocity relative to the platform to 0 in t* = 3 / a, over d = 3 t* / 2, and it moves
// with the platform from then. Placed at rest at x = -3: x = -3 + a t^2 / 2 until t*, then
// -3 + d + 3 (t - t*) until 2 s; at 2 s the platform stops and the box slides on,
// x = x2 + 3 s - a s^2 / 2 (s = t - 2), to 3 at 2 + t*; at 4 s the platform leaves it behind
// again, the mirror image, and at 6 s stops under it.
#pragma once

namespace animator::platform_ride {

inline double box_x(double t, double g) {
    const double a = 0.5 * g, ts = 3.0 / a, d = 1.5 * ts;
    const double x2 = -3.0 + d + 3.0 * (2.0 - ts), x6 = 3.0 - d - 3.0 * (2.0 - ts);
    if (t <= ts) return -3.0 + 0.5 * a * t * t;
    if (t <= 2.0) return -3.0 + d + 3.0 * (t - ts);
    if (t <= 2.0 + ts) return x2 + 3.0 * (t - 2.0) - 0.5 * a * (t - 2.0) * (t - 2.0);
    if (t <= 4.0) return 3.0;
    if (t <= 4.0 + ts) return 3.0 - 0.5 * a * (t - 4.0) * (t - 4.0);
    if (t <= 6.0) return 3.0 - d - 3.0 * (t - 4.0 - ts);
    if (t <= 6.0 + ts) return x6 - 3.0 * (t - 6.0) + 0.5 * a * (t - 6.0) * (t - 6.0);
    return -3.0;
}

inline double box_vx(double t, double g) {
    const double a = 0.5 * g, ts = 3.0 / a;
    if (t <= ts) return a * t;
    if (t <= 2.0) return 3.0;
    if (t <= 2.0 + ts) return 3.0 - a * (t - 2.0);
    if (t <= 4.0) return 0.0;
    if (t <= 4.0 + ts) return -a * (t - 4.0);
    if (t <= 6.0) return -3.0;
    if (t <= 6.0 + ts) return -3.0 + a * (t - 6.0);
    return 0.0;
}

} // namespace animator::platform_ride
