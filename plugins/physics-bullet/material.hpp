// A model's rigid-body settings as Bullet takes them (SDK 1.3, docs/physics-bullet.md "Per-model
// settings"): its restitution and friction, set on its body, combined per contact as
// physics.custom combines them (the lower restitution, the higher friction of the two models);
// whether Bullet turns it, and its angular velocity at t = 0.
#pragma once

#include <animator/document.h>

#include <glm/vec3.hpp>

#include <string>

namespace physics_bullet {

struct Material {
    double restitution = 1.0; // the seed's elastic contact
    double friction = 0.0;    // the seed's frictionless contact
    bool rotates = false;
    glm::dvec3 angular_velocity{0.0}; // at t = 0, world axes, rad/s
};

// The model's own values when its description carries them (ANI_MODEL_DESC_HAS_BODY), else the
// defaults. The backend's document-wide parameters of earlier documents still hold for every
// contact: the restitution is at most `all_restitution`, the friction at least `all_friction`,
// and every model turns with `all_rotate` (with the min / max rule that is the same contact as
// before, e.g. both models at e = 1 and the parameter at E: E). Throws ani::Failure naming the
// model when a value is out of range or not finite.
Material material_of(const ani_model_desc &desc, const std::string &model_name,
                     double all_restitution, double all_friction, bool all_rotate);

// Bullet combines two bodies' coefficients through process-wide callbacks (btManifoldResult.h),
// by default the product. Sets them to the min (restitution) and max (friction) rules; the same
// functions every time, so bakes running one after the other (or instances of the plugin) agree.
void install_combine_rules();

// The rules themselves, for the tests.
double combined_restitution(double a, double b);
double combined_friction(double a, double b);

} // namespace physics_bullet
