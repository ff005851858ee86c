// A model's contact material and turning (SDK 1.3, issue 18): restitution e in [0, 1], Coulomb
// friction mu >= 0, whether contacts turn it, and its angular velocity at t = 0. A description
// older than 1.3 gets the seed's world: e = 1, mu = 0, turned only by its keys.
#pragma once

#include <animator/physics.h>
#include <glm/vec3.hpp>

namespace physics_custom {

struct Material {
    double restitution = 1.0;
    double friction = 0.0;
    bool rotates = false;
    glm::dvec3 angular_velocity{0.0};
    // The seed's elastic, frictionless, non-turning contacts (its code paths, bit for bit).
    bool seed() const { return restitution == 1.0 && friction == 0.0 && !rotates; }
};

// Reads the description's values, refusing (ani::Failure, naming the model) one out of range or
// not finite.
Material material_of(const ani_model_desc &desc);

} // namespace physics_custom
