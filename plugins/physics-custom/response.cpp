#include "response.hpp"

#include <glm/geometric.hpp>

namespace physics_custom {

glm::dvec3 reflect_off_moving_wall(const glm::dvec3 &v, const glm::dvec3 &v_wall, const glm::dvec3 &n) {
    return v - 2.0 * glm::dot(v - v_wall, n) * n;
}

} // namespace physics_custom
