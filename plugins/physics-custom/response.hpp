// Elastic responses (seed, "3D Elastic Collisions"; physics.md for the moving wall). The two the
// gas lane takes at every collision are inline: called, they were 2 to 4% of its small gases.
#pragma once

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <utility>

namespace physics_custom {

// Off a model without Dynamics: the reflection about the normal, v1 = v0 - 2 (v0 . n) n.
inline glm::dvec3 reflect(const glm::dvec3 &v, const glm::dvec3 &n) {
    return v - 2.0 * glm::dot(v, n) * n;
}

// Off a keyed model moving at v_wall, as a wall of infinite mass: the relative velocity is
// reflected, v1 = v0 - 2 ((v0 - v_wall) . n) n.
glm::dvec3 reflect_off_moving_wall(const glm::dvec3 &v, const glm::dvec3 &v_wall, const glm::dvec3 &n);

// Two models with Dynamics: the 1D elastic exchange along the normal, the tangential
// components unchanged; momentum and kinetic energy are conserved.
inline std::pair<glm::dvec3, glm::dvec3> elastic_exchange(double ma, const glm::dvec3 &va,
                                                          double mb, const glm::dvec3 &vb,
                                                          const glm::dvec3 &n) {
    // v = v_perp + v_par; only the components along n exchange, as in 1D:
    // va1 = ((ma - mb) va + 2 mb vb) / (ma + mb), vb1 = ((mb - ma) vb + 2 ma va) / (ma + mb).
    const double ua = glm::dot(va, n), ub = glm::dot(vb, n);
    const double total = ma + mb;
    const double ua1 = ((ma - mb) * ua + 2.0 * mb * ub) / total;
    const double ub1 = ((mb - ma) * ub + 2.0 * ma * ua) / total;
    return {va + (ua1 - ua) * n, vb + (ub1 - ub) * n};
}

} // namespace physics_custom
