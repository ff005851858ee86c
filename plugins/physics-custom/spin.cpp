#include "spin.hpp"

#include <glm/geometric.hpp>
#include <glm/gtx/euler_angles.hpp>
#include <glm/gtx/quaternion.hpp>

#include <cmath>

namespace physics_custom {

void Spin::start(double t, const glm::dquat &q, const glm::dvec3 &rate) {
    t0 = t;
    q0 = q;
    w = rate;
    alpha = glm::dvec3(0.0);
    free.reset();
    hinge.reset();
    if (moments.x > 0.0)
        free = std::make_shared<const ani::FreeRotation>(moments, q0 * principal, w, t0);
}

void Spin::hinge_on(double t, const glm::dquat &q, const glm::dvec3 &unit_axis,
                    std::shared_ptr<const ani::Pendulum> p) {
    start(t, q, glm::dvec3(0.0));
    free.reset();
    axis = unit_axis;
    hinge = std::move(p);
    hinge_angle0 = hinge->angle(t);
    w = rate(t);
}

glm::dvec3 Spin::rate(double t) const {
    if (hinge) {
        double angle, rate;
        hinge->evaluate(t, angle, rate);
        return rate * axis;
    }
    if (!torque_free()) return w + (t - t0) * alpha;
    glm::dquat q;
    glm::dvec3 rate;
    free->evaluate(t, q, rate);
    return rate;
}

double Spin::rate_bound() const {
    if (hinge) return (1.0 + 1e-12) * hinge->max_rate();
    const double speed = glm::length(w);
    if (!torque_free()) return speed;
    const glm::dvec3 body = glm::conjugate(q0 * principal) * w;
    const double twice_energy = glm::dot(body, moments * body);
    return (1.0 + 1e-12) * std::max(speed, std::sqrt(twice_energy / moments.x));
}

double Spin::rate_change_bound() const {
    if (hinge) return (1.0 + 1e-12) * hinge->omega2(); // |psi''| = w^2 |sin psi|, about a fixed axis
    if (!torque_free()) return 0.0;
    const glm::dvec3 body = glm::conjugate(q0 * principal) * w;
    return (1.0 + 1e-12) * glm::length(moments * body) * rate_bound() / moments.x;
}

glm::dmat3 Spin::inverse_inertia(double t) const {
    const glm::dmat3 r = glm::mat3_cast(at(t) * principal);
    const glm::dmat3 inverse(glm::dvec3(1.0 / moments.x, 0.0, 0.0),
                             glm::dvec3(0.0, 1.0 / moments.y, 0.0),
                             glm::dvec3(0.0, 0.0, 1.0 / moments.z));
    return r * inverse * glm::transpose(r);
}

glm::dquat Spin::at(double t) const {
    if (hinge) return glm::normalize(glm::angleAxis(hinge->angle(t) - hinge_angle0, axis) * q0);
    if (torque_free()) {
        glm::dquat q;
        glm::dvec3 rate;
        free->evaluate(t, q, rate);
        return glm::normalize(q * glm::conjugate(principal));
    }
    if (alpha != glm::dvec3(0.0)) return ani::spun_up(q0, w, alpha, t - t0);
    const double speed = glm::length(w);
    if (!(speed > 0.0)) return q0;
    return glm::normalize(glm::angleAxis(speed * (t - t0), w / speed) * q0);
}

glm::dquat orientation_of_angles(const glm::dvec3 &degrees) {
    const glm::dvec3 a = glm::radians(degrees);
    return glm::normalize(glm::quat_cast(glm::dmat3(glm::eulerAngleXYZ(a.x, a.y, a.z))));
}

glm::dvec3 angular_velocity_between(const glm::dquat &q_before, const glm::dquat &q_after,
                                    double dt) {
    glm::dquat d = glm::normalize(q_after * glm::inverse(q_before));
    if (d.w < 0.0) d = -d; // the shorter way round
    const glm::dvec3 axis(d.x, d.y, d.z);
    const double s = glm::length(axis);
    if (!(s > 0.0) || !(dt > 0.0)) return glm::dvec3(0.0);
    const double angle = 2.0 * std::atan2(s, d.w);
    return axis / s * (angle / dt);
}

} // namespace physics_custom
