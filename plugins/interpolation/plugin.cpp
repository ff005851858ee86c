// The animator-interpolation library: its three interpolator plugins (descriptors, instances,
// evaluate) and the entry. The maths lives in linear, kinematic, smooth, angles and rotation.
#include "channel_check.hpp"
#include "kinematic.hpp"
#include "linear.hpp"
#include "smooth.hpp"

#include <animator/interpolator.h>
#include <animator/plugin_cpp.hpp>

namespace {

constexpr uint32_t bit(ani_channel_kind kind) { return 1u << kind; }

constexpr uint32_t kEveryChannel = bit(ANI_CHANNEL_POSITION) | bit(ANI_CHANNEL_ANGLES) |
                                   bit(ANI_CHANNEL_SCALE) | bit(ANI_CHANNEL_CAMERA_POSITION) |
                                   bit(ANI_CHANNEL_CAMERA_ROTATION);

const char *const kLinearId = "interpolation.linear";
const char *const kKinematicId = "interpolation.kinematic";
const char *const kSmoothId = "interpolation.smooth";

// ---- instances: only parameters, read-only during evaluate (which may run concurrently) ----

struct Instance {
    explicit Instance(const ani_plugin_descriptor &d) : params(d.params, d.param_count) {}
    ani::ParamStore params;
};

void *create_instance(const ani_plugin_descriptor &descriptor, ani_status *status) {
    Instance *self = nullptr;
    ani::guarded(status, [&] { self = new Instance(descriptor); });
    return self;
}

void destroy_instance(void *instance) { delete static_cast<Instance *>(instance); }

// Checks everything, evaluates the plugin's curve for the channel (one sweep of the times), and
// refuses to hand back anything that is not finite.
template <class Evaluate>
ani_status_code evaluate_with(const char *plugin_id, uint32_t mask, bool uses_initial_rate,
                              void *instance, const ani_channel *channel, const double *times,
                              uint32_t count, double *values, double *rates, ani_status *status,
                              Evaluate evaluate) {
    return ani::guarded(status, [&] {
        if (instance == nullptr)
            throw ani::Failure(ANI_ERR_INVALID_ARGUMENT, std::string(plugin_id) + ": the instance is null");
        interp::check_channel(plugin_id, channel, mask, uses_initial_rate);
        interp::check_times(plugin_id, times, count, values, rates);
        evaluate(*static_cast<const Instance *>(instance), *channel, times, count, values, rates);
        interp::check_outputs(plugin_id, values, rates, count);
    });
}

// ---- interpolation.linear -------------------------------------------------------------------

extern const ani_plugin_descriptor linear_descriptor;

void *linear_create(const ani_host *, ani_status *status) { return create_instance(linear_descriptor, status); }

ani_status_code linear_evaluate(void *instance, const ani_channel *channel, const double *times,
                                uint32_t count, double *values, double *rates, ani_status *status) {
    return evaluate_with(kLinearId, kEveryChannel, false, instance, channel, times, count, values,
                         rates, status, [](const Instance &, const ani_channel &c, auto... out) {
                             interp::evaluate_linear(c, out...);
                         });
}

const ani_interpolator_api linear_api = {
    sizeof(ani_interpolator_api),
    {sizeof(ani_instance_api), linear_create, destroy_instance, ani::store_get_param<Instance>, ani::store_set_param<Instance>},
    kEveryChannel,
    linear_evaluate,
};

const ani_plugin_descriptor linear_descriptor = {
    sizeof(ani_plugin_descriptor),
    kLinearId,
    ANI_KIND_INTERPOLATOR,
    "Linear",
    {1, 0, 0},
    "Straight lines between keyframes at a steady speed. Angles turn the way the user turned "
    "them (or the shorter way); the camera's rotation turns at a steady rate about one axis "
    "(slerp).",
    nullptr,
    0,
    &linear_api,
};

// ---- interpolation.kinematic ----------------------------------------------------------------

extern const ani_plugin_descriptor kinematic_descriptor;

void *kinematic_create(const ani_host *, ani_status *status) {
    return create_instance(kinematic_descriptor, status);
}

ani_status_code kinematic_evaluate(void *instance, const ani_channel *channel, const double *times,
                                   uint32_t count, double *values, double *rates, ani_status *status) {
    return evaluate_with(kKinematicId, bit(ANI_CHANNEL_POSITION), true, instance, channel, times,
                         count, values, rates, status, [](const Instance &, const ani_channel &c, auto... out) {
                             interp::evaluate_kinematic(c, out...);
                         });
}

const ani_interpolator_api kinematic_api = {
    sizeof(ani_interpolator_api),
    {sizeof(ani_instance_api), kinematic_create, destroy_instance, ani::store_get_param<Instance>, ani::store_set_param<Instance>},
    bit(ANI_CHANNEL_POSITION),
    kinematic_evaluate,
};

const ani_plugin_descriptor kinematic_descriptor = {
    sizeof(ani_plugin_descriptor),
    kKinematicId,
    ANI_KIND_INTERPOLATOR,
    "Kinematic",
    {1, 0, 0},
    "A model's center moves with constant acceleration from key to key, starting with the "
    "model's initial velocity, so velocity is continuous and every key is reached on time.",
    nullptr,
    0,
    &kinematic_api,
};

// ---- interpolation.smooth -------------------------------------------------------------------

const ani_param_descriptor smooth_params[] = {
    {sizeof(ani_param_descriptor), "tension", "Tension",
     "How tight the curve is at its keys: 0 is Catmull-Rom, 1 makes every tangent flat.",
     ANI_PARAM_FLOAT, 0.0, 1.0, {{0.0, 0.0, 0.0, 0.0}}, 0.05, nullptr, 0},
    {sizeof(ani_param_descriptor), "ease", "Ease in and out",
     "On: the motion slows to a stop at every key (every tangent is 0).", ANI_PARAM_BOOL, 0.0,
     1.0, {{0.0, 0.0, 0.0, 0.0}}, 0.0, nullptr, 0},
};

extern const ani_plugin_descriptor smooth_descriptor;

void *smooth_create(const ani_host *, ani_status *status) { return create_instance(smooth_descriptor, status); }

ani_status_code smooth_evaluate(void *instance, const ani_channel *channel, const double *times,
                                uint32_t count, double *values, double *rates, ani_status *status) {
    return evaluate_with(kSmoothId, kEveryChannel, false, instance, channel, times, count, values,
                         rates, status, [](const Instance &self, const ani_channel &c, auto... out) {
                             interp::SmoothSettings settings;
                             settings.tension = self.params.number("tension");
                             settings.ease = self.params.number("ease") >= 0.5;
                             const auto curve = interp::make_smooth_curve(c, settings);
                             interp::evaluate_curve(*curve, c.keys, c.key_count, out...);
                         });
}

const ani_interpolator_api smooth_api = {
    sizeof(ani_interpolator_api),
    {sizeof(ani_instance_api), smooth_create, destroy_instance, ani::store_get_param<Instance>, ani::store_set_param<Instance>},
    kEveryChannel,
    smooth_evaluate,
};

const ani_plugin_descriptor smooth_descriptor = {
    sizeof(ani_plugin_descriptor),
    kSmoothId,
    ANI_KIND_INTERPOLATOR,
    "Smooth",
    {1, 0, 0},
    "Smooth curves through the keyframes (cubic Hermite with Catmull-Rom tangents), with a "
    "tension and an ease in and out at every key.",
    smooth_params,
    sizeof(smooth_params) / sizeof(smooth_params[0]),
    &smooth_api,
};

// ---- the entry ------------------------------------------------------------------------------

const ani_plugin_descriptor *const kPlugins[] = {&linear_descriptor, &kinematic_descriptor,
                                                  &smooth_descriptor};

} // namespace

ANI_PLUGIN_ENTRY(kPlugins)
