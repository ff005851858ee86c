#include "timeline/keyed_motion.hpp"

#include <algorithm>

namespace animator {

namespace {

constexpr const char *kKinematic = "interpolation.kinematic";

std::unique_ptr<PluginInstance> instance_of(PluginRegistry &plugins, const std::string &id) {
    const PluginInfo *info = plugins.find(id);
    if (!info || info->kind != ANI_KIND_INTERPOLATOR)
        throw PluginError("no interpolator plugin '" + id +
                          "' was found (is animator-interpolation.so beside the executable?)");
    return std::make_unique<PluginInstance>(*info, plugins.host());
}

ani_key key_of(double t, const glm::dvec3 &v, const glm::dvec3 &turn = glm::dvec3(0.0)) {
    ani_key k{};
    k.time = t;
    for (int i = 0; i < 3; ++i) {
        k.value[i] = v[i];
        k.turn[i] = turn[i];
    }
    return k;
}

double seconds(std::int64_t ms) { return static_cast<double>(ms) / 1000.0; }

} // namespace

Interpolators Interpolators::load(PluginRegistry &plugins, const Document &doc) {
    Interpolators out;
    out.chosen = instance_of(plugins, doc.settings().interpolation);
    // The document's saved parameters for its interpolator (e.g. smooth's tension).
    auto saved = doc.settings().params.find(doc.settings().interpolation);
    if (saved != doc.settings().params.end())
        for (const auto &[param, value] : saved->second) out.chosen->set_param(param, value);
    out.kinematic = instance_of(plugins, kKinematic);
    return out;
}

void KeyedMotion::finish(Channel &c, int kind, const PluginInstance *interpolator, const glm::dvec3 &initial_rate) {
    c.interpolator = interpolator;
    c.channel.struct_size = sizeof c.channel;
    c.channel.kind = kind;
    c.channel.keys = c.keys.data();
    c.channel.key_count = static_cast<uint32_t>(c.keys.size());
    for (int i = 0; i < 3; ++i) c.channel.initial_rate[i] = initial_rate[i];
}

KeyedMotion::KeyedMotion(const Document &doc, const Interpolators &interpolators) {
    const auto &models = doc.models();
    models_.resize(models.size());
    for (size_t m = 0; m < models.size(); ++m) {
        ModelChannels &ch = models_[m];
        for (const Keyframe *k : doc.keys_of(static_cast<int>(m))) {
            const ModelState &s = *k->states[m];
            const double t = seconds(k->time_ms);
            ch.center.keys.push_back(key_of(t, s.center));
            ch.angles.keys.push_back(key_of(t, s.angles, s.turn));
            ch.scale.keys.push_back(key_of(t, s.scale));
        }
        const Model &model = models[m];
        // Dynamics on: the center follows the kinematic equations, starting at the model's
        // initial velocity (seed, "Keyframe Interpolation with Kinematic Equations").
        finish(ch.center, ANI_CHANNEL_POSITION,
               model.dynamics ? interpolators.kinematic.get() : interpolators.chosen.get(),
               model.dynamics ? model.initial_velocity : glm::dvec3(0.0));
        finish(ch.angles, ANI_CHANNEL_ANGLES, interpolators.chosen.get(), glm::dvec3(0.0));
        finish(ch.scale, ANI_CHANNEL_SCALE, interpolators.chosen.get(), glm::dvec3(0.0));
    }
    for (const Keyframe *k : doc.keys_of(-1)) {
        const CameraState &c = *k->camera;
        const double t = seconds(k->time_ms);
        camera_position_.keys.push_back(key_of(t, c.position));
        ani_key r{};
        r.time = t;
        r.value[0] = c.rotation.w;
        r.value[1] = c.rotation.x;
        r.value[2] = c.rotation.y;
        r.value[3] = c.rotation.z;
        camera_rotation_.keys.push_back(r);
        fov_times_.push_back(t);
        fov_values_.push_back(c.fov_degrees);
    }
    finish(camera_position_, ANI_CHANNEL_CAMERA_POSITION, interpolators.chosen.get(), glm::dvec3(0.0));
    finish(camera_rotation_, ANI_CHANNEL_CAMERA_ROTATION, interpolators.chosen.get(), glm::dvec3(0.0));
}

void KeyedMotion::evaluate(const Channel &c, const std::vector<double> &times, std::vector<double> &values,
                           std::vector<double> &rates) {
    values.assign(times.size() * 4, 0.0);
    rates.assign(times.size() * 4, 0.0);
    const auto &api = c.interpolator->api<ani_interpolator_api>();
    ani_status status{};
    if (api.evaluate(c.interpolator->handle(), &c.channel, times.data(), static_cast<uint32_t>(times.size()),
                     values.data(), rates.data(), &status) != ANI_OK)
        throw PluginError("interpolator '" + c.interpolator->info().id + "': " + status.message);
}

std::vector<ModelPose> KeyedMotion::model(int m, const std::vector<double> &times) const {
    const ModelChannels &ch = models_[static_cast<size_t>(m)];
    std::vector<double> centers, velocities, angles, angle_rates, scales, scale_rates;
    evaluate(ch.center, times, centers, velocities);
    evaluate(ch.angles, times, angles, angle_rates);
    evaluate(ch.scale, times, scales, scale_rates);
    std::vector<ModelPose> out(times.size());
    for (size_t i = 0; i < times.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            out[i].center[c] = centers[4 * i + static_cast<size_t>(c)];
            out[i].velocity[c] = velocities[4 * i + static_cast<size_t>(c)];
            out[i].angles[c] = angles[4 * i + static_cast<size_t>(c)];
            // Outside its keys a model's angles are held: they do not turn, whatever rate the
            // interpolator continues with.
            const bool held = times[i] < ch.angles.keys.front().time || times[i] > ch.angles.keys.back().time;
            out[i].angle_rates[c] = held ? 0.0 : angle_rates[4 * i + static_cast<size_t>(c)];
            out[i].scale[c] = scales[4 * i + static_cast<size_t>(c)];
        }
    return out;
}

void keyed_turning(const ModelPose &pose, glm::dquat &q, glm::dvec3 &w) {
    const glm::dvec3 kX{1.0, 0.0, 0.0}, kY{0.0, 1.0, 0.0}, kZ{0.0, 0.0, 1.0};
    const glm::dvec3 a = glm::radians(pose.angles), rate = glm::radians(pose.angle_rates);
    const glm::dquat A = glm::angleAxis(a.x, kX), B = glm::angleAxis(a.y, kY), C = glm::angleAxis(a.z, kZ);
    q = A * B * C;
    w = rate.x * kX + A * (rate.y * kY) + (A * B) * (rate.z * kZ);
}

ModelPose KeyedMotion::model(int m, double t) const { return model(m, std::vector<double>{t}).front(); }

CameraState KeyedMotion::camera(double t) const {
    std::vector<double> position, position_rate, rotation, rotation_rate;
    evaluate(camera_position_, {t}, position, position_rate);
    evaluate(camera_rotation_, {t}, rotation, rotation_rate);
    CameraState c;
    c.position = {position[0], position[1], position[2]};
    c.rotation = glm::normalize(glm::dquat(rotation[0], rotation[1], rotation[2], rotation[3]));
    // The field of view: linear between the camera's keys, held outside them.
    auto next = std::upper_bound(fov_times_.begin(), fov_times_.end(), t);
    if (next == fov_times_.begin()) {
        c.fov_degrees = fov_values_.front();
    } else if (next == fov_times_.end()) {
        c.fov_degrees = fov_values_.back();
    } else {
        const size_t i = static_cast<size_t>(next - fov_times_.begin());
        const double s = (t - fov_times_[i - 1]) / (fov_times_[i] - fov_times_[i - 1]);
        c.fov_degrees = fov_values_[i - 1] + s * (fov_values_[i] - fov_values_[i - 1]);
    }
    return c;
}

ani_time_span KeyedMotion::keyed_span(int m) const {
    const auto &keys = models_[static_cast<size_t>(m)].center.keys;
    return ani_time_span{keys.front().time, keys.back().time};
}

} // namespace animator
