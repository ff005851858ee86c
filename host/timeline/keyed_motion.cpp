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

void KeyedMotion::evaluate(const Channel &c, const double *times, std::size_t n, double *values, double *rates) {
    std::fill(values, values + 4 * n, 0.0);
    std::fill(rates, rates + 4 * n, 0.0);
    const auto &api = c.interpolator->api<ani_interpolator_api>();
    // Not zeroed whole: its 1 KB message, cleared at every call, was a sixth of the keyed starts
    // of a bake of 100,000 balls (the plugin writes the status; an empty message if it does not).
    ani_status status;
    status.code = ANI_OK;
    status.message[0] = '\0';
    if (api.evaluate(c.interpolator->handle(), &c.channel, times, static_cast<uint32_t>(n), values, rates,
                     &status) != ANI_OK)
        throw PluginError("interpolator '" + c.interpolator->info().id + "': " + status.message);
}

ModelPose KeyedMotion::pose_of(const ModelChannels &ch, double t, const double *centers, const double *velocities,
                               const double *angles, const double *angle_rates, const double *scales) {
    ModelPose out;
    // Outside its keys a model's angles are held: they do not turn, whatever rate the
    // interpolator continues with.
    const bool held = t < ch.angles.keys.front().time || t > ch.angles.keys.back().time;
    for (int c = 0; c < 3; ++c) {
        out.center[c] = centers[c];
        out.velocity[c] = velocities[c];
        out.angles[c] = angles[c];
        out.angle_rates[c] = held ? 0.0 : angle_rates[c];
        out.scale[c] = scales[c];
    }
    return out;
}

std::vector<ModelPose> KeyedMotion::model(int m, const std::vector<double> &times) const {
    const ModelChannels &ch = models_[static_cast<size_t>(m)];
    const std::size_t n = times.size();
    std::vector<double> centers(4 * n), velocities(4 * n), angles(4 * n), angle_rates(4 * n), scales(4 * n),
        scale_rates(4 * n);
    evaluate(ch.center, times.data(), n, centers.data(), velocities.data());
    evaluate(ch.angles, times.data(), n, angles.data(), angle_rates.data());
    evaluate(ch.scale, times.data(), n, scales.data(), scale_rates.data());
    std::vector<ModelPose> out(n);
    for (size_t i = 0; i < n; ++i)
        out[i] = pose_of(ch, times[i], &centers[4 * i], &velocities[4 * i], &angles[4 * i], &angle_rates[4 * i],
                         &scales[4 * i]);
    return out;
}

void keyed_turning(const ModelPose &pose, glm::dquat &q, glm::dvec3 &w) {
    const glm::dvec3 kX{1.0, 0.0, 0.0}, kY{0.0, 1.0, 0.0}, kZ{0.0, 0.0, 1.0};
    const glm::dvec3 a = glm::radians(pose.angles), rate = glm::radians(pose.angle_rates);
    const glm::dquat A = glm::angleAxis(a.x, kX), B = glm::angleAxis(a.y, kY), C = glm::angleAxis(a.z, kZ);
    q = A * B * C;
    w = rate.x * kX + A * (rate.y * kY) + (A * B) * (rate.z * kZ);
}

// One time, without allocating (the physics backends ask for every model's start).
ModelPose KeyedMotion::model(int m, double t) const {
    const ModelChannels &ch = models_[static_cast<size_t>(m)];
    double centers[4], velocities[4], angles[4], angle_rates[4], scales[4], scale_rates[4];
    evaluate(ch.center, &t, 1, centers, velocities);
    evaluate(ch.angles, &t, 1, angles, angle_rates);
    evaluate(ch.scale, &t, 1, scales, scale_rates);
    return pose_of(ch, t, centers, velocities, angles, angle_rates, scales);
}

CameraState KeyedMotion::camera(double t) const {
    double position[4], position_rate[4], rotation[4], rotation_rate[4];
    evaluate(camera_position_, &t, 1, position, position_rate);
    evaluate(camera_rotation_, &t, 1, rotation, rotation_rate);
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
