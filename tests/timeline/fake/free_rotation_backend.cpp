// A physics backend for the host's tests (id physics.test_free_rotation): it reports what the
// test asks for, so that the host's reading of ABI 1.4 free-rotation segments is checked apart
// from any real backend. Model 0 stays at the origin (its motion segment: the pivot's path) and
// turns at w = (0, 0, 2) rad/s about its pivot (0, 1, 0) in a free-rotation segment whose
// moments are (1, 2, 3), or, with the parameter `bad` at 1, (3, 2, 1): not ascending. With the
// parameter `hinge` at 1 it reports an ABI 1.6 hinge segment instead: model 0 swings about the
// z axis through its pivot as the pendulum psi'' = -9 sin psi from psi = 0.5 at rest (omega2 = -1
// with `bad`).
#include <animator/physics.h>
#include <animator/plugin_cpp.hpp>

namespace {

constexpr char kPluginId[] = "physics.test_free_rotation";

const ani_param_descriptor kParams[] = {
    {sizeof(ani_param_descriptor), "bad", "Bad", "1: moments that are not ascending",
     ANI_PARAM_BOOL, 0.0, 1.0, {{0.0, 0.0, 0.0, 0.0}}, 0.0, nullptr, 0},
    {sizeof(ani_param_descriptor), "hinge", "Hinge", "1: a hinge segment",
     ANI_PARAM_BOOL, 0.0, 1.0, {{0.0, 0.0, 0.0, 0.0}}, 0.0, nullptr, 0},
};

struct Instance {
    ani::ParamStore params{kParams, 2};
};

void *create(const ani_host *, ani_status *status) {
    Instance *self = nullptr;
    ani::guarded(status, [&] { self = new Instance(); });
    return self;
}

void destroy(void *instance) { delete static_cast<Instance *>(instance); }

ani_status_code bake(void *instance, const ani_physics_scene *scene, double t_begin, double t_end,
                     const ani_bake_sink *sink, ani_status *status) {
    return ani::guarded(status, [&] {
        const Instance &self = *static_cast<Instance *>(instance);
        for (uint32_t m = 0; m < scene->model_count; ++m) {
            ani_motion_segment s{};
            s.model = m;
            s.motion = ANI_MOTION_FREE;
            s.t0 = t_begin;
            s.t1 = t_end;
            sink->segment(sink->context, &s);
        }
        if (scene->model_count == 0) return;
        const bool bad = self.params.number("bad") != 0.0;
        if (self.params.number("hinge") != 0.0) {
            if (!sink->hinge || t_begin != 0.0) return;
            ani_hinge_segment h{};
            h.model = 0;
            h.t0 = t_begin;
            h.t1 = t_end;
            h.q0 = ani_quat{1.0, 0.0, 0.0, 0.0};
            h.axis = ani_vec3{0.0, 0.0, 1.0};
            h.angle0 = 0.5;
            h.rate0 = 0.0;
            h.omega2 = bad ? -1.0 : 9.0;
            h.pivot = ani_vec3{0.0, 1.0, 0.0};
            sink->hinge(sink->context, &h);
            return;
        }
        if (!sink->free_rotation) return;
        ani_free_rotation_segment r{};
        r.model = 0;
        r.t0 = t_begin;
        r.t1 = t_end;
        r.q0 = ani_quat{1.0, 0.0, 0.0, 0.0};
        r.w0 = ani_vec3{0.0, 0.0, 2.0};
        r.moments = bad ? ani_vec3{3.0, 2.0, 1.0} : ani_vec3{1.0, 2.0, 3.0};
        r.principal = ani_quat{1.0, 0.0, 0.0, 0.0};
        r.pivot = ani_vec3{0.0, 1.0, 0.0};
        if (t_begin == 0.0) sink->free_rotation(sink->context, &r);
    });
}

const ani_physics_api api = {
    sizeof(ani_physics_api),
    {sizeof(ani_instance_api), create, destroy, ani::store_get_param<Instance>,
     ani::store_set_param<Instance>},
    bake,
};

const ani_plugin_descriptor descriptor = {
    sizeof(ani_plugin_descriptor),
    kPluginId,
    ANI_KIND_PHYSICS,
    "Test: free rotation",
    {0, 1, 0},
    "Reports one free-rotation segment about a pivot, for the host's tests.",
    kParams,
    2,
    &api,
};

const ani_plugin_descriptor *const kPlugins[] = {&descriptor};

} // namespace

ANI_PLUGIN_ENTRY(kPlugins)
