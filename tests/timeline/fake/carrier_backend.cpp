// A physics backend for the host's tests (id physics.test_carrier): it reports what the test asks
// for, so that the host's reading of ABI 1.8 carried segments is checked apart from any real
// backend. Model 0 is keyed throughout; model 1 is carried by model 0 over the whole bake, at
// offset (1, 0.5, 0) in its frame, turned 30 degrees about x relative to it.
//   - `mode` 1: model 1 is carried by itself; 2: model 0 is carried by model 1 as well (a chain
//     that comes back); 3: a model carried by a model there is not.
//   - A bake that starts after 0 checks the state the host gives model 1: free, where its
//     carrier's keys put it, turning with its carrier (start_turning); it fails naming what is not.
#include <animator/physics.h>
#include <animator/plugin_cpp.hpp>

#include <cmath>
#include <string>

namespace {

constexpr char kPluginId[] = "physics.test_carrier";

const ani_param_descriptor kParams[] = {
    {sizeof(ani_param_descriptor), "mode", "Mode",
     "0: model 1 carried by model 0; 1: by itself; 2: a chain; 3: by a model there is not",
     ANI_PARAM_INT, 0.0, 3.0, {{0.0, 0.0, 0.0, 0.0}}, 0.0, nullptr, 0},
};

struct Instance {
    ani::ParamStore params{kParams, 1};
};

void *create(const ani_host *, ani_status *status) {
    Instance *self = nullptr;
    ani::guarded(status, [&] { self = new Instance(); });
    return self;
}

void destroy(void *instance) { delete static_cast<Instance *>(instance); }

const double kPi = 3.14159265358979323846;
const ani_vec3 kOffset{1.0, 0.5, 0.0};
const ani_quat kRelative{std::cos(kPi / 12.0), std::sin(kPi / 12.0), 0.0, 0.0};

// The start the host must give model 1 at t: its carrier's keys (turning about y only, in the
// test's document) put it at c + Ry offset, moving at v + w x (Ry offset).
std::string check_start(const ani_physics_scene &scene, double t) {
    ani_model_state carrier{};
    ani_vec3 v{};
    if (scene.evaluate_keyed(scene.host_context, 0, t, &carrier, &v) != ANI_OK)
        return "cannot evaluate model 0's keys";
    const ani_physics_model &m = scene.models[1];
    if (m.start.motion != ANI_MOTION_FREE) return "model 1 does not start free";
    if (!ANI_PHYSICS_MODEL_HAS_TURNING(&m) || m.start_turning != 1)
        return "model 1 does not start turning";
    const double a = carrier.angles.y * kPi / 180.0, w = kPi / 4.0; // the test's keys: 45 deg/s
    const double arm[3] = {std::cos(a) * kOffset.x + std::sin(a) * kOffset.z, kOffset.y,
                           -std::sin(a) * kOffset.x + std::cos(a) * kOffset.z};
    const double center[3] = {carrier.center.x + arm[0], carrier.center.y + arm[1],
                              carrier.center.z + arm[2]};
    // w = (0, w, 0): w x arm = (w arm_z, 0, -w arm_x).
    const double velocity[3] = {v.x + w * arm[2], v.y, v.z - w * arm[0]};
    const double got_c[3] = {m.start.center.x, m.start.center.y, m.start.center.z};
    const double got_v[3] = {m.start.velocity.x, m.start.velocity.y, m.start.velocity.z};
    for (int k = 0; k < 3; ++k) {
        if (std::abs(got_c[k] - center[k]) > 1e-12) return "model 1 does not start where carried";
        if (std::abs(got_v[k] - velocity[k]) > 1e-12) return "model 1 does not start at its carrier's velocity";
    }
    if (std::abs(m.start_angular_velocity.y - w) > 1e-12) return "model 1 does not start turning with its carrier";
    return "";
}

ani_status_code bake(void *instance, const ani_physics_scene *scene, double t_begin, double t_end,
                     const ani_bake_sink *sink, ani_status *status) {
    return ani::guarded(status, [&] {
        const Instance &self = *static_cast<Instance *>(instance);
        if (scene->model_count < 2) throw ani::Failure(ANI_ERR_INVALID_ARGUMENT, "two models are needed");
        if (t_begin > 0.0) {
            const std::string wrong = check_start(*scene, t_begin);
            if (!wrong.empty()) throw ani::Failure(ANI_ERR_FAILED, wrong);
        }
        const int mode = static_cast<int>(self.params.number("mode"));
        for (uint32_t m = 0; m < scene->model_count; ++m) {
            ani_motion_segment s{};
            s.model = m;
            s.motion = m == 1 || mode == 2 ? ANI_MOTION_CARRIED : ANI_MOTION_KEYED;
            s.t0 = t_begin;
            s.t1 = t_end;
            sink->segment(sink->context, &s);
        }
        if (!sink->carried) return;
        ani_carried_segment c{};
        c.model = 1;
        c.carrier = mode == 1 ? 1 : mode == 3 ? scene->model_count : 0;
        c.t0 = t_begin;
        c.t1 = t_end;
        c.offset = kOffset;
        c.relative = kRelative;
        sink->carried(sink->context, &c);
        if (mode == 2) {
            c.model = 0;
            c.carrier = 1;
            sink->carried(sink->context, &c);
        }
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
    "Test: carried",
    {0, 1, 0},
    "Reports one model carried by another, for the host's tests.",
    kParams,
    1,
    &api,
};

const ani_plugin_descriptor *const kPlugins[] = {&descriptor};

} // namespace

ANI_PLUGIN_ENTRY(kPlugins)
