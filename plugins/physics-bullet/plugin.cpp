// The Bullet physics backend (id physics.bullet): the scene in a btDiscreteDynamicsWorld stepped
// at a fixed step, configured to follow the seed's model as closely as Bullet can
// (docs/physics-bullet.md). Used to cross-check physics.custom, and offered as a second engine.
#include "bullet_bake.hpp"

#include <animator/physics.h>
#include <animator/plugin_cpp.hpp>

#include <cmath>
#include <mutex>
#include <string>

namespace {

constexpr char kPluginId[] = "physics.bullet";

const ani_param_descriptor kParams[] = {
    {sizeof(ani_param_descriptor),
     "step",
     "Time step",
     "Bullet's fixed time step in seconds. Smaller is more accurate and slower; the error of a "
     "bounce or an exchange shrinks about in proportion to it.",
     ANI_PARAM_TIME,
     1e-5,
     0.1,
     {{1.0 / 240.0, 0.0, 0.0, 0.0}},
     0.0,
     nullptr,
     0},
    {sizeof(ani_param_descriptor),
     "solver_iterations",
     "Solver iterations",
     "Iterations of Bullet's sequential impulse solver per step: more resolve simultaneous "
     "contacts (a Newton's cradle) more exactly.",
     ANI_PARAM_INT,
     1.0,
     1000.0,
     {{10.0, 0.0, 0.0, 0.0}},
     1.0,
     nullptr,
     0},
    {sizeof(ani_param_descriptor),
     "ccd",
     "Continuous collision detection",
     "Sweeps fast bodies over each step so they cannot pass through thin models (they stop at the "
     "contact, losing the rest of that step).",
     ANI_PARAM_BOOL,
     0.0,
     1.0,
     {{1.0, 0.0, 0.0, 0.0}},
     0.0,
     nullptr,
     0},
    {sizeof(ani_param_descriptor),
     "rotate_on_contact",
     "Rotate on contact",
     "Every model with Dynamics turns from its contacts once its keys end, as if each had Rotates "
     "on (for earlier documents: prefer each model's Rotates). Off, only models with Rotates do.",
     ANI_PARAM_BOOL,
     0.0,
     1.0,
     {{0.0, 0.0, 0.0, 0.0}},
     0.0,
     nullptr,
     0},
    {sizeof(ani_param_descriptor),
     "friction",
     "Friction",
     "The least Coulomb friction of every contact; a model's own Friction counts where higher (for "
     "earlier documents: prefer each model's; 0: the models' own). Without rotation a model slides "
     "to a stop; with it, it rolls.",
     ANI_PARAM_FLOAT,
     0.0,
     2.0,
     {{0.0, 0.0, 0.0, 0.0}},
     0.01,
     nullptr,
     0},
    {sizeof(ani_param_descriptor),
     "restitution",
     "Restitution",
     "The most restitution of every contact; a model's own Restitution counts where lower (for "
     "earlier documents: prefer each model's; 1: the models' own).",
     ANI_PARAM_FLOAT,
     0.0,
     1.0,
     {{1.0, 0.0, 0.0, 0.0}},
     0.01,
     nullptr,
     0},
    {sizeof(ani_param_descriptor),
     "margin",
     "Collision margin",
     "The margin in metres Bullet keeps around convex models: their faces stay where the mesh's "
     "are, their edges and corners are rounded by it (at most a fifth of the model's inner "
     "radius). Smaller lands a cube on its corner closer to the exact time; Bullet's own default "
     "is 0.04.",
     ANI_PARAM_FLOAT,
     1e-4,
     0.1,
     {{0.04, 0.0, 0.0, 0.0}},
     0.001,
     nullptr,
     0},
};

struct Instance {
    const ani_host *host = nullptr;
    ani::ParamStore params{kParams, sizeof(kParams) / sizeof(kParams[0])};
    physics_bullet::BakeInProgress bake; // the last slice's world, and what it said
};

void *create(const ani_host *host, ani_status *status) {
    Instance *self = nullptr;
    ani::guarded(status, [&] {
        self = new Instance();
        self->host = host;
    });
    return self;
}

void destroy(void *instance) {
    delete static_cast<Instance *>(instance);
}

ani_status_code set_param(void *instance, const char *id, const ani_param_value *value,
                          ani_status *status) {
    return ani::guarded(status, [&] {
        if (!value) throw ani::Failure(ANI_ERR_INVALID_ARGUMENT, "no value");
        const double v = value->value[0];
        if (id && std::string(id) == "step" && !(std::isfinite(v) && v > 0.0))
            throw ani::Failure(ANI_ERR_INVALID_ARGUMENT, "the time step must be positive");
        ani_status inner{};
        if (static_cast<Instance *>(instance)->params.set(id, value, &inner) != ANI_OK)
            throw ani::Failure(static_cast<ani_status_code>(inner.code), inner.message);
    });
}

ani_status_code bake(void *instance, const ani_physics_scene *scene, double t_begin, double t_end,
                     const ani_bake_sink *sink, ani_status *status) {
    return ani::guarded(status, [&] {
        if (!scene || !sink || !sink->segment || !scene->evaluate_keyed)
            throw ani::Failure(ANI_ERR_INVALID_ARGUMENT,
                               "bake needs a scene, a sink and evaluate_keyed");
        if (!(t_begin <= t_end) || !std::isfinite(t_begin) || !std::isfinite(t_end))
            throw ani::Failure(ANI_ERR_INVALID_ARGUMENT,
                               "bake needs finite times with t_begin <= t_end");
        if (!std::isfinite(scene->gravity))
            throw ani::Failure(ANI_ERR_INVALID_ARGUMENT, "gravity is not finite");
        if (sink->progress && !sink->progress(sink->context, 0.0))
            throw ani::Failure(ANI_ERR_CANCELLED, "the bake was cancelled");
        Instance &self = *static_cast<Instance *>(instance);
        physics_bullet::BakeOptions options;
        options.step = self.params.number("step");
        options.solver_iterations = static_cast<int>(self.params.number("solver_iterations"));
        options.ccd = self.params.number("ccd") != 0.0;
        options.rotate_on_contact = self.params.number("rotate_on_contact") != 0.0;
        options.friction = self.params.number("friction");
        options.restitution = self.params.number("restitution");
        options.margin = self.params.number("margin");
        {
            // Bullet keeps global statistics counters (gNumClampedCcdMotions,
            // gNumSplitImpulseRecoveries, ...) that are not atomic: bakes of different instances
            // take turns.
            static std::mutex bullet;
            std::lock_guard<std::mutex> lock(bullet);
            physics_bullet::bake_scene(*scene, t_begin, t_end, *sink, self.host, options,
                                       &self.bake);
        }
        if (sink->progress && !sink->progress(sink->context, 1.0))
            throw ani::Failure(ANI_ERR_CANCELLED, "the bake was cancelled");
    });
}

const ani_physics_api api = {
    sizeof(ani_physics_api),
    {sizeof(ani_instance_api), create, destroy, ani::store_get_param<Instance>, set_param},
    bake,
};

const ani_plugin_descriptor descriptor = {
    sizeof(ani_plugin_descriptor),
    kPluginId,
    ANI_KIND_PHYSICS,
    "Bullet",
    {0, 1, 0},
    "Bullet 3 (double precision) at a fixed time step, set up to follow the seed's model: keyed "
    "models as kinematic bodies; each model's restitution, friction and Rotates (by default "
    "elastic, frictionless, turned by keys only), a contact taking the lower restitution and the "
    "higher friction. A second engine to cross-check the exact one.",
    kParams,
    sizeof(kParams) / sizeof(kParams[0]),
    &api,
};

const ani_plugin_descriptor *const kPlugins[] = {&descriptor};

} // namespace

ANI_PLUGIN_ENTRY(kPlugins)
