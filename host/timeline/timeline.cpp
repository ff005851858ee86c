#include "timeline/timeline.hpp"

#include <animator/halves.hpp>
#include <animator/huge_pages.hpp>

#include <glm/gtc/quaternion.hpp>
#include <glm/gtx/euler_angles.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>

namespace animator {

namespace {

std::unique_ptr<PluginInstance> physics_instance(PluginRegistry &plugins, const Document &doc,
                                                 const std::string &backend) {
    const std::string id = backend.empty() ? doc.settings().physics_backend : backend;
    const PluginInfo *info = plugins.find(id);
    if (!info || info->kind != ANI_KIND_PHYSICS) {
        std::string known;
        for (const PluginInfo *p : plugins.find_kind(ANI_KIND_PHYSICS)) known += (known.empty() ? "" : ", ") + p->id;
        throw PluginError("no physics backend '" + id + "' (found: " + (known.empty() ? "none" : known) + ")");
    }
    auto instance = std::make_unique<PluginInstance>(*info, plugins.host());
    // The document's saved parameters for this backend.
    auto saved = doc.settings().params.find(id);
    if (saved != doc.settings().params.end())
        for (const auto &[param, value] : saved->second) instance->set_param(param, value);
    return instance;
}

glm::dvec3 at(const ani_motion_segment &s, double t) {
    const double tau = t - s.t0;
    return glm::dvec3(s.p0.x, s.p0.y, s.p0.z) + glm::dvec3(s.v0.x, s.v0.y, s.v0.z) * tau +
           0.5 * glm::dvec3(s.a.x, s.a.y, s.a.z) * tau * tau;
}

glm::dvec3 velocity_at(const ani_motion_segment &s, double t) {
    const double tau = t - s.t0;
    return glm::dvec3(s.v0.x, s.v0.y, s.v0.z) + glm::dvec3(s.a.x, s.a.y, s.a.z) * tau;
}

// The physics-relevant part of a model: a change elsewhere (a colour) moves nothing.
bool same_physics(const Model &a, const Model &b) {
    return a.mesh == b.mesh && a.parent == b.parent && a.dynamics == b.dynamics && a.gravity == b.gravity &&
           a.mass == b.mass && a.initial_velocity == b.initial_velocity &&
           a.restitution == b.restitution && a.friction == b.friction && a.rotates == b.rotates &&
           a.angular_velocity == b.angular_velocity;
}

struct BakeContext {
    Timeline *timeline;
    SegmentStore *segments;
    EventList *events;
    const std::function<bool(double)> *progress;
    std::map<std::string, double> *counts;
    std::vector<std::vector<RotationSegment>> *rotations;
    std::vector<ani_overlap> *overlaps;
    std::vector<std::vector<ani_carried_segment>> *carried;
    const std::vector<Model> *models;
    std::string refused = {}; // a free-rotation segment the host cannot evaluate
    // Refuses the bake for model `model`'s segment of `kind` at t0 when `why` says something.
    bool refuse(uint32_t model, const char *kind, double t0, const std::string &why) {
        if (why.empty()) return false;
        refused = "model " + std::to_string(model) + "'s " + kind + " segment at t = " + std::to_string(t0) + " s: " + why;
        return true;
    }
};

// The context of a bake's questions about keyed poses: the poses already found at its start.
struct KeyedAnswers {
    const KeyedMotion *keyed;
    double from;
    ani::UnwrittenVector<std::optional<ModelPose>> at_from; // per model (each made in run_bake)
};

// What every kind of rotation segment gives: its model, its span and its orientation at t0.
template <class Segment> RotationSegment rotation_segment(const Segment &s) {
    RotationSegment r;
    r.model = s.model;
    r.t0 = s.t0;
    r.t1 = s.t1;
    r.q0 = s.q0;
    return r;
}

template <std::size_t N> bool all_finite(const double (&numbers)[N]) {
    return std::all_of(numbers, numbers + N, [](double x) { return std::isfinite(x); });
}

} // namespace

glm::dvec3 angles_of(const glm::dquat &q) {
    const glm::dmat4 m = glm::mat4_cast(q);
    double x = 0.0, y = 0.0, z = 0.0;
    glm::extractEulerAngleXYZ(m, x, y, z);
    glm::dvec3 degrees = glm::degrees(glm::dvec3(x, y, z));
    for (int i = 0; i < 3; ++i) {
        degrees[i] = std::fmod(degrees[i], 360.0);
        if (degrees[i] < 0.0) degrees[i] += 360.0;
    }
    return degrees;
}

glm::dquat orientation_at(const RotationSegment &s, double t) {
    if (s.free) {
        glm::dquat q;
        glm::dvec3 w;
        s.free->evaluate(t, q, w);
        return glm::normalize(q * glm::conjugate(s.principal));
    }
    const glm::dquat q0(s.q0.w, s.q0.x, s.q0.y, s.q0.z);
    if (s.hinge) return glm::normalize(glm::angleAxis(s.hinge->angle(t) - s.hinge->angle(s.t0), s.axis) * q0);
    const glm::dvec3 w(s.w.x, s.w.y, s.w.z);
    if (s.alpha != glm::dvec3(0.0)) return ani::spun_up(glm::normalize(q0), w, s.alpha, t - s.t0);
    const double speed = glm::length(w);
    const glm::dquat turn = speed > 0.0 ? glm::angleAxis(speed * (t - s.t0), w / speed) : glm::dquat(1.0, 0.0, 0.0, 0.0);
    return glm::normalize(turn * q0);
}

std::shared_ptr<const ani::FreeRotation> free_rotation_of(const RotationSegment &s) {
    const glm::dquat q0(s.q0.w, s.q0.x, s.q0.y, s.q0.z);
    return std::make_shared<const ani::FreeRotation>(s.moments, glm::normalize(q0) * s.principal,
                                                     glm::dvec3(s.w.x, s.w.y, s.w.z), s.t0);
}

std::shared_ptr<const ani::Pendulum> hinge_of(const RotationSegment &s) {
    return std::make_shared<const ani::Pendulum>(s.omega2, s.angle0, s.rate0, s.t0);
}

glm::dvec3 angular_velocity_at(const RotationSegment &s, double t) {
    if (s.free) {
        glm::dquat q;
        glm::dvec3 w;
        s.free->evaluate(t, q, w);
        return w;
    }
    if (s.hinge) {
        double angle, rate;
        s.hinge->evaluate(t, angle, rate);
        return rate * s.axis;
    }
    return glm::dvec3(s.w.x, s.w.y, s.w.z) + (t - s.t0) * s.alpha;
}

Timeline::Timeline(const Document &doc, PluginRegistry &plugins, const std::string &backend)
    : doc_(doc), plugins_(plugins), interpolators_(Interpolators::load(plugins, doc)),
      keyed_(std::make_unique<KeyedMotion>(doc_, interpolators_)), backend_override_(backend),
      physics_(physics_instance(plugins, doc_, backend)), segments_(doc_.models().size()),
      rotations_(doc_.models().size()), carried_(doc_.models().size()) {
    describe_document();
}

void Timeline::describe_document() {
    view_ = std::make_unique<DocumentView>(doc_);
    const auto &models = doc_.models();
    groups_.resize(models.size());
    for (size_t m = 0; m < models.size(); ++m) {
        int root = static_cast<int>(m);
        while (models[static_cast<size_t>(root)].parent >= 0) root = models[static_cast<size_t>(root)].parent;
        groups_[m] = static_cast<uint32_t>(root);
    }
}

const ani_motion_segment *Timeline::segment_at(int model, double t) const {
    const SegmentSpan list = segments_[static_cast<size_t>(model)];
    auto it = std::upper_bound(list.begin(), list.end(), t,
                               [](double time, const ani_motion_segment &s) { return time < s.t0; });
    if (it == list.begin()) return list.empty() ? nullptr : &list.front();
    return &*(it - 1);
}

const RotationSegment *Timeline::rotation_at(int model, double t) const {
    const auto &turns = rotations_[static_cast<size_t>(model)];
    const auto r = std::upper_bound(turns.begin(), turns.end(), t,
                                    [](double time, const RotationSegment &x) { return time < x.t0; });
    return r != turns.begin() && t <= (r - 1)->t1 ? &*(r - 1) : nullptr;
}

const ani_carried_segment *Timeline::carried_at(int model, double t) const {
    const auto &list = carried_[static_cast<size_t>(model)];
    const auto c = std::upper_bound(list.begin(), list.end(), t,
                                    [](double time, const ani_carried_segment &x) { return time < x.t0; });
    return c != list.begin() && t <= (c - 1)->t1 ? &*(c - 1) : nullptr;
}

Placement Timeline::placement(int model, double t) const {
    return placement(model, t, 0);
}

Placement Timeline::placement(int model, double t, std::size_t depth) const {
    Placement p;
    const ani_motion_segment *s = segment_at(model, t);
    const ani_carried_segment *c = s && s->motion == ANI_MOTION_CARRIED ? carried_at(model, t) : nullptr;
    // (A chain of carriers longer than the models would come back to one: carried_refusal
    // refuses such a bake, and a restored one ends it here.)
    if (c && depth < carried_.size()) {
        const Placement carrier = placement(static_cast<int>(c->carrier), t, depth + 1);
        const glm::dvec3 arm = carrier.q * glm::dvec3(c->offset.x, c->offset.y, c->offset.z);
        p.center = carrier.center + arm;
        p.velocity = carrier.velocity + glm::cross(carrier.w, arm);
        p.q = glm::normalize(carrier.q * glm::dquat(c->relative.w, c->relative.x, c->relative.y, c->relative.z));
        p.w = carrier.w;
        return p;
    }
    const ModelPose pose = keyed_->model(model, t);
    p.center = pose.center;
    p.velocity = pose.velocity;
    if (s && s->motion != ANI_MOTION_KEYED && s->motion != ANI_MOTION_CARRIED) origin_at(model, *s, t, p.center, p.velocity);
    if (const RotationSegment *r = rotation_at(model, t)) {
        p.q = orientation_at(*r, t);
        p.w = angular_velocity_at(*r, t);
    } else {
        keyed_turning(pose, p.q, p.w);
    }
    return p;
}

std::string Timeline::carried_refusal(double from) const {
    const std::size_t n = carried_.size();
    for (std::size_t m = 0; m < n; ++m) {
        for (const ani_carried_segment &c : carried_[m]) {
            if (c.t1 < from) continue;
            const std::string which = "model " + std::to_string(m) + "'s carried segment at t = " + std::to_string(c.t0) + " s: ";
            // Along the chain of carriers at the middle of the span, no model comes back.
            const double mid = 0.5 * (c.t0 + c.t1);
            std::vector<char> seen(n, 0);
            seen[m] = 1;
            for (const ani_carried_segment *link = &c; link;) {
                const std::size_t up = link->carrier;
                if (seen[up]) return which + "its chain of carriers comes back to model " + std::to_string(up);
                seen[up] = 1;
                const ani_motion_segment *s = segment_at(static_cast<int>(up), mid);
                link = s && s->motion == ANI_MOTION_CARRIED ? carried_at(static_cast<int>(up), mid) : nullptr;
            }
            const ani_motion_segment *s = segment_at(static_cast<int>(m), mid);
            if (!s || s->motion != ANI_MOTION_CARRIED) return which + "its motion segment there does not say ANI_MOTION_CARRIED";
            if (rotation_at(static_cast<int>(m), mid)) return which + "a rotation segment covers it too";
        }
    }
    return "";
}

ani_body_state Timeline::state_at(int model, double t, std::optional<ModelPose> *keyed_pose) const {
    ani_body_state state{};
    const ani_motion_segment *s = segment_at(model, t);
    if (s && s->motion == ANI_MOTION_CARRIED) {
        // Given to the backend as free at this state (physics.h): it finds again what carries it.
        const Placement p = placement(model, t);
        state.motion = ANI_MOTION_FREE;
        state.center = to_ani(p.center);
        state.velocity = to_ani(p.velocity);
    } else if (!s || s->motion == ANI_MOTION_KEYED) {
        const ModelPose pose = keyed_->model(model, t);
        if (keyed_pose) *keyed_pose = pose;
        state.motion = ANI_MOTION_KEYED;
        state.center = to_ani(pose.center);
        state.velocity = to_ani(pose.velocity);
    } else {
        state.motion = s->motion;
        glm::dvec3 center, velocity;
        origin_at(model, *s, t, center, velocity);
        state.center = to_ani(center);
        state.velocity = to_ani(velocity);
    }
    return state;
}

void Timeline::origin_at(int model, const ani_motion_segment &s, double t, glm::dvec3 &center,
                         glm::dvec3 &velocity) const {
    center = at(s, t);
    velocity = velocity_at(s, t);
    const RotationSegment *r = rotation_at(model, t);
    if (!r || r->pivot == glm::dvec3(0.0)) return;
    const glm::dvec3 arm = orientation_at(*r, t) * r->pivot;
    center -= arm;
    velocity -= glm::cross(angular_velocity_at(*r, t), arm);
}

void Timeline::set_meshes(const std::vector<std::shared_ptr<const Mesh>> &meshes) {
    // One view per distinct mesh and rest shape: a gas of 10,000 balls shares one sphere's vertex
    // array. A model with a rest shape (a sheared course node) is collided with in that shape, so
    // its backend gets the mesh's vertices already through it.
    std::map<std::pair<const Mesh *, std::array<double, 9>>, std::shared_ptr<const MeshView>> views;
    meshes_.clear();
    for (size_t i = 0; i < meshes.size(); ++i) {
        const auto &mesh = meshes[i];
        if (!mesh) {
            meshes_.push_back(nullptr);
            continue;
        }
        const glm::dmat3 rest = i < doc_.models().size() ? doc_.models()[i].rest : glm::dmat3(1.0);
        std::array<double, 9> key{};
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) key[static_cast<size_t>(3 * c + r)] = rest[c][r];
        auto &shared = views[{mesh.get(), key}];
        if (!shared) {
            auto mv = std::make_shared<MeshView>();
            mv->mesh = mesh;
            const bool shaped = rest != glm::dmat3(1.0);
            for (const glm::dvec3 &p : mesh->positions) {
                const glm::dvec3 q = shaped ? rest * p : p;
                mv->positions.insert(mv->positions.end(), {q.x, q.y, q.z});
            }
            ani_mesh_view &v = mv->view;
            v.struct_size = sizeof v;
            v.positions = mv->positions.data();
            v.vertex_count = static_cast<uint32_t>(mesh->positions.size());
            v.triangles = mesh->triangles.data();
            v.triangle_count = static_cast<uint32_t>(mesh->triangle_count());
            if (shaped) {
                Mesh through = *mesh;
                for (glm::dvec3 &p : through.positions) p = rest * p;
                compute_bounding_sphere(through);
                v.bound_center = to_ani(through.bound_center);
                v.bound_radius = through.bound_radius;
                v.is_sphere = approximates_sphere(through) ? 1 : 0;
            } else {
                v.bound_center = to_ani(mesh->bound_center);
                v.bound_radius = mesh->bound_radius;
                v.is_sphere = approximates_sphere(*mesh) ? 1 : 0;
            }
            shared = std::move(mv);
        }
        meshes_.push_back(shared);
    }
    truncate(0.0);
    baked_any_ = false;
}

void Timeline::truncate(double from) {
    segments_.truncate(from);
    events_.erase(std::remove_if(events_.begin(), events_.end(), [&](const ani_collision_event &e) { return e.t >= from; }),
                  events_.end());
    for (auto &list : rotations_) {
        list.erase(std::remove_if(list.begin(), list.end(), [&](const RotationSegment &s) { return s.t0 >= from; }),
                   list.end());
        if (!list.empty() && list.back().t1 > from) list.back().t1 = from;
    }
    for (auto &list : carried_) {
        list.erase(std::remove_if(list.begin(), list.end(), [&](const ani_carried_segment &s) { return s.t0 >= from; }),
                   list.end());
        if (!list.empty() && list.back().t1 > from) list.back().t1 = from;
    }
    overlaps_.erase(std::remove_if(overlaps_.begin(), overlaps_.end(), [&](const ani_overlap &o) { return o.t >= from; }),
                    overlaps_.end());
    baked_until_ = std::min(baked_until_, from);
}

void Timeline::run_bake(double from, double until, const std::function<bool(double)> &progress) {
    const DocumentView &view = *view_;
    const auto &models = doc_.models();
    const double end_of_time = static_cast<double>(doc_.settings().max_time_ms) / 1000.0;
    // Written in two halves at once below, each element once (huge_pages.hpp: UnwrittenVector).
    ani::UnwrittenVector<ani_physics_model> scene_models(models.size());
    ani::UnwrittenVector<ani_time_span> spans(models.size());
    // Every model's key times, in one array (a vector each was an allocation a model: 100,000 for
    // a gas), the model's from key_from[m] to key_from[m + 1].
    std::vector<double> key_times;
    std::vector<std::size_t> key_from(models.size() + 1, 0);
    for (size_t m = 0; m < models.size(); ++m) {
        key_from[m] = key_times.size();
        for (const Keyframe &k : doc_.keyframes())
            if (k.states[m]) key_times.push_back(static_cast<double>(k.time_ms) / 1000.0);
    }
    key_from[models.size()] = key_times.size();
    // The backend asks for the keyed pose of every model that starts on its keys, at `from`:
    // the answers are the poses found here (evaluating them again took a tenth of a bake of
    // 100,000 balls).
    KeyedAnswers answers{keyed_.get(), from,
                         ani::UnwrittenVector<std::optional<ModelPose>>(models.size())};
    // Each model's part of the scene, in two halves at once (animator/halves.hpp: a model's start,
    // its span and its turning are read from this timeline and the keys, never written, and the
    // interpolators' evaluate may be called from any thread, interpolator.h; a hundred
    // nanoseconds a model, most of it waiting on memory).
    ani::in_halves(models.size() >= ani::kWorthTwoHalves, models.size(),
                   [&](std::size_t begin, std::size_t end) {
                       for (std::size_t m = begin; m < end; ++m) {
                           ani_physics_model &pm = scene_models[m];
                           pm = ani_physics_model{};
                           ::new (static_cast<void *>(&answers.at_from[m]))
                               std::optional<ModelPose>();
                           pm.start = state_at(static_cast<int>(m), from, &answers.at_from[m]);
                           pm.struct_size = sizeof pm;
                           pm.desc = &view.view().models[m];
                           pm.mesh = m < meshes_.size() && meshes_[m] ? &meshes_[m]->view : nullptr;
                           // Parts of a jointed model move with their parent: keyed (relative to
                           // it) throughout.
                           pm.group = groups_[m];
                           spans[m] = pm.group != m
                                          ? ani_time_span{0.0, std::max(end_of_time, until)}
                                          : keyed_->keyed_span(static_cast<int>(m));
                           pm.keyed_spans = &spans[m];
                           pm.keyed_span_count = 1;
                           if (const RotationSegment *r = rotation_at(static_cast<int>(m), from)) {
                               const glm::dquat q = orientation_at(*r, from);
                               pm.start_orientation = ani_quat{q.w, q.x, q.y, q.z};
                               pm.start_angular_velocity = to_ani(angular_velocity_at(*r, from));
                               pm.start_turning = 1;
                           } else if (pm.start.motion == ANI_MOTION_FREE &&
                                      carried_at(static_cast<int>(m), from)) {
                               const Placement p = placement(static_cast<int>(m), from);
                               pm.start_orientation = ani_quat{p.q.w, p.q.x, p.q.y, p.q.z};
                               pm.start_angular_velocity = to_ani(p.w);
                               pm.start_turning = 1;
                           }
                           pm.key_times = key_times.data() + key_from[m];
                           pm.key_count = static_cast<uint32_t>(key_from[m + 1] - key_from[m]);
                       }
                   });
    ani_physics_scene scene{};
    scene.struct_size = sizeof scene;
    scene.models = scene_models.data();
    scene.model_count = static_cast<uint32_t>(scene_models.size());
    scene.gravity = doc_.settings().gravity;
    scene.down_axis = static_cast<int32_t>(doc_.settings().down_axis);
    scene.host_context = &answers;
    scene.evaluate_keyed = [](void *context, uint32_t model, double t, ani_model_state *state, ani_vec3 *velocity) {
        const auto *known_poses = static_cast<const KeyedAnswers *>(context);
        if (model >= known_poses->at_from.size()) return ANI_ERR_FAILED;
        try {
            const std::optional<ModelPose> &known = known_poses->at_from[model];
            const ModelPose pose =
                t == known_poses->from && known ? *known : known_poses->keyed->model(static_cast<int>(model), t);
            state->center = to_ani(pose.center);
            state->angles = to_ani(pose.angles);
            state->scale = to_ani(pose.scale);
            state->turn = ani_vec3{0.0, 0.0, 0.0};
            *velocity = to_ani(pose.velocity);
            return ANI_OK;
        } catch (const std::exception &) {
            return ANI_ERR_FAILED;
        }
    };

    BakeContext context{this, &segments_, &events_, &progress, &stats_.backend_counts, &rotations_, &overlaps_, &carried_, &models};
    ani_bake_sink sink{};
    sink.context = &context;
    sink.segment = [](void *c, const ani_motion_segment *s) {
        auto *ctx = static_cast<BakeContext *>(c);
        if (s->model < ctx->segments->models()) ctx->segments->log(*s); // (filed after the call)
    };
    sink.event = [](void *c, const ani_collision_event *e) { static_cast<BakeContext *>(c)->events->push_back(*e); };
    sink.progress = [](void *c, double fraction) -> int32_t {
        auto *ctx = static_cast<BakeContext *>(c);
        return !*ctx->progress || (*ctx->progress)(fraction) ? 1 : 0;
    };
    sink.rotation = [](void *c, const ani_rotation_segment *s) {
        auto *ctx = static_cast<BakeContext *>(c);
        if (s->model < ctx->rotations->size()) {
            RotationSegment r;
            static_cast<ani_rotation_segment &>(r) = *s;
            (*ctx->rotations)[s->model].push_back(std::move(r));
        }
    };
    sink.free_rotation = [](void *c, const ani_free_rotation_segment *s) {
        auto *ctx = static_cast<BakeContext *>(c);
        if (s->model >= ctx->rotations->size() || !ctx->refused.empty()) return;
        const glm::dvec3 moments(s->moments.x, s->moments.y, s->moments.z), w0(s->w0.x, s->w0.y, s->w0.z);
        const glm::dquat q0(s->q0.w, s->q0.x, s->q0.y, s->q0.z), principal(s->principal.w, s->principal.x, s->principal.y, s->principal.z);
        std::string why = ani::FreeRotation::refusal(moments, w0);
        const double numbers[] = {s->t0, s->t1, q0.w, q0.x, q0.y, q0.z, principal.w, principal.x, principal.y, principal.z,
                                  s->pivot.x, s->pivot.y, s->pivot.z};
        if (why.empty() && !all_finite(numbers)) why = "a time, an orientation or the pivot is not finite";
        if (why.empty() && (glm::length(q0) == 0.0 || glm::length(principal) == 0.0)) why = "an orientation is zero";
        if (ctx->refuse(s->model, "free-rotation", s->t0, why)) return;
        RotationSegment r = rotation_segment(*s);
        r.w = s->w0;
        r.principal = glm::normalize(principal);
        r.pivot = glm::dvec3(s->pivot.x, s->pivot.y, s->pivot.z);
        r.moments = moments;
        r.free = free_rotation_of(r);
        (*ctx->rotations)[s->model].push_back(std::move(r));
    };
    sink.spin_up = [](void *c, const ani_spin_up_segment *s) {
        auto *ctx = static_cast<BakeContext *>(c);
        if (s->model >= ctx->rotations->size() || !ctx->refused.empty()) return;
        const double numbers[] = {s->t0, s->t1, s->q0.w, s->q0.x, s->q0.y, s->q0.z, s->w0.x, s->w0.y, s->w0.z, s->alpha.x, s->alpha.y, s->alpha.z};
        std::string why;
        if (!all_finite(numbers)) why = "a time, the orientation, w0 or alpha is not finite";
        const glm::dquat q0(s->q0.w, s->q0.x, s->q0.y, s->q0.z);
        if (why.empty() && glm::length(q0) == 0.0) why = "the orientation is zero";
        if (ctx->refuse(s->model, "spin-up", s->t0, why)) return;
        RotationSegment r = rotation_segment(*s);
        r.w = s->w0;
        r.alpha = glm::dvec3(s->alpha.x, s->alpha.y, s->alpha.z);
        (*ctx->rotations)[s->model].push_back(std::move(r));
    };
    sink.hinge = [](void *c, const ani_hinge_segment *s) {
        auto *ctx = static_cast<BakeContext *>(c);
        if (s->model >= ctx->rotations->size() || !ctx->refused.empty()) return;
        std::string why = ani::Pendulum::refusal(s->omega2, s->angle0, s->rate0);
        const double numbers[] = {s->t0, s->t1, s->q0.w, s->q0.x, s->q0.y, s->q0.z, s->axis.x, s->axis.y, s->axis.z,
                                  s->pivot.x, s->pivot.y, s->pivot.z};
        if (why.empty() && !all_finite(numbers)) why = "a time, the orientation, the axis or the pivot is not finite";
        const glm::dquat q0(s->q0.w, s->q0.x, s->q0.y, s->q0.z);
        const glm::dvec3 axis(s->axis.x, s->axis.y, s->axis.z);
        if (why.empty() && glm::length(q0) == 0.0) why = "the orientation is zero";
        if (why.empty() && std::abs(glm::length(axis) - 1.0) > 1e-9) why = "the axis is not a unit vector";
        if (ctx->refuse(s->model, "hinge", s->t0, why)) return;
        RotationSegment r = rotation_segment(*s);
        r.w = {s->rate0 * axis.x, s->rate0 * axis.y, s->rate0 * axis.z};
        r.axis = axis;
        r.pivot = glm::dvec3(s->pivot.x, s->pivot.y, s->pivot.z);
        r.omega2 = s->omega2;
        r.angle0 = s->angle0;
        r.rate0 = s->rate0;
        r.hinge = hinge_of(r);
        (*ctx->rotations)[s->model].push_back(std::move(r));
    };
    sink.carried = [](void *c, const ani_carried_segment *s) {
        auto *ctx = static_cast<BakeContext *>(c);
        const std::size_t n = ctx->carried->size();
        if (s->model >= n || !ctx->refused.empty()) return;
        const double numbers[] = {s->t0, s->t1, s->offset.x, s->offset.y, s->offset.z,
                                  s->relative.w, s->relative.x, s->relative.y, s->relative.z};
        const glm::dquat q(s->relative.w, s->relative.x, s->relative.y, s->relative.z);
        std::string why;
        if (!all_finite(numbers)) why = "a time, the offset or the orientation is not finite";
        else if (glm::length(q) == 0.0) why = "the orientation is zero";
        else if (s->carrier >= n || s->carrier == s->model) why = "its carrier " + std::to_string(s->carrier) + " is not another model";
        else if ((*ctx->models)[s->model].parent >= 0 || (*ctx->models)[s->carrier].parent >= 0)
            why = "a part of a jointed model carries or is carried";
        if (ctx->refuse(s->model, "carried", s->t0, why)) return;
        ani_carried_segment r = *s;
        const glm::dquat unit = glm::normalize(q);
        r.relative = ani_quat{unit.w, unit.x, unit.y, unit.z};
        (*ctx->carried)[s->model].push_back(r);
    };
    sink.overlap = [](void *c, const ani_overlap *o) {
        auto *ctx = static_cast<BakeContext *>(c);
        const std::size_t n = ctx->segments->models();
        if (o->a < n && o->b < n && o->a != o->b && std::isfinite(o->t) && std::isfinite(o->depth))
            ctx->overlaps->push_back(*o);
    };
    sink.count = [](void *c, const char *name, double value) {
        if (name && std::isfinite(value)) (*static_cast<BakeContext *>(c)->counts)[name] += value;
    };

    ani_status status{};
    const auto &api = physics_->api<ani_physics_api>();
    const ani_status_code code = api.bake(physics_->handle(), &scene, from, until, &sink, &status);
    segments_.file();
    ++stats_.bake_calls;
    if (code == ANI_ERR_CANCELLED) {
        truncate(from);
        throw BakeCancelled();
    }
    if (code != ANI_OK) {
        truncate(from);
        throw PluginError("physics backend '" + physics_->info().id + "': " + status.message);
    }
    if (context.refused.empty()) context.refused = carried_refusal(from);
    if (!context.refused.empty()) {
        truncate(from);
        throw PluginError("physics backend '" + physics_->info().id + "' reported " + context.refused);
    }
    stats_.seconds_baked += until - from;
    baked_until_ = until;
    baked_any_ = true;
}

BakedState Timeline::baked_state() const {
    return BakedState{baked_any_ ? baked_until_ : 0.0, segments_.lists(), rotations_, carried_, events_, overlaps_};
}

void Timeline::restore(BakedState state) {
    const std::size_t n = doc_.models().size();
    if (state.segments.size() != n || state.rotations.size() != n || state.carried.size() != n)
        throw std::invalid_argument("a bake of " + std::to_string(state.segments.size()) + " models for a document of " +
                                    std::to_string(n));
    segments_.assign(state.segments);
    rotations_ = std::move(state.rotations);
    carried_ = std::move(state.carried);
    events_ = std::move(state.events);
    overlaps_ = std::move(state.overlaps);
    baked_until_ = state.until;
    baked_any_ = true;
}

std::vector<std::pair<std::string, ParamValue>> Timeline::backend_params() const {
    std::vector<std::pair<std::string, ParamValue>> params;
    const ani_plugin_descriptor *d = physics_->info().descriptor;
    for (uint32_t k = 0; d && k < d->param_count; ++k) params.emplace_back(d->params[k].id, physics_->get_param(d->params[k].id));
    return params;
}

const ani_mesh_view *Timeline::mesh_view(int model) const {
    const auto m = static_cast<size_t>(model);
    return m < meshes_.size() && meshes_[m] ? &meshes_[m]->view : nullptr;
}

void Timeline::bake(double until, const std::function<bool(double)> &progress) {
    if (baked_any_ && until <= baked_until_) return;
    run_bake(baked_any_ ? baked_until_ : 0.0, until, progress);
}

Frame Timeline::evaluate(double t) const {
    Frame frame;
    const int n = static_cast<int>(doc_.models().size());
    frame.models.resize(static_cast<size_t>(n));
    frame.motion.resize(static_cast<size_t>(n));
    for (int m = 0; m < n; ++m) {
        ModelPose pose = keyed_->model(m, t); // rotation and scale always come from the keys
        const ani_motion_segment *s = segment_at(m, t);
        frame.motion[static_cast<size_t>(m)] = s ? s->motion : ANI_MOTION_KEYED;
        if (s && s->motion == ANI_MOTION_CARRIED) {
            const Placement p = placement(m, t);
            pose.center = p.center;
            pose.velocity = p.velocity;
            pose.angles = angles_of(p.q);
            frame.models[static_cast<size_t>(m)] = pose;
            continue;
        }
        if (s && s->motion != ANI_MOTION_KEYED) origin_at(m, *s, t, pose.center, pose.velocity);
        // A backend that turns models (rigid-body rotation) overrides the keys' angles.
        if (const RotationSegment *r = rotation_at(m, t)) pose.angles = angles_of(orientation_at(*r, t));
        frame.models[static_cast<size_t>(m)] = pose;
    }
    frame.camera = keyed_->camera(t);
    return frame;
}

double Timeline::affected_from(const Document &before, const Document &after) {
    constexpr double never = std::numeric_limits<double>::infinity();
    const Settings &a = before.settings(), &b = after.settings();
    if (a.gravity != b.gravity || a.down_axis != b.down_axis || a.physics_backend != b.physics_backend ||
        a.interpolation != b.interpolation || a.params != b.params)
        return 0.0;
    if (before.models().size() != after.models().size()) return 0.0;
    for (size_t m = 0; m < before.models().size(); ++m)
        if (!same_physics(before.models()[m], after.models()[m])) return 0.0;

    double from = never;
    for (size_t m = 0; m < before.models().size(); ++m) {
        const auto keys_a = before.keys_of(static_cast<int>(m)), keys_b = after.keys_of(static_cast<int>(m));
        // The first key that differs; the motion changes from the key before it, because the
        // segment leading into it is interpolated from there.
        size_t i = 0;
        while (i < keys_a.size() && i < keys_b.size() && keys_a[i]->time_ms == keys_b[i]->time_ms &&
               *keys_a[i]->states[m] == *keys_b[i]->states[m])
            ++i;
        if (i == keys_a.size() && i == keys_b.size()) continue;
        const std::int64_t previous = i == 0 ? 0 : keys_a[i - 1]->time_ms;
        from = std::min(from, static_cast<double>(previous) / 1000.0);
    }
    return from;
}

void Timeline::set_document(const Document &doc, const std::function<bool(double)> &progress) {
    const double until = baked_until_;
    const bool baked = baked_any_;
    edit(doc);
    if (baked && baked_until_ < until) run_bake(baked_until_, until, progress);
}

void Timeline::edit(const Document &doc) {
    const double from = affected_from(doc_, doc);
    const bool new_interpolation = doc.settings().interpolation != doc_.settings().interpolation ||
                                   doc.settings().params != doc_.settings().params;
    const bool new_backend = doc.settings().physics_backend != doc_.settings().physics_backend ||
                             doc.settings().params != doc_.settings().params;
    // What can fail comes first, so that a failure leaves the timeline as it was.
    std::unique_ptr<PluginInstance> physics = new_backend ? physics_instance(plugins_, doc, backend_override_) : nullptr;
    Interpolators interpolators = new_interpolation ? Interpolators::load(plugins_, doc) : Interpolators{};
    doc_ = doc;
    if (physics) physics_ = std::move(physics);
    if (new_interpolation) interpolators_ = std::move(interpolators);
    keyed_ = std::make_unique<KeyedMotion>(doc_, interpolators_);
    describe_document();
    if (doc_.models().size() != segments_.models()) {
        segments_.reset(doc_.models().size());
        rotations_.assign(doc_.models().size(), {});
        carried_.assign(doc_.models().size(), {});
        overlaps_.clear();
    }
    if (baked_any_ && from < baked_until_) truncate(from);
}

void Timeline::set_backend(const std::string &id, const std::function<bool(double)> &progress) {
    const double until = baked_until_;
    const bool baked = baked_any_;
    use_backend(id);
    if (baked) run_bake(0.0, until, progress);
}

void Timeline::use_backend(const std::string &id) {
    auto physics = physics_instance(plugins_, doc_, id); // throws, leaving everything as it was
    physics_ = std::move(physics);
    backend_override_ = id;
    truncate(0.0);
    baked_any_ = false;
}

} // namespace animator
