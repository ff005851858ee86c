// Elastic responses (seed, "3D Elastic Collisions"; physics.md for the moving wall).
#pragma once

#include <glm/vec3.hpp>

#include <utility>

namespace physics_custom {

// Off a model without Dynamics: the reflection about the normal, v1 = v0 - 2 (v0 . n) n.
glm::dvec3 reflect(const glm::dvec3 &v, const glm::dvec3 &n);

// Off a keyed model moving at v_wall, as a wall of infinite mass: the relative velocity is
// reflected, v1 = v0 - 2 ((v0 - v_wall) . n) n.
glm::dvec3 reflect_off_moving_wall(const glm::dvec3 &v, const glm::dvec3 &v_wall, const glm::dvec3 &n);

// Two models with Dynamics: the 1D elastic exchange along the normal, the tangential
// components unchanged; momentum and kinetic energy are conserved.
std::pair<glm::dvec3, glm::dvec3> elastic_exchange(double ma, const glm::dvec3 &va, double mb, const glm::dvec3 &vb,
                                                   const glm::dvec3 &n);

} // namespace physics_custom
