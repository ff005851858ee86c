// The cubic Hermite segment: the curve through two values with given derivatives at both ends.
#pragma once

namespace interp {

struct ValueRate {
    double value;
    double rate; // derivative per second
};

// The cubic from p0 (at tau = 0) to p1 (at tau = dt) with derivatives m0 and m1 (per second),
// at tau seconds into the segment. Written as p0 + h01 (p1 - p0) + dt (h10 m0 + h11 m1), which is
// the textbook h00 p0 + h10 dt m0 + h01 p1 + h11 dt m1 since h00 = 1 - h01, but reproduces a
// constant exactly and loses less to rounding.
inline ValueRate hermite(double p0, double p1, double m0, double m1, double dt, double tau) {
    const double s = tau / dt;
    const double s2 = s * s, s3 = s2 * s;
    const double h01 = -2 * s3 + 3 * s2, h10 = s3 - 2 * s2 + s, h11 = s3 - s2;
    const double d01 = -6 * s2 + 6 * s, d10 = 3 * s2 - 4 * s + 1, d11 = 3 * s2 - 2 * s;
    return {p0 + h01 * (p1 - p0) + dt * (h10 * m0 + h11 * m1),
            d01 * (p1 - p0) / dt + d10 * m0 + d11 * m1};
}

// The Hermite blend from 0 to 1 over s in [0, 1] with the derivative `m` (per unit s) at both
// ends: m = 1 is s itself, m = 0 is smoothstep 3 s^2 - 2 s^3. The rate is per unit s.
inline ValueRate hermite_blend(double s, double m) {
    if (m == 1.0) return {s, 1.0}; // exactly, not to rounding
    return hermite(0.0, 1.0, m, m, 1.0, s);
}

} // namespace interp
