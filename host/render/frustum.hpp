// Frustum culling: the six planes of a view-projection matrix (Gribb and Hartmann, "Fast
// Extraction of Viewing Frustum Planes from the World-View-Projection Matrix", 2001) and whether
// a bounding sphere can be seen.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>

namespace animator {

class Frustum {
  public:
    explicit Frustum(const glm::dmat4 &view_projection);

    // False only when the sphere lies wholly outside one of the planes (so it cannot be seen).
    bool may_see(const glm::dvec3 &center, double radius) const;

  private:
    std::array<glm::dvec4, 6> planes_; // inside where dot(plane.xyz, p) + plane.w >= 0, normalised
};

// The world-space bounding sphere of a mesh's sphere (center, radius in model space) under a
// model's world matrix: the center transformed, the radius times the largest axis scale.
void transform_bounding_sphere(const glm::dmat4 &world, const glm::dvec3 &center, double radius,
                               glm::dvec3 &world_center, double &world_radius);

} // namespace animator
