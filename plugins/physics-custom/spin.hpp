// The turning of a free sphere that `rotates` (issue 18). A sphere is a spherical top (inertia
// 2/5 m r^2 about every axis), so without torque its angular velocity is constant and its
// orientation is exactly q(t) = turn(w (t - t0)) q0: one rotation segment per stretch between the
// contacts that change w.
#pragma once

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

namespace physics_custom {

struct Spin {
    bool on = false; // contacts turn it; reported as rotation segments
    double t0 = 0.0; // start of the current stretch
    glm::dquat q0{1.0, 0.0, 0.0, 0.0};
    glm::dvec3 w{0.0}; // rad/s, world axes
    glm::dquat at(double t) const;
};

// The world orientation of Euler angles X-Y-Z in degrees (the keys' convention, as
// linear_part() turns them).
glm::dquat orientation_of_angles(const glm::dvec3 &degrees);

// The world angular velocity that turns q_before into q_after in dt: the rotation
// q_after q_before^-1 as an axis times its angle, over dt (the shorter way round).
glm::dvec3 angular_velocity_between(const glm::dquat &q_before, const glm::dquat &q_after,
                                    double dt);

// A solid sphere's inverse inertia, 1 / (2/5 m r^2).
inline double sphere_inverse_inertia(double mass, double radius) {
    return 1.0 / (0.4 * mass * radius * radius);
}

} // namespace physics_custom
