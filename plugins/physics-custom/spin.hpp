// The turning of a free model that `rotates` (issue 18). A sphere or a cube is a spherical top
// (one moment about every axis), so without torque its angular velocity is constant and its
// orientation is exactly q(t) = turn(w (t - t0)) q0: one rotation segment per stretch between the
// contacts that change w. Any other body (a box, a cylinder) turns without torque as Euler and
// Poinsot say, exactly (animator/free_rotation.hpp): its angular velocity changes as it turns.
#pragma once

#include <animator/free_rotation.hpp>
#include <animator/pendulum.hpp>

#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <memory>

namespace physics_custom {

struct Spin {
    bool on = false; // contacts turn it; reported as rotation segments
    double t0 = 0.0; // start of the current stretch
    glm::dquat q0{1.0, 0.0, 0.0, 0.0};
    glm::dvec3 w{0.0}; // rad/s, world axes, at t0 (throughout for a spherical top)
    // A ball that friction turns on its support: w changes at this rate (rad/s^2, world axes),
    // reported as spin-up segments (ABI 1.5). start() sets it to 0.
    glm::dvec3 alpha{0.0};
    // A body whose principal moments differ: its moments (ascending; 0 for a spherical top) and
    // principal axes in its own frame, and its torque-free turn from (q0, w) at t0 (start()).
    glm::dvec3 moments{0.0};
    glm::dquat principal{1.0, 0.0, 0.0, 0.0};
    std::shared_ptr<const ani::FreeRotation> free;
    // Tipping over an edge (bake_hinge.cpp): it turns about the fixed world axis `axis` as the
    // pendulum says, q(t) = turn(axis, angle(t) - angle(t0)) q0 (reported as hinge segments,
    // ABI 1.6). start() clears it; hinge_on() sets it.
    std::shared_ptr<const ani::Pendulum> hinge;
    glm::dvec3 axis{0.0};
    double hinge_angle0 = 0.0; // the pendulum's angle at t0

    // Turns from orientation q at angular velocity w at time t.
    void start(double t, const glm::dquat &q, const glm::dvec3 &w);
    // Turns from orientation q at time t about the unit axis as the pendulum p says.
    void hinge_on(double t, const glm::dquat &q, const glm::dvec3 &unit_axis,
                  std::shared_ptr<const ani::Pendulum> p);
    glm::dquat at(double t) const;
    glm::dvec3 rate(double t) const; // the angular velocity at t
    // Whether its angular velocity changes as it turns (reported as free-rotation segments).
    bool torque_free() const { return free && free->kind() != ani::FreeRotation::Kind::constant; }
    // Bounds over all time of |w(t)| and |w'(t)| (Euler: I w' = (I w) x w, with |w| at most
    // sqrt(2 T / I1) and |I w| = |L| kept).
    double rate_bound() const;
    double rate_change_bound() const;
    // The world inverse inertia at t of a body whose moments are set: R P diag(1/I) P^T R^T.
    glm::dmat3 inverse_inertia(double t) const;
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
