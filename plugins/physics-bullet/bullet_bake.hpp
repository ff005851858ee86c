// The Bullet bake (docs/physics-bullet.md): the scene in a btDiscreteDynamicsWorld stepped at a
// fixed step, free models with Dynamics as dynamic rigid bodies, keyed models (and models without
// Dynamics, which nothing can push) as kinematic bodies, static models as static ones. Bullet's
// steps are reported as closed-form segments, one per stretch between contacts (track.hpp).
#pragma once

#include <animator/physics.h>

namespace physics_bullet {

struct BakeOptions {
    double step = 1.0 / 240.0; // seconds
    int solver_iterations = 10;
    bool ccd = true;
    bool rotate_on_contact = false;
    double friction = 0.0;
    double restitution = 1.0;
};

// Bakes [t_begin, t_end]: keyed spans, Bullet's steps, collision events. Throws ani::Failure.
void bake_scene(const ani_physics_scene &scene, double t_begin, double t_end,
                const ani_bake_sink &sink, const ani_host *host, const BakeOptions &options);

} // namespace physics_bullet
