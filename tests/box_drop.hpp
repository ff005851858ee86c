// A box (half extents h, uniform, mass m) dropped from rest with an angular velocity on a floor
// (y = 0) with Rotates on (issue 18), worked out here independently of the backends and of the
// SDK's closed form (animator/free_rotation.hpp, Jacobi elliptic functions): Euler's equations
// I w' = (I w) x w in the body frame and q' = q (0, w) / 2, integrated by classical Runge-Kutta
// in steps of 1e-4 s (its error, ~(w dt)^4 per unit time, is far below 1e-12 here), the first
// impact found by scanning the lowest corner's height and bisecting inside the step with one
// Runge-Kutta step from the step's start. tests/physics/turning_test.cpp checks physics.custom
// against it; tests/physics-bullet/body_settings_test.cpp measures Bullet with it.
#pragma once

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace box_drop {

struct Rotation {
    glm::dquat q{1.0, 0.0, 0.0, 0.0}; // body -> world
    glm::dvec3 w{0.0};                // body frame
};

class Box {
  public:
    Box(const glm::dvec3 &half, double mass) : half_(half) {
        const glm::dvec3 s = half * half;
        moments_ = mass / 3.0 * glm::dvec3(s.y + s.z, s.x + s.z, s.x + s.y);
    }
    const glm::dvec3 &moments() const { return moments_; }

    // One Runge-Kutta step of dt.
    Rotation step(const Rotation &r, double dt) const {
        const auto rate = [&](const Rotation &x) {
            Rotation d;
            d.w = glm::cross(moments_ * x.w, x.w) / moments_;
            d.q = x.q * glm::dquat(0.0, x.w.x, x.w.y, x.w.z) * 0.5;
            return d;
        };
        const auto plus = [](const Rotation &x, const Rotation &d, double h) {
            Rotation y;
            y.q = glm::dquat(x.q.w + h * d.q.w, x.q.x + h * d.q.x, x.q.y + h * d.q.y,
                             x.q.z + h * d.q.z);
            y.w = x.w + h * d.w;
            return y;
        };
        const Rotation k1 = rate(r), k2 = rate(plus(r, k1, 0.5 * dt)),
                       k3 = rate(plus(r, k2, 0.5 * dt)), k4 = rate(plus(r, k3, dt));
        Rotation out;
        const auto mix = [&](double a, double b, double c, double d) {
            return (a + 2.0 * b + 2.0 * c + d) * (dt / 6.0);
        };
        out.q = glm::normalize(glm::dquat(r.q.w + mix(k1.q.w, k2.q.w, k3.q.w, k4.q.w),
                                          r.q.x + mix(k1.q.x, k2.q.x, k3.q.x, k4.q.x),
                                          r.q.y + mix(k1.q.y, k2.q.y, k3.q.y, k4.q.y),
                                          r.q.z + mix(k1.q.z, k2.q.z, k3.q.z, k4.q.z)));
        out.w = r.w + glm::dvec3(mix(k1.w.x, k2.w.x, k3.w.x, k4.w.x),
                                 mix(k1.w.y, k2.w.y, k3.w.y, k4.w.y),
                                 mix(k1.w.z, k2.w.z, k3.w.z, k4.w.z));
        return out;
    }

    // The orientation and body angular velocity at t from q0 and the world angular velocity w0
    // at 0, in steps of at most dt.
    Rotation at(const glm::dquat &q0, const glm::dvec3 &w0, double t, double dt = 1e-4) const {
        Rotation r{q0, glm::conjugate(q0) * w0};
        const int n = static_cast<int>(std::ceil(t / dt));
        for (int k = 0; k < n; ++k) r = step(r, t / n);
        return r;
    }

    // The lowest corner's height over the floor of a box centred at y with orientation q.
    double lowest(double y, const glm::dquat &q) const {
        double low = 1e300;
        for (int k = 0; k < 8; ++k) {
            const glm::dvec3 p = half_ * glm::dvec3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1);
            low = std::min(low, y + (q * p).y);
        }
        return low;
    }

    // Dropped from rest at height y0 under g with orientation q0 and world angular velocity w0:
    // the time its lowest corner first reaches the floor.
    double first_impact(double y0, double g, const glm::dquat &q0, const glm::dvec3 &w0,
                        double dt = 1e-4) const {
        Rotation r{q0, glm::conjugate(q0) * w0};
        double t = 0.0;
        for (;;) {
            const Rotation next = step(r, dt);
            if (lowest(y0 - 0.5 * g * (t + dt) * (t + dt), next.q) <= 0.0) break;
            r = next;
            t += dt;
            if (t > 100.0) throw std::runtime_error("box_drop: no impact within 100 s");
        }
        double lo = 0.0, hi = dt;
        for (int k = 0; k < 200 && hi - lo > 1e-16; ++k) {
            const double mid = 0.5 * (lo + hi), at = t + mid;
            (lowest(y0 - 0.5 * g * at * at, step(r, mid).q) > 0.0 ? lo : hi) = mid;
        }
        return t + 0.5 * (lo + hi);
    }

  private:
    glm::dvec3 half_, moments_;
};

} // namespace box_drop
