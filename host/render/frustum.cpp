#include "render/frustum.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

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
    const glm::dvec3 a(world[0]), b(world[1]), c(world[2]);
    // The most the matrix stretches a direction: its longest column when they are orthogonal (a
    // T R S), else (a rest shape's shear) at most the root of their squared lengths' sum.
    const double tolerance = 1e-9 * (glm::dot(a, a) + glm::dot(b, b) + glm::dot(c, c));
    const bool orthogonal = std::abs(glm::dot(a, b)) <= tolerance && std::abs(glm::dot(b, c)) <= tolerance &&
                            std::abs(glm::dot(a, c)) <= tolerance;
    const double scale = orthogonal ? std::max({glm::length(a), glm::length(b), glm::length(c)})
                                    : std::sqrt(glm::dot(a, a) + glm::dot(b, b) + glm::dot(c, c));
    world_radius = radius * scale;
}

} // namespace animator
