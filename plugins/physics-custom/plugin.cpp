// The custom physics backend (id physics.custom): the seed's algorithms, exact and event-driven.
// Keyed spans, free motion after a model's keys, and exact collisions (event_bake.hpp).
#include "event_bake.hpp"

#include <animator/physics.h>
#include <animator/plugin_cpp.hpp>

#include <cmath>
#include <string>

namespace {

constexpr char kPluginId[] = "physics.custom";

const char *const kBroadPhases[] = {"Automatic", "Grid", "All pairs"};

const ani_param_descriptor kParams[] = {
    {sizeof(ani_param_descriptor), "broad_phase", "Broad phase",
     "How the bake finds the pairs of spheres that may meet: Automatic uses a uniform grid from 16 "
     "moving spheres on, Grid always, All pairs tests every pair at every event (the oracle).",
     ANI_PARAM_ENUM, 0.0, 2.0, {{0.0, 0.0, 0.0, 0.0}}, 0.0, kBroadPhases, 3},
    {sizeof(ani_param_descriptor), "gas_lane", "Gas lane",
     "Bakes a scene whose moving models are all free spheres of one radius without gravity, "
     "spin or friction, bouncing elastically (a gas), with a compact engine of its own when the "
     "broad phase is the grid: the same events, several times faster. Off: the general engine.",
     ANI_PARAM_BOOL, 0.0, 1.0, {{1.0, 0.0, 0.0, 0.0}}, 0.0, nullptr, 0},
};

struct Instance {
    const ani_host *host = nullptr;
    ani::ParamStore params{kParams, sizeof(kParams) / sizeof(kParams[0])};
    // What one slice of a bake leaves to the next (event_bake.hpp).
    physics_custom::BakeInProgress in_progress;
};

void *create(const ani_host *host, ani_status *status) {
    Instance *self = nullptr;
    ani::guarded(status, [&] {
        self = new Instance();
        self->host = host;
    });
    return self;
}

void destroy(void *instance) { delete static_cast<Instance *>(instance); }

ani_status_code bake(void *instance, const ani_physics_scene *scene, double t_begin, double t_end,
                     const ani_bake_sink *sink, ani_status *status) {
    return ani::guarded(status, [&] {
        if (!scene || !sink || !sink->segment || !scene->evaluate_keyed)
            throw ani::Failure(ANI_ERR_INVALID_ARGUMENT, "bake needs a scene, a sink and evaluate_keyed");
        if (!(t_begin <= t_end) || !std::isfinite(t_begin) || !std::isfinite(t_end))
            throw ani::Failure(ANI_ERR_INVALID_ARGUMENT, "bake needs finite times with t_begin <= t_end");
        if (!std::isfinite(scene->gravity)) throw ani::Failure(ANI_ERR_INVALID_ARGUMENT, "gravity is not finite");
        if (sink->progress && !sink->progress(sink->context, 0.0))
            throw ani::Failure(ANI_ERR_CANCELLED, "the bake was cancelled");
        Instance &self = *static_cast<Instance *>(instance);
        physics_custom::BakeOptions options;
        options.broad_phase = static_cast<physics_custom::BroadPhase>(static_cast<int>(self.params.number("broad_phase")));
        options.gas_lane = self.params.number("gas_lane") != 0.0;
        physics_custom::bake_scene(*scene, t_begin, t_end, *sink, self.host, options, &self.in_progress);
        if (sink->progress && !sink->progress(sink->context, 1.0))
            throw ani::Failure(ANI_ERR_CANCELLED, "the bake was cancelled");
    });
}

const ani_physics_api api = {
    sizeof(ani_physics_api),
    {sizeof(ani_instance_api), create, destroy, ani::store_get_param<Instance>, ani::store_set_param<Instance>},
    bake,
};

const ani_plugin_descriptor descriptor = {
    sizeof(ani_plugin_descriptor),
    kPluginId,
    ANI_KIND_PHYSICS,
    "Custom (exact)",
    {0, 1, 0},
    "The seed's physics, exact: keyed motion, then free fall, constant velocity or projectile "
    "motion after each model's last keyframe, with elastic collisions found at their exact times.",
    kParams,
    sizeof(kParams) / sizeof(kParams[0]),
    &api,
};

const ani_plugin_descriptor *const kPlugins[] = {&descriptor};

} // namespace

ANI_PLUGIN_ENTRY(kPlugins)
