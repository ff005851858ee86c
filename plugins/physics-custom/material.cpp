#include "material.hpp"

#include <animator/plugin_cpp.hpp>

#include <cmath>
#include <string>

namespace physics_custom {

Material material_of(const ani_model_desc &desc) {
    Material m;
    if (!ANI_MODEL_DESC_HAS_BODY(&desc)) return m;
    auto refuse = [&](const std::string &what) {
        throw ani::Failure(ANI_ERR_INVALID_ARGUMENT,
                           "model '" + std::string(desc.name ? desc.name : "?") + "': " + what);
    };
    if (!(desc.restitution >= 0.0 && desc.restitution <= 1.0))
        refuse("restitution must be in [0, 1]");
    if (!(desc.friction >= 0.0) || !std::isfinite(desc.friction))
        refuse("friction must be a finite number >= 0");
    const ani_vec3 &w = desc.angular_velocity;
    if (!std::isfinite(w.x) || !std::isfinite(w.y) || !std::isfinite(w.z))
        refuse("angular velocity must be finite");
    m.restitution = desc.restitution;
    m.friction = desc.friction;
    m.rotates = desc.rotates != 0;
    m.angular_velocity = {w.x, w.y, w.z};
    return m;
}

} // namespace physics_custom
