// The closed form of assets/animations/platform_lift.ani (docs/physics.md, "Sticking to a
// platform that accelerates"), shared by tests/physics/sticking_test.cpp and bench/rest.cpp. The
// platform's smooth keys ease in and out of every key (every tangent 0): a span of length T from p0
// to p1 is p0 + (p1 - p0) (3 s^2 - 2 s^3), s = (t - t0) / T, whose acceleration is at most
// 6 |p1 - p0| / T^2 (at its ends). It moves from x = -3 to 0 over [0, 2] s, waits over [2, 3], and
// rises from y = 1 to 3 over [3, 5]. The box sticks to it throughout, 0.35 m above its centre.
#pragma once

#include <algorithm>

namespace animator::platform_lift {

inline double ease(double s) {
    s = std::clamp(s, 0.0, 1.0);
    return s * s * (3.0 - 2.0 * s);
}

inline double ease_rate(double s) {
    return s <= 0.0 || s >= 1.0 ? 0.0 : 6.0 * s * (1.0 - s);
}

// The box's centre and velocity at t (x and y; z stays 0).
inline double box_x(double t) {
    return -3.0 + 3.0 * ease(t / 2.0);
}
inline double box_y(double t) {
    return 1.35 + 2.0 * ease((t - 3.0) / 2.0);
}
inline double box_vx(double t) {
    return 3.0 * ease_rate(t / 2.0) / 2.0;
}
inline double box_vy(double t) {
    return 2.0 * ease_rate((t - 3.0) / 2.0) / 2.0;
}

} // namespace animator::platform_lift
