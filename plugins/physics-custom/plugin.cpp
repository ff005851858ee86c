// The custom physics backend (id physics.custom): the seed's algorithms, exact and event-driven.
// This part: keyed spans and the free motion after a model's keys, as closed-form segments.
// Collisions come next (issue "physics-custom: exact continuous collisions").
#include "free_motion.hpp"

#include <animator/physics.h>
#include <animator/plugin_cpp.hpp>

#include <cmath>
#include <string>

namespace {

using physics_custom::free_segment;

bool finite(const ani_vec3 &v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

struct Instance {
    const ani_host *host = nullptr;
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

ani_status_code get_param(void *, const char *id, ani_param_value *, ani_status *status) {
    return ani::set_status(status, ANI_ERR_UNKNOWN_PARAM,
                           std::string("physics.custom has no parameter '") + (id ? id : "") + "'");
}

ani_status_code set_param(void *, const char *id, const ani_param_value *, ani_status *status) {
    return get_param(nullptr, id, nullptr, status);
}

void emit(const ani_bake_sink *sink, const ani_motion_segment &s, const char *name) {
    if (!finite(s.p0) || !finite(s.v0) || !finite(s.a) || !std::isfinite(s.t0) || !std::isfinite(s.t1))
        throw ani::Failure(ANI_ERR_FAILED, std::string("model '") + name +
                                               "' would move to a value that is not finite; check its keys, velocity and gravity");
    sink->segment(sink->context, &s);
}

// One model's motion over [t_begin, t_end]: KEYED over its keyed spans, free in between and
// after the last one, starting from where and how fast its keys left it.
void bake_model(const ani_physics_scene &scene, uint32_t index, double t_begin, double t_end,
                const ani_vec3 &gravity, const ani_bake_sink *sink) {
    const ani_physics_model &model = scene.models[index];
    const char *name = model.desc && model.desc->name ? model.desc->name : "?";
    if (!model.desc) throw ani::Failure(ANI_ERR_INVALID_ARGUMENT, "a model has no description");
    double t = t_begin;
    ani_body_state state = model.start;
    for (uint32_t k = 0; k < model.keyed_span_count && t < t_end; ++k) {
        const ani_time_span span = model.keyed_spans[k];
        if (span.end <= t && !(span.begin == span.end && span.end == t && state.motion == ANI_MOTION_KEYED))
            continue; // entirely before t
        if (span.begin > t) { // a free stretch before this span
            const double until = std::min(span.begin, t_end);
            emit(sink, free_segment(index, *model.desc, state, t, until, gravity), name);
            t = until;
            if (t >= t_end) break;
        }
        const double end = std::min(span.end, t_end);
        if (end > t) {
            ani_motion_segment keyed{};
            keyed.model = index;
            keyed.motion = ANI_MOTION_KEYED;
            keyed.t0 = t;
            keyed.t1 = end;
            emit(sink, keyed, name);
        }
        t = std::max(t, end);
        // Leaving the keys: where they put the model and how fast it was going there.
        ani_model_state pose{};
        ani_vec3 velocity{};
        ani_status_code code = scene.evaluate_keyed(scene.host_context, index, span.end, &pose, &velocity);
        if (code != ANI_OK) throw ani::Failure(static_cast<ani_status_code>(code), std::string("cannot evaluate the keys of model '") + name + "'");
        state.motion = ANI_MOTION_KEYED;
        state.center = pose.center;
        state.velocity = velocity;
    }
    if (t < t_end) emit(sink, free_segment(index, *model.desc, state, t, t_end, gravity), name);
}

ani_status_code bake(void *, const ani_physics_scene *scene, double t_begin, double t_end,
                     const ani_bake_sink *sink, ani_status *status) {
    return ani::guarded(status, [&] {
        if (!scene || !sink || !sink->segment || !scene->evaluate_keyed)
            throw ani::Failure(ANI_ERR_INVALID_ARGUMENT, "bake needs a scene, a sink and evaluate_keyed");
        if (!(t_begin <= t_end) || !std::isfinite(t_begin) || !std::isfinite(t_end))
            throw ani::Failure(ANI_ERR_INVALID_ARGUMENT, "bake needs finite times with t_begin <= t_end");
        if (!std::isfinite(scene->gravity)) throw ani::Failure(ANI_ERR_INVALID_ARGUMENT, "gravity is not finite");
        const ani_vec3 gravity = physics_custom::gravity_vector(scene->gravity, scene->down_axis);
        for (uint32_t i = 0; i < scene->model_count; ++i) {
            bake_model(*scene, i, t_begin, t_end, gravity, sink);
            if (sink->progress && !sink->progress(sink->context, double(i + 1) / scene->model_count))
                throw ani::Failure(ANI_ERR_CANCELLED, "the bake was cancelled");
        }
    });
}

const ani_physics_api api = {
    sizeof(ani_physics_api),
    {sizeof(ani_instance_api), create, destroy, get_param, set_param},
    bake,
};

const ani_plugin_descriptor descriptor = {
    sizeof(ani_plugin_descriptor),
    "physics.custom",
    ANI_KIND_PHYSICS,
    "Custom (exact)",
    {0, 1, 0},
    "The seed's physics, exact: keyed motion, then free fall, constant velocity or projectile "
    "motion after each model's last keyframe, as closed-form segments.",
    nullptr,
    0,
    &api,
};

ani_status_code init(const ani_host *, ani_status *status) { return ani::set_status(status, ANI_OK, ""); }
void deinit() {}
uint32_t count() { return 1; }
const ani_plugin_descriptor *get(uint32_t index) { return index == 0 ? &descriptor : nullptr; }

} // namespace

extern "C" {
ANI_DECLARE_ENTRY;
const ani_plugin_entry animator_plugin_entry = {
    sizeof(ani_plugin_entry), {ANI_ABI_MAJOR, ANI_ABI_MINOR, 0}, init, deinit, count, get,
};
}
