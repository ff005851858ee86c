#include "spin.hpp"

#include <glm/geometric.hpp>
#include <glm/gtx/euler_angles.hpp>
#include <glm/gtx/quaternion.hpp>

#include <cmath>

namespace physics_custom {

glm::dquat Spin::at(double t) const {
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
