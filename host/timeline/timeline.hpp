// The timeline: the state of every model and of the camera at any time t, the same whichever
// way the user reached t. Keyed spans come from the interpolators (keyed_motion.hpp); free spans
// from the physics backend's bake, cached as closed-form segments (never one sample per frame),
// so scrubbing back is a look-up and an edit re-bakes only from the earliest time it can change.
#pragma once

#include "assets/mesh.hpp"
#include "document/document_view.hpp"
#include "timeline/keyed_motion.hpp"
#include "timeline/segment_store.hpp"

#include <animator/free_rotation.hpp>
#include <animator/huge_pages.hpp>
#include <animator/pendulum.hpp>

#include <glm/gtc/quaternion.hpp>

#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>

namespace animator {

struct BakeCancelled : std::runtime_error {
    BakeCancelled() : std::runtime_error("the bake was cancelled") {}
};

struct Frame {
    std::vector<ModelPose> models;
    std::vector<int> motion; // ani_motion_kind of each model at that time
    CameraState camera;
};

// What the bakes did, counted (not timed), for `animator bake --stats` and for tests.
struct BakeStats {
    std::size_t bake_calls = 0;
    double seconds_baked = 0.0; // simulated time covered by all bake calls
    std::map<std::string, double> backend_counts; // the backend's own counts, summed by name
};

// A backend's rotation segment: at constant angular velocity (ani_rotation_segment: q0 followed
// by a turn of |w| (t - t0) about w), or, when `free` is set (ABI 1.4, ani_free_rotation_segment),
// torque-free: the principal frame turns as `free` says and the model is it times
// conjugate(principal). q0 and w are the model's orientation and angular velocity at t0 either way.
struct RotationSegment : ani_rotation_segment {
    std::shared_ptr<const ani::FreeRotation> free;
    glm::dquat principal{1.0, 0.0, 0.0, 0.0};
    // The point the model turns about, in its own frame as scaled (0: its origin): the motion
    // segments then give where this point is, not the origin (ani_free_rotation_segment).
    glm::dvec3 pivot{0.0};
    // A spin-up segment's angular acceleration (ani_spin_up_segment; `w` is then w0).
    glm::dvec3 alpha{0.0};
    // A hinge segment's pendulum and the line's direction (ani_hinge_segment: the model turns
    // by psi(t) - psi(t0) about `axis` after q0, about `pivot`).
    std::shared_ptr<const ani::Pendulum> hinge;
    glm::dvec3 axis{0.0};
    // The numbers `free` and `hinge` are made from (free_rotation_of, hinge_of), kept so that a
    // bake read from a file (timeline/bake_file.hpp) makes them again, the same to the bit.
    glm::dvec3 moments{0.0};                        // free: the principal moments, ascending
    double omega2 = 0.0, angle0 = 0.0, rate0 = 0.0; // hinge: the pendulum's w^2, angle and rate at t0
};

// A free segment's closed form from its t0, q0, w (w0), principal and moments; a hinge
// segment's from its t0, omega2, angle0 and rate0. The numbers must pass
// ani::FreeRotation::refusal or ani::Pendulum::refusal.
std::shared_ptr<const ani::FreeRotation> free_rotation_of(const RotationSegment &s);
std::shared_ptr<const ani::Pendulum> hinge_of(const RotationSegment &s);

// The collisions of a bake in time order: several megabytes at 100,000 balls, in 2 MB pages once
// large (animator/huge_pages.hpp), so that growing them does not fault 4 KB pages one by one.
using EventList = ani::HugeVector<ani_collision_event>;

// What a bake made: every model's motion and rotation segments, the collisions and overlaps,
// and how far it reaches. A timeline gives it (to save it) and takes one made elsewhere
// (timeline/bake_file.hpp).
struct BakedState {
    double until = 0.0;
    std::vector<std::vector<ani_motion_segment>> segments; // per model, in time order
    std::vector<std::vector<RotationSegment>> rotations;   // per model, in time order
    std::vector<std::vector<ani_carried_segment>> carried; // per model, in time order
    EventList events;
    std::vector<ani_overlap> overlaps;
};

// The world orientation and angular velocity (rad/s, world axes) of a rotation segment at t.
glm::dquat orientation_at(const RotationSegment &s, double t);
glm::dvec3 angular_velocity_at(const RotationSegment &s, double t);

// Where a model without a parent is at one time, and how it moves: its origin and that point's
// velocity, its world orientation (unit, without its scale) and angular velocity (rad/s, world
// axes).
struct Placement {
    glm::dvec3 center{0.0}, velocity{0.0};
    glm::dquat q{1.0, 0.0, 0.0, 0.0};
    glm::dvec3 w{0.0};
};

// Euler angles in degrees in [0, 360) (the documents' X-Y-Z convention) of an orientation.
glm::dvec3 angles_of(const glm::dquat &q);

class Timeline {
  public:
    // `backend` overrides the document's physics backend when not empty. Throws PluginError for
    // a missing interpolator or backend.
    Timeline(const Document &doc, PluginRegistry &plugins, const std::string &backend = "");
    // Not copied or moved: view_ points into doc_ (its strings, some held in place).
    Timeline(const Timeline &) = delete;
    Timeline &operator=(const Timeline &) = delete;

    // Bakes [baked_until(), until] seconds. `progress` gets [0, 1] and returns false to cancel
    // (throws BakeCancelled; what was baked before stays). Throws PluginError if the backend
    // fails.
    void bake(double until, const std::function<bool(double)> &progress = {});
    double baked_until() const { return baked_until_; }
    // The bake so far, and a bake to use in place of baking (of this document, backend and
    // meshes: timeline/bake_file.hpp checks that). restore() throws std::invalid_argument,
    // changing nothing, when the state has not one list of each per model.
    BakedState baked_state() const;
    void restore(BakedState state);

    // Every model and the camera at t seconds, within what is baked.
    Frame evaluate(double t) const;

    // The meshes of the models (one per model, null for an empty), for collisions. Without them
    // the backend computes motion without contacts. Invalidates the bake.
    void set_meshes(const std::vector<std::shared_ptr<const Mesh>> &meshes);

    // Takes an edited document: the bake is kept up to the earliest time the edit can change
    // and redone from there to where it was.
    void set_document(const Document &doc, const std::function<bool(double)> &progress = {});
    // The same without baking again: what is baked stays up to the earliest time the edit can
    // change, and the next bake() goes on from there (the editor bakes in slices between
    // frames, so an edit never freezes it). Throws PluginError, changing nothing, when a newly
    // chosen plugin is missing.
    void edit(const Document &doc);

    // Swaps the physics backend while the program runs: the new one is created first (a
    // PluginError leaves the previous one in place), then the bake is redone with it up to
    // where it was. The document is not changed; `id` overrides its choice from now on, and ""
    // goes back to it.
    void set_backend(const std::string &id, const std::function<bool(double)> &progress = {});
    // The same without baking again: the next bake() starts over from 0 with the new backend.
    void use_backend(const std::string &id);
    const std::string &backend_override() const { return backend_override_; }
    const Document &document() const { return doc_; }

    // The earliest time (seconds) at which `after` can move differently from `before`; infinity
    // when the edit changes no motion (a colour, the camera).
    static double affected_from(const Document &before, const Document &after);

    // A model's motion segments in time order (valid until the next bake or edit), and the one
    // that holds t (the last starting at or before t; the first before them all), or null.
    SegmentSpan segments(int model) const { return segments_[static_cast<size_t>(model)]; }
    const ani_motion_segment *segment_at(int model, double t) const;
    const EventList &events() const { return events_; }
    // The backend's rotation segments of a model (only for a backend that turns models).
    const std::vector<RotationSegment> &rotations(int model) const { return rotations_[static_cast<size_t>(model)]; }
    // The pairs of models the backend found overlapping (each once, when found), in the order found.
    const std::vector<ani_overlap> &overlaps() const { return overlaps_; }
    const BakeStats &stats() const { return stats_; }
    const std::string &backend_id() const { return physics_->info().id; }
    // The backend's parameters as its instance has them (the document's or its defaults), in
    // the order the plugin declares them.
    std::vector<std::pair<std::string, ParamValue>> backend_params() const;
    // The mesh the backend collides model `model` with (after its rest shape), or null.
    const ani_mesh_view *mesh_view(int model) const;
    const KeyedMotion &keyed() const { return *keyed_; }
    // The backend's rotation segment that turns the model at t, if one does.
    const RotationSegment *rotation_at(int model, double t) const;
    // The backend's carried segments of a model (ABI 1.8), and the one that carries it at t.
    const std::vector<ani_carried_segment> &carried(int model) const { return carried_[static_cast<size_t>(model)]; }
    const ani_carried_segment *carried_at(int model, double t) const;
    // Model `model` (without a parent) at t, within what is baked: from its keys, the backend's
    // segments, or its carrier's placement where it is carried.
    Placement placement(int model, double t) const;

  private:
    void truncate(double from);
    // The state the backend starts model `model` in at t; `keyed_pose`, when given, gets its
    // keyed pose when the state comes from its keys.
    ani_body_state state_at(int model, double t, std::optional<ModelPose> *keyed_pose = nullptr) const;
    // Where the model's origin is and how fast it moves at t from its free motion segment s: a
    // model turned about a pivot has the pivot's motion in s.
    void origin_at(int model, const ani_motion_segment &s, double t, glm::dvec3 &center,
                   glm::dvec3 &velocity) const;
    Placement placement(int model, double t, std::size_t depth) const;
    // Empty, or why the carried segments reported since `from` cannot be evaluated.
    std::string carried_refusal(double from) const;
    void run_bake(double from, double until, const std::function<bool(double)> &progress);
    // Makes view_ and groups_ of doc_ (when it is set).
    void describe_document();

    Document doc_;
    PluginRegistry &plugins_;
    Interpolators interpolators_;
    std::unique_ptr<KeyedMotion> keyed_;
    // Made with doc_ (edit()), for every bake of it: the editor bakes a document in slices, and
    // at 100,000 balls remaking the view and walking the models for their roots took a twentieth
    // of a bake.
    std::unique_ptr<DocumentView> view_;  // doc_ as the plugins read it
    std::vector<uint32_t> groups_;         // each model's root (itself unless jointed)
    std::string backend_override_; // a backend chosen over the document's, or ""
    std::unique_ptr<PluginInstance> physics_;
    struct MeshView {
        std::shared_ptr<const Mesh> mesh;
        std::vector<double> positions;
        ani_mesh_view view{};
    };
    std::vector<std::shared_ptr<const MeshView>> meshes_; // per model (shared by models with one mesh), null without
    SegmentStore segments_;
    EventList events_;
    std::vector<std::vector<RotationSegment>> rotations_; // per model, in time order
    std::vector<std::vector<ani_carried_segment>> carried_; // per model, in time order
    std::vector<ani_overlap> overlaps_;
    double baked_until_ = 0.0;
    bool baked_any_ = false;
    BakeStats stats_;
};

} // namespace animator
