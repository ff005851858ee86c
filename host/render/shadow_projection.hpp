// Where a light's shadow map looks: a perspective projection from a point light that holds the
// scene's bounding sphere (the casters and the surfaces they may shade), as tight as it can, so
// the map's texels are spent on the scene (Williams 1978, "Casting curved shadows on curved
// surfaces"; Dimitrov's "Cascaded Shadow Maps" for the fit to bounds). Pure math, no GL.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace animator {

struct ShadowProjection {
    // World to the map's texture space: x and y in 0..1 across the map, z the depth 0..1 that the
    // depth pass writes (bias matrix * projection * view).
    glm::dmat4 world_to_map{1.0};
    // World to clip space for the depth pass.
    glm::dmat4 view_projection{1.0};
    // The width of one texel at distance 1 from the light: a texel at distance d is this times d
    // wide. Shading pushes a point this far (times d) along its normal before looking it up, so a
    // surface never shades itself (normal offset, Holbein 2011).
    double texel_per_distance = 0.0;
    // The scene's sphere is wholly inside the map's view; false when the light is inside or
    // nearly inside it, when the map covers a cone of kWidestShadowDegrees about the sphere's
    // centre and what lies outside is lit.
    bool holds_scene = true;
};

// The widest field of view of a shadow map, in degrees (a light inside the scene's bounds).
constexpr double kWidestShadowDegrees = 120.0;

// The projection of a map `size` texels square, from a light at `light` holding the sphere at
// `centre` with `radius` (> 0).
ShadowProjection shadow_projection(const glm::dvec3 &light, const glm::dvec3 &centre, double radius,
                                   int size);

} // namespace animator
