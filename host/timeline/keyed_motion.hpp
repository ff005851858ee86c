// Keyed motion: every model's and the camera's state between their own keys, from interpolator
// plugins (seed, "Linear Interpolation between Keyframes" and "Keyframe Interpolation with
// Kinematic Equations"). Rotation and scale always come from here (the seed has no torque);
// the center comes from here only over a model's keyed span, and from the physics bake after.
#pragma once

#include "document/document.hpp"
#include "plugin/instance.hpp"

#include <animator/interpolator.h>
#include <animator/physics.h>

#include <glm/gtc/quaternion.hpp>

#include <memory>
#include <vector>

namespace animator {

struct ModelPose {
    glm::dvec3 center{0.0};
    glm::dvec3 angles{0.0}; // degrees in [0, 360)
    glm::dvec3 scale{1.0};
    glm::dvec3 velocity{0.0}; // of the center, m/s
    glm::dvec3 angle_rates{0.0}; // of the keyed angles, degrees per second (the interpolator's; 0 outside the keys)
};

// The rotation R = Rx(a) Ry(b) Rz(c) of a pose's angles (in its parent's frame) and its angular
// velocity there, exact from the angle rates: from R' R^T = [w]x for a product A B C,
// w = a' e_x + A (b' e_y) + A B (c' e_z).
void keyed_turning(const ModelPose &pose, glm::dquat &q, glm::dvec3 &w);

// The interpolator instances a document needs: its choice (the seed's linear by default) for
// everything but the center of a model with Dynamics on, which is kinematic.
struct Interpolators {
    std::unique_ptr<PluginInstance> chosen;    // the document's choice, for keyed motion
    std::unique_ptr<PluginInstance> kinematic; // the center of a model with Dynamics on

    // Throws PluginError naming a missing plugin.
    static Interpolators load(PluginRegistry &plugins, const Document &doc);
};

class KeyedMotion {
  public:
    // Builds the channels of every model and of the camera; `interpolators` must outlive this.
    KeyedMotion(const Document &doc, const Interpolators &interpolators);

    // The keyed pose of model `m` at t seconds. Before its first key and after its last, the
    // nearest key's values; velocity after the last key is the velocity it left its keys with.
    ModelPose model(int m, double t) const;
    // Many sorted times at once (one sweep per channel).
    std::vector<ModelPose> model(int m, const std::vector<double> &times) const;
    CameraState camera(double t) const;

    // [first key, last key] of model m, in seconds.
    ani_time_span keyed_span(int m) const;
    std::size_t model_count() const { return models_.size(); }

    // (The channels point into keys_.)
    KeyedMotion(const KeyedMotion &) = delete;
    KeyedMotion &operator=(const KeyedMotion &) = delete;

  private:
    struct Channel {
        const PluginInstance *interpolator = nullptr;
        ani_channel channel{}; // its keys in keys_
        const ani_key &first() const { return channel.keys[0]; }
        const ani_key &last() const { return channel.keys[channel.key_count - 1]; }
    };
    struct ModelChannels {
        Channel center, angles, scale;
    };
    // Appends a channel's keys to keys_ (`keys` appends them, in time order) and sets the
    // channel but for where its keys are (at `from`, pointed at once keys_ is whole).
    template <class Keys>
    void add(Channel &c, int kind, const PluginInstance *interpolator,
             const glm::dvec3 &initial_rate, std::size_t &from, const Keys &keys);
    // The channel at n times: 4 values and 4 rates per time.
    static void evaluate(const Channel &c, const double *times, std::size_t n, double *values, double *rates);
    // The pose from the channels' values at one time (4 numbers each).
    static ModelPose pose_of(const ModelChannels &ch, double t, const double *centers, const double *velocities,
                             const double *angles, const double *angle_rates, const double *scales);

    // Every channel's keys, model after model (its center's, angles' and scale's), then the
    // camera's: one array read in order (a vector per channel was three allocations a model, and
    // the keyed starts of a bake of 100,000 models read them from all over the heap).
    std::vector<ani_key> keys_;
    std::vector<ModelChannels> models_;
    Channel camera_position_, camera_rotation_;
    std::vector<double> fov_times_, fov_values_; // the camera's field of view, linear between keys
};

} // namespace animator
