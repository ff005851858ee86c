// The document model: the in-memory animation that every other stage reads and edits
// (seed, "The Animator Interface", "The Model Interface", "Linear Interpolation between
// Keyframes": models, per-keyframe NodeStates, keyframes, camera, animation settings).
//
// It knows no screen, no GL, no sound device and no plugin: it is plain data with invariants.
// Edits that a user makes go through edits.hpp so they can be undone.
#pragma once

#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace animator {

// A violated invariant of the document (a keyframe at a taken time, a duplicate model name...).
struct DocumentError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

enum class Axis { X = 0, Y = 1, Z = 2 };

struct Material {
    glm::dvec3 kd{0.7, 0.7, 0.7};
    glm::dvec3 ks{0.3, 0.3, 0.3};
    double shininess = 25.0;
    bool operator==(const Material &o) const {
        return kd == o.kd && ks == o.ks && shininess == o.shininess;
    }
};

// A joint's range (the CS488 puppet's gr.joint): the least and greatest of each of the model's
// own angles, in degrees read signed (-180, 180], X Y Z as in its state. The editor clamps a turn
// of the model to it; min == max holds that angle still.
struct JointRange {
    glm::dvec3 min{0.0}, max{0.0};
    bool operator==(const JointRange &o) const { return min == o.min && max == o.max; }
};

// What the seed's Model Interface holds for one model.
struct Model {
    std::string name;
    std::string mesh; // "" for an empty: a node of the scene tree without geometry
    int parent = -1;  // index of the parent model in the scene tree, -1 under the root
    Material material;
    std::string texture;
    double tint = 0.0;
    double reflectivity = 0.0;
    double transparency = 0.0;
    double refractive_index = 1.0;
    bool dynamics = false;
    bool gravity = false;
    double mass = 1.0;
    glm::dvec3 initial_velocity{0.0};
    // Rigid-body settings (issue 18; defaults: the seed's idealised world). A contact uses the
    // lower restitution and the higher friction of its two models.
    double restitution = 1.0;               // [0, 1]
    double friction = 0.0;                  // >= 0, Coulomb's mu
    bool rotates = false;                   // turned by its contacts, not only by its keys
    glm::dvec3 angular_velocity{0.0};       // at t = 0, rad/s about world axes
    std::string collision_sound;
    std::string moving_sound;
    // A fixed linear shape under the keyed T R S (docs/ani-format.md): the model's mesh is drawn
    // and collided with as world = parent's T R S ... this T R S * rest. It is the model's own:
    // children hang from T R S without it. A course scene's shear (a node scaled unevenly after
    // it was rotated) lives here; the identity otherwise.
    glm::dmat3 rest{1.0};
    std::optional<JointRange> joint; // a joint's range, from a course puppet's gr.joint

    bool operator==(const Model &o) const;
};

// One model's state at one keyframe (the seed's NodeState), in its parent's frame (the world
// for a model under the root). Its transform is T(center) Rx(angles.x) Ry(angles.y)
// Rz(angles.z) S(scale): rotations about the model's own axes, X first.
struct ModelState {
    glm::dvec3 center{0.0};
    glm::dvec3 angles{0.0}; // degrees in [0, 360) about the model's own axes
    glm::dvec3 scale{1.0};
    glm::dvec3 turn{0.0};   // rotation direction per axis: sign of the seed's `ccw`
    bool operator==(const ModelState &o) const {
        return center == o.center && angles == o.angles && scale == o.scale && turn == o.turn;
    }
};

// Identity rotation: at the origin looking down -Z with +Y up, as in CS488.
struct CameraState {
    glm::dvec3 position{0.0};
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
    double fov_degrees = 50.0;
    bool operator==(const CameraState &o) const {
        return position == o.position && rotation == o.rotation && fov_degrees == o.fov_degrees;
    }
};

// A keyframe keys some models and perhaps the camera, as in Blender or Maya: a model's motion
// is interpolated between its own keys, and it is free after its own last key (seed, "Motion
// after the Final Keyframe"). The keyframe at t = 0 keys every model and the camera: it is the
// initial placement.
struct Keyframe {
    std::int64_t time_ms = 0;
    std::vector<std::optional<ModelState>> states; // one slot per model, in model order
    std::optional<CameraState> camera;
    bool operator==(const Keyframe &o) const {
        return time_ms == o.time_ms && states == o.states && camera == o.camera;
    }
};

// A plugin parameter's saved value (the SDK's ani_param_value): settings.params[plugin][param].
using ParamValue = std::array<double, 4>;
using ParamValues = std::map<std::string, std::map<std::string, ParamValue>>;

// A point light of the scene (the CS488 ray tracer's gr.light): its light reaches a point at
// distance d as colour / (falloff[0] + falloff[1] d + falloff[2] d^2).
struct Light {
    std::string name;
    glm::dvec3 position{0.0};
    glm::dvec3 colour{1.0};
    glm::dvec3 falloff{1.0, 0.0, 0.0};
    bool operator==(const Light &o) const {
        return name == o.name && position == o.position && colour == o.colour && falloff == o.falloff;
    }
};

struct Settings {
    static constexpr std::int64_t kMinMaxTimeMs = 1000;      // 1 s
    static constexpr std::int64_t kMaxMaxTimeMs = 300000000; // 300000 s
    static constexpr std::int64_t kDefaultMaxTimeMs = 60000; // 60 s

    std::int64_t max_time_ms = kDefaultMaxTimeMs;
    double gravity = 9.81;
    Axis down_axis = Axis::Y;
    bool cel_shading = false;
    std::string skybox;
    std::string physics_backend = "physics.custom";
    // The interpolator of keyed motion (a Dynamics model's center always follows the seed's
    // kinematic equations): the seed's "interpolation.linear", or "interpolation.smooth".
    std::string interpolation = "interpolation.linear";
    ParamValues params;
    // The scene's lights; with none, the renderer's default light rides with the camera, at this
    // place in the camera's frame.
    static constexpr std::size_t kMaxLights = 8;
    inline static const glm::dvec3 kCameraLightOffset{-4.0, 6.0, 4.0};
    std::vector<Light> lights;
    glm::dvec3 ambient{0.2};
    // What `animator render` writes when not told (a course scene's gr.render): a file name for
    // a still ("" for none) and a size in pixels (0 for the command's default).
    std::string render_output;
    int render_width = 0, render_height = 0;

    bool operator==(const Settings &o) const {
        return max_time_ms == o.max_time_ms && gravity == o.gravity && down_axis == o.down_axis &&
               cel_shading == o.cel_shading && skybox == o.skybox &&
               physics_backend == o.physics_backend && interpolation == o.interpolation &&
               params == o.params && lights == o.lights && ambient == o.ambient &&
               render_output == o.render_output && render_width == o.render_width &&
               render_height == o.render_height;
    }
};

// Checks a model's properties; returns "" when valid, else what is wrong.
std::string check_model(const Model &model);
std::string check_state(const ModelState &state);
std::string check_camera(const CameraState &camera);
std::string check_settings(const Settings &settings);

// Wraps an angle in degrees into [0, 360), as the seed stores angles.
double wrap_degrees(double degrees);

class Document {
  public:
    // A new document: no models, the t = 0 keyframe, default settings.
    Document();

    const std::vector<Model> &models() const { return models_; }
    const std::vector<Keyframe> &keyframes() const { return keyframes_; }
    const Settings &settings() const { return settings_; }

    // Index of the model with this name, or -1.
    int find_model(const std::string &name) const;
    // Index of the keyframe at exactly this time, or -1.
    int find_keyframe(std::int64_t time_ms) const;
    const Keyframe &keyframe_at(std::int64_t time_ms) const;

    // Adds a model at the end, keyed with `state` at t = 0 (and not keyed at later keyframes).
    // Throws DocumentError for a duplicate or empty name, a bad parent, or invalid properties.
    void add_model(const Model &model, const ModelState &state);
    // Removes the last model (the undo of add_model).
    void remove_last_model();
    void set_model(int index, const Model &model);

    // Inserts a keyframe in time order, with a slot per model. Throws for a time that is taken,
    // negative or past max time, or for a t = 0 keyframe that does not key everything.
    void insert_keyframe(const Keyframe &keyframe);
    // Deletes the keyframe at time_ms and returns it. The t = 0 keyframe cannot be deleted.
    Keyframe delete_keyframe(std::int64_t time_ms);

    // Keys (or, with nullopt, unkeys) a model or the camera at a keyframe. At t = 0 everything
    // stays keyed.
    void set_state(std::int64_t keyframe_ms, int model, const std::optional<ModelState> &state);
    void set_camera(std::int64_t keyframe_ms, const std::optional<CameraState> &camera);

    // The keyframes that key model `model` (or, with -1, the camera), in time order.
    std::vector<const Keyframe *> keys_of(int model) const;

    // Replaces the settings. A shorter max time deletes the keyframes past it, which are
    // returned (the caller keeps them to undo).
    std::vector<Keyframe> set_settings(const Settings &settings);

    bool operator==(const Document &o) const {
        return models_ == o.models_ && keyframes_ == o.keyframes_ && settings_ == o.settings_;
    }

  private:
    Keyframe &mutable_keyframe(std::int64_t time_ms);

    std::vector<Model> models_;
    std::unordered_map<std::string, int> by_name_; // models_'s indices by name (a large scene)
    std::vector<Keyframe> keyframes_; // strictly increasing times; keyframes_[0].time_ms == 0
    Settings settings_;
};

} // namespace animator
