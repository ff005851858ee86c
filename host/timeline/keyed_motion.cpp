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

template <class Keys>
void KeyedMotion::add(Channel &c, int kind, const PluginInstance *interpolator,
                      const glm::dvec3 &initial_rate, std::size_t &from, const Keys &keys) {
    from = keys_.size();
    keys(keys_);
    c.interpolator = interpolator;
    c.channel.struct_size = sizeof c.channel;
    c.channel.kind = kind;
    c.channel.key_count = static_cast<uint32_t>(keys_.size() - from);
    for (int i = 0; i < 3; ++i) c.channel.initial_rate[i] = initial_rate[i];
}

KeyedMotion::KeyedMotion(const Document &doc, const Interpolators &interpolators) {
    const auto &models = doc.models();
    const auto &keyframes = doc.keyframes();
    std::size_t keyed = 0, camera_keys = 0;
    for (const Keyframe &k : keyframes) {
        camera_keys += k.camera.has_value();
        for (const auto &state : k.states) keyed += state.has_value();
    }
    keys_.reserve(3 * keyed + 2 * camera_keys);
    models_.resize(models.size());
    std::vector<std::size_t> from(3 * models.size() + 2); // each channel's first key in keys_
    for (size_t m = 0; m < models.size(); ++m) {
        ModelChannels &ch = models_[m];
        // The model's keys of one channel, in time order.
        const auto each = [&](auto &&key_of_state) {
            return [&, key_of_state](std::vector<ani_key> &out) {
                for (const Keyframe &k : keyframes)
                    if (const auto &s = k.states[m])
                        out.push_back(key_of_state(seconds(k.time_ms), *s));
            };
        };
        const Model &model = models[m];
        // Dynamics on: the center follows the kinematic equations, starting at the model's
        // initial velocity (seed, "Keyframe Interpolation with Kinematic Equations").
        add(ch.center, ANI_CHANNEL_POSITION,
            model.dynamics ? interpolators.kinematic.get() : interpolators.chosen.get(),
            model.dynamics ? model.initial_velocity : glm::dvec3(0.0), from[3 * m],
            each([](double t, const ModelState &s) { return key_of(t, s.center); }));
        add(ch.angles, ANI_CHANNEL_ANGLES, interpolators.chosen.get(), glm::dvec3(0.0),
            from[3 * m + 1],
            each([](double t, const ModelState &s) { return key_of(t, s.angles, s.turn); }));
        add(ch.scale, ANI_CHANNEL_SCALE, interpolators.chosen.get(), glm::dvec3(0.0),
            from[3 * m + 2],
            each([](double t, const ModelState &s) { return key_of(t, s.scale); }));
    }
    const std::size_t camera = 3 * models.size();
    add(camera_position_, ANI_CHANNEL_CAMERA_POSITION, interpolators.chosen.get(), glm::dvec3(0.0),
        from[camera], [&](std::vector<ani_key> &out) {
            for (const Keyframe &k : keyframes)
                if (k.camera) out.push_back(key_of(seconds(k.time_ms), k.camera->position));
        });
    add(camera_rotation_, ANI_CHANNEL_CAMERA_ROTATION, interpolators.chosen.get(), glm::dvec3(0.0),
        from[camera + 1], [&](std::vector<ani_key> &out) {
            for (const Keyframe &k : keyframes) {
                if (!k.camera) continue;
                const CameraState &c = *k.camera;
                ani_key r{};
                r.time = seconds(k.time_ms);
                r.value[0] = c.rotation.w;
                r.value[1] = c.rotation.x;
                r.value[2] = c.rotation.y;
                r.value[3] = c.rotation.z;
                out.push_back(r);
                fov_times_.push_back(r.time);
                fov_values_.push_back(c.fov_degrees);
            }
        });
    // keys_ is whole: the channels are pointed at their keys.
    for (size_t m = 0; m < models.size(); ++m) {
        models_[m].center.channel.keys = keys_.data() + from[3 * m];
        models_[m].angles.channel.keys = keys_.data() + from[3 * m + 1];
        models_[m].scale.channel.keys = keys_.data() + from[3 * m + 2];
    }
    camera_position_.channel.keys = keys_.data() + from[camera];
    camera_rotation_.channel.keys = keys_.data() + from[camera + 1];
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
    const bool held = t < ch.angles.first().time || t > ch.angles.last().time;
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
    const Channel &center = models_[static_cast<size_t>(m)].center;
    return ani_time_span{center.first().time, center.last().time};
}

} // namespace animator
