#include "material.hpp"

#include <animator/plugin_cpp.hpp>

#include <BulletCollision/CollisionDispatch/btCollisionObject.h>
#include <BulletCollision/CollisionDispatch/btManifoldResult.h>

#include <algorithm>
#include <cmath>

namespace physics_bullet {

namespace {

btScalar min_restitution(const btCollisionObject *a, const btCollisionObject *b) {
    return combined_restitution(a->getRestitution(), b->getRestitution());
}

btScalar max_friction(const btCollisionObject *a, const btCollisionObject *b) {
    return combined_friction(a->getFriction(), b->getFriction());
}

[[noreturn]] void refuse(const std::string &model, const std::string &what) {
    throw ani::Failure(ANI_ERR_INVALID_ARGUMENT, "model '" + model + "' has " + what);
}

} // namespace

double combined_restitution(double a, double b) {
    return std::min(a, b);
}

double combined_friction(double a, double b) {
    return std::max(a, b);
}

Material material_of(const ani_model_desc &desc, const std::string &model_name,
                     double all_restitution, double all_friction, bool all_rotate) {
    Material m;
    if (ANI_MODEL_DESC_HAS_BODY(&desc)) {
        if (!(desc.restitution >= 0.0 && desc.restitution <= 1.0))
            refuse(model_name, "a restitution outside 0 .. 1");
        if (!(desc.friction >= 0.0 && std::isfinite(desc.friction)))
            refuse(model_name, "a friction that is not a finite number >= 0");
        const ani_vec3 &w = desc.angular_velocity;
        if (!std::isfinite(w.x) || !std::isfinite(w.y) || !std::isfinite(w.z))
            refuse(model_name, "an angular velocity that is not finite");
        m.restitution = desc.restitution;
        m.friction = desc.friction;
        m.rotates = desc.rotates != 0;
        m.angular_velocity = glm::dvec3(w.x, w.y, w.z);
    }
    m.restitution = combined_restitution(m.restitution, all_restitution);
    m.friction = combined_friction(m.friction, all_friction);
    m.rotates = m.rotates || all_rotate;
    return m;
}

void install_combine_rules() {
    gCalculateCombinedRestitutionCallback = &min_restitution;
    gCalculateCombinedFrictionCallback = &max_friction;
}

} // namespace physics_bullet
