// A cube dropped corner first on a floor (y = 0) with Rotates on, e = 1, mu = 0 (issue 18),
// worked out here independently of the backends: the first impact in closed form, the impulse
// at the lowest corner by hand, and the second impact by scanning the lowest corner's height over
// the closed-form flight in steps of 1e-4 s and bisecting. tests/physics/turning_test.cpp checks
// physics.custom against it; tests/physics-bullet/scenes.cpp measures either backend with it.
#pragma once

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtx/euler_angles.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace cube_drop {

struct Drop {
    double t1 = 0.0, t2 = 0.0;   // the first and second impact times
    double h0 = 0.0;             // the lowest corner's height at t = 0
    glm::dvec3 corner{0.0};      // the corner that lands first, from the centre, at t1
    glm::dvec3 v1{0.0}, w1{0.0}; // velocity and angular velocity after the first impact
    double inertia = 0.0;        // m s^2 / 6
};

// The corners of a cube of half side `half` centred at the origin.
inline std::array<glm::dvec3, 8> corners(double half) {
    std::array<glm::dvec3, 8> out;
    for (int k = 0; k < 8; ++k)
        out[static_cast<size_t>(k)] =
            half * glm::dvec3(k & 1 ? 1.0 : -1.0, k & 2 ? 1.0 : -1.0, k & 4 ? 1.0 : -1.0);
    return out;
}

// The keys' turn of Euler angles X-Y-Z in degrees.
inline glm::dmat3 turn_of(const glm::dvec3 &degrees) {
    return glm::dmat3(glm::eulerAngleXYZ(glm::radians(degrees.x), glm::radians(degrees.y),
                                         glm::radians(degrees.z)));
}

// Dropped from rest at `center`, turned by `degrees`, under gravity g along -y.
inline Drop drop(const glm::dvec3 &center, const glm::dvec3 &degrees, double half, double mass,
                 double g) {
    Drop d;
    const glm::dmat3 r0 = turn_of(degrees);
    const double side = 2.0 * half;
    d.inertia = mass * side * side / 6.0;
    d.h0 = 1e300;
    for (const glm::dvec3 &p : corners(half)) {
        const glm::dvec3 q = r0 * p;
        if (center.y + q.y < d.h0) {
            d.h0 = center.y + q.y;
            d.corner = q;
        }
    }
    d.t1 = std::sqrt(2.0 * d.h0 / g);
    // The impulse j n at the corner, n = +y: its normal speed -g t1 becomes g t1 (e = 1), so
    // j = 2 g t1 / (1/m + |r x n|^2 / I); v' = v + j n / m, w' = (r x n) j / I.
    const glm::dvec3 n(0.0, 1.0, 0.0), rxn = glm::cross(d.corner, n);
    const double j = 2.0 * g * d.t1 / (1.0 / mass + glm::dot(rxn, rxn) / d.inertia);
    d.v1 = glm::dvec3(0.0, -g * d.t1, 0.0) + (j / mass) * n;
    d.w1 = rxn * (j / d.inertia);
    const glm::dvec3 c1 = center - glm::dvec3(0.0, d.h0, 0.0);
    auto height = [&](double tau) {
        const glm::dvec3 c = c1 + d.v1 * tau - glm::dvec3(0.0, 0.5 * g * tau * tau, 0.0);
        const glm::dmat3 turned = glm::dmat3(glm::mat3_cast(glm::angleAxis(glm::length(d.w1) * tau,
                                                                           glm::normalize(d.w1)))) *
                                  r0;
        double lowest = 1e300;
        for (const glm::dvec3 &p : corners(half)) lowest = std::min(lowest, c.y + (turned * p).y);
        return lowest;
    };
    double lo = 1e-4, hi = lo;
    while (height(hi) > 0.0) {
        lo = hi;
        hi += 1e-4;
        if (hi > 100.0) throw std::runtime_error("cube_drop: no second impact within 100 s");
    }
    for (int k = 0; k < 200 && hi - lo > 1e-15; ++k) {
        const double mid = 0.5 * (lo + hi);
        (height(mid) > 0.0 ? lo : hi) = mid;
    }
    d.t2 = d.t1 + 0.5 * (lo + hi);
    return d;
}

} // namespace cube_drop
