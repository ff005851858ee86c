#include "render/frustum.hpp"

#include <glm/geometric.hpp>

#include <algorithm>

namespace animator {

Frustum::Frustum(const glm::dmat4 &m) {
    // Rows of the matrix (glm is column-major: m[column][row]).
    auto row = [&](int r) { return glm::dvec4(m[0][r], m[1][r], m[2][r], m[3][r]); };
    const glm::dvec4 r0 = row(0), r1 = row(1), r2 = row(2), r3 = row(3);
    planes_ = {r3 + r0, r3 - r0, r3 + r1, r3 - r1, r3 + r2, r3 - r2};
    for (glm::dvec4 &p : planes_) p /= glm::length(glm::dvec3(p));
}

bool Frustum::may_see(const glm::dvec3 &center, double radius) const {
    for (const glm::dvec4 &p : planes_)
        if (glm::dot(glm::dvec3(p), center) + p.w < -radius) return false;
    return true;
}

void transform_bounding_sphere(const glm::dmat4 &world, const glm::dvec3 &center, double radius,
                               glm::dvec3 &world_center, double &world_radius) {
    world_center = glm::dvec3(world * glm::dvec4(center, 1.0));
    const double scale =
        std::max({glm::length(glm::dvec3(world[0])), glm::length(glm::dvec3(world[1])),
                  glm::length(glm::dvec3(world[2]))});
    world_radius = radius * scale;
}

} // namespace animator
