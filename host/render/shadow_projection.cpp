#include "render/shadow_projection.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace animator {

ShadowProjection shadow_projection(const glm::dvec3 &light, const glm::dvec3 &centre, double radius,
                                   int size) {
    ShadowProjection p;
    glm::dvec3 to_centre = centre - light;
    double distance = glm::length(to_centre);
    const double widest = glm::radians(kWidestShadowDegrees) / 2.0;
    double half_angle = widest;
    // Outside the sphere (with a margin) the cone that just holds it: sin(half angle) = r / d.
    if (distance > radius * 1.02)
        half_angle = std::min(std::asin(radius / distance) * 1.02, widest);
    p.holds_scene = distance > radius * 1.02 && half_angle < widest;
    if (distance < 1e-9) { // the light at the centre: look down
        to_centre = glm::dvec3(0.0, -1.0, 0.0);
        distance = 1.0;
    }
    const glm::dvec3 forward = to_centre / glm::length(to_centre);
    // Any up not along the view; +Y unless the light looks (nearly) straight up or down.
    const glm::dvec3 up =
        std::abs(forward.y) > 0.99 ? glm::dvec3(0.0, 0.0, 1.0) : glm::dvec3(0.0, 1.0, 0.0);
    const glm::dmat4 view = glm::lookAt(light, light + forward, up);
    const double along = glm::length(centre - light);
    const double far = along + radius * 1.02;
    // Near as far out as the sphere allows (depth precision), never closer than far / 1000.
    const double near = std::max(along - radius * 1.02, far / 1000.0);
    const glm::dmat4 projection = glm::perspective(2.0 * half_angle, 1.0, near, far);
    p.view_projection = projection * view;
    // Clip space -1..1 to texture space 0..1, depth too (what the depth pass stores).
    const glm::dmat4 bias = glm::translate(glm::dmat4(1.0), glm::dvec3(0.5)) *
                            glm::scale(glm::dmat4(1.0), glm::dvec3(0.5));
    p.world_to_map = bias * p.view_projection;
    p.texel_per_distance = 2.0 * std::tan(half_angle) / std::max(size, 1);
    return p;
}

} // namespace animator
