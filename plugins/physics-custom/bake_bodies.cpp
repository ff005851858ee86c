// The event-driven bake's bodies (physics.md, "Where the code is"): which models are bodies or
// obstacles, their start, keys, shapes, poses, mass properties and turning, and the segments
// reported to the host. Relies on event_bake_detail.hpp (the types) and the bake's data.
#include "event_bake_detail.hpp"

#include <unordered_map>

namespace physics_custom::bake {

// Sorts the models: static ones with a mesh are obstacles; spheres that can move and models
// with a mesh that are keyed during the bake are bodies; the rest (jointed parts, models
// without a mesh, free models that are not spheres) move without collisions.
void EventBake::classify() {
    Reaches reaches;
    bodies_.reserve(scene_->model_count); // at most one per model: never moved as they are added
    materials_.reserve(scene_->model_count);
    for (uint32_t i = 0; i < scene_->model_count; ++i) {
        const ani_physics_model &m = scene_->models[i];
        if (!m.desc) throw ani::Failure(ANI_ERR_INVALID_ARGUMENT, "a model has no description");
        const auto [span, free_now, movable, solid] = standing(i);
        const double keyed_until = std::min(std::max(span.end, t_begin_), t_end_);
        // A model released from its keys in an earlier bake is still free where that bake
        // left it (the host's cache says so), until its next key.
        const bool released = !free_now && m.start.motion != ANI_MOTION_KEYED;
        const ani_model_desc &d = *m.desc;
        materials_.push_back(material_of(d)); // refuses values out of range
        // Keys that all hold it in the same place (a floor keyed along with the rest of a
        // keyframe) do not make it a moving wall.
        const bool held_still =
            !free_now && !released && solid && !movable && keys_hold_still(i, span.end);
        const bool keyed_here = !free_now && span.end > t_begin_ && !held_still;

        // A static model (it never moves again) is an obstacle made of its triangles.
        is_body_.push_back(false);
        if (!movable && (free_now || held_still) && solid) {
            add_obstacle(i, t_begin_);
            emit_unmoved(i);
            continue;
        }
        const std::optional<double> radius = sphere_radius(i, free_now ? t_begin_ : keyed_until);
        if (solid && (movable || keyed_here)) {
            std::optional<TurningShape> turning =
                check_turning(i, radius.has_value(), free_now ? t_begin_ : span.end);
            is_body_.back() = true;
            Body b = body_of(i, radius, free_now ? t_begin_ : span.end, reaches);
            if (turning) set_turning(b, std::move(*turning));
            if (!b.sphere) mesh_bodies_.push_back(static_cast<int>(bodies_.size()));
            bodies_.push_back(std::move(b));
            Body &body = bodies_.back();
            if (released) {
                activate(body, t_begin_, m.start);
                if (!body.dynamics) stop(body);
                body.resume_at = next_key(i, t_begin_);
            } else if (free_now) {
                activate(body, t_begin_, start_of(i, t_begin_));
                // Stopped by a contact in an earlier bake (Dynamics off): it stays stopped.
                if (!body.dynamics && m.start.motion == ANI_MOTION_REST) stop(body);
            } else {
                body.mode = Body::Mode::kKeyed;
                body.keyed_from = t_begin_;
                body.active = true;
            }
            body.path.p = body.keyed() ? vec(keyed(i, t_begin_, nullptr).center) : body.path.p;

            continue;
        }
        emit_unmoved(i);
    }
}

EventBake::Standing EventBake::standing(uint32_t i) const {
    const ani_physics_model &m = scene_->models[i];
    const ani_time_span span =
        m.keyed_span_count ? m.keyed_spans[0] : ani_time_span{t_begin_, t_begin_};
    return {span, span.end <= t_begin_, m.desc->dynamics || m.desc->gravity,
            m.mesh && m.mesh->triangle_count > 0 && m.group == i};
}

// The record of model i as a body (a sphere of `radius`, or its mesh), not yet moving: its shape,
// mass and material (materials_[i] made), and where its keys end.
Body EventBake::body_of(uint32_t i, const std::optional<double> &radius, double keys_end,
                        Reaches &reaches) const {
    const ani_physics_model &m = scene_->models[i];
    Body b;
    b.model = i;
    b.sphere = radius.has_value();
    b.radius = radius.value_or(0.0);
    const auto [reach, fresh] = reaches.try_emplace(m.mesh, 0.0);
    if (fresh) reach->second = mesh_reach(*m.mesh);
    b.reach = reach->second;
    if (!b.sphere) b.edges = edges_of(m.mesh->triangles, m.mesh->triangle_count);
    b.dynamics = m.desc->dynamics != 0;
    b.mass = m.desc->mass;
    b.material = materials_[i];
    b.keys_end = keys_end;
    return b;
}

// The motion of a model that is not a body over [t_begin, t_end] (in every slice of a bake):
// a static model held by its keys, then at rest; any other model keyed, then free without
// collisions.
void EventBake::emit_unmoved(uint32_t i) {
    const auto [span, free_now, movable, solid] = standing(i);
    const double keyed_until = std::min(std::max(span.end, t_begin_), t_end_);
    if (keyed_until > t_begin_) emit_keyed(i, t_begin_, keyed_until);
    if (!(free_now || span.end < t_end_)) return; // keyed throughout this slice
    emit_free(i, start_of(i, free_now ? t_begin_ : keyed_until), free_now ? t_begin_ : keyed_until);
}

// Whether a model's keys from t_begin to its last key all place it the same way and leave it
// still (checked at each key and half-way between keys).
bool EventBake::keys_hold_still(uint32_t i, double last) const {
    const ani_physics_model &m = scene_->models[i];
    if (!(m.struct_size >= offsetof(ani_physics_model, key_count) + sizeof(m.key_count) &&
          m.key_times))
        return false;
    std::vector<double> times = {t_begin_};
    for (uint32_t k = 0; k < m.key_count; ++k)
        if (m.key_times[k] > t_begin_ && m.key_times[k] <= last) {
            times.push_back(0.5 * (times.back() + m.key_times[k]));
            times.push_back(m.key_times[k]);
        }
    glm::dvec3 v0;
    const ani_model_state first = keyed(i, t_begin_, &v0);
    auto same = [](const ani_vec3 &a, const ani_vec3 &b) {
        return a.x == b.x && a.y == b.y && a.z == b.z;
    };
    for (double t : times) {
        glm::dvec3 v;
        const ani_model_state s = keyed(i, t, &v);
        if (v != glm::dvec3(0.0) || !same(s.center, first.center) ||
            !same(s.angles, first.angles) || !same(s.scale, first.scale))
            return false;
    }
    return true;
}

// The state a model is in at t: the host's cache where a resumed bake starts, otherwise its
// keys' (physics.md: where and how fast it leaves them).
ani_model_state EventBake::keyed(uint32_t m, double t, glm::dvec3 *velocity) const {
    KeyedMemo &memo = keyed_memo_[m];
    if (!keyed_known_[m] || !(memo.t == t)) {
        ani_vec3 v{};
        keyed_known_[m] = 0;
        if (scene_->evaluate_keyed(scene_->host_context, m, t, &memo.state, &v) != ANI_OK)
            throw ani::Failure(ANI_ERR_FAILED, std::string("cannot evaluate the keys of model '") +
                                                   name_of(scene_->models[m]) + "'");
        memo.t = t;
        memo.velocity = vec(v);
        keyed_known_[m] = 1;
    }
    if (velocity) *velocity = memo.velocity;
    return memo.state;
}

ani_body_state EventBake::start_of(uint32_t i, double t) {
    const ani_physics_model &m = scene_->models[i];
    if (t == t_begin_ && m.start.motion != ANI_MOTION_KEYED) return m.start;
    return leaving_keys(i, t);
}

// The first of the model's keys after t (the end of its keys if none is in between).
double EventBake::next_key(uint32_t i, double t) const {
    const ani_physics_model &m = scene_->models[i];
    if (m.struct_size >= offsetof(ani_physics_model, key_count) + sizeof(m.key_count) &&
        m.key_times)
        for (uint32_t k = 0; k < m.key_count; ++k)
            if (m.key_times[k] > t) return m.key_times[k];
    return m.keyed_span_count ? m.keyed_spans[0].end : t;
}

std::optional<double> EventBake::sphere_radius(uint32_t i, double t) {
    const ani_physics_model &m = scene_->models[i];
    if (!m.mesh || !m.mesh->is_sphere) return std::nullopt;
    if (glm::length(vec(m.mesh->bound_center)) > 1e-9 * m.mesh->bound_radius) return std::nullopt;
    const ani_model_state s = keyed(i, t, nullptr);
    if (!uniform(s.scale)) return std::nullopt;
    return m.mesh->bound_radius * s.scale.x;
}

void EventBake::add_obstacle(uint32_t i, double t) {
    const ani_mesh_view &mesh = *scene_->models[i].mesh;
    const ani_model_state state = keyed(i, t, nullptr);
    const glm::dmat3 linear = linear_part(state);
    Obstacle o;
    o.model = i;
    for (uint32_t k = 0; k < 3 * mesh.triangle_count; ++k) {
        const double *p = mesh.positions + 3 * static_cast<size_t>(mesh.triangles[k]);
        o.corners.push_back(vec(state.center) + linear * glm::dvec3(p[0], p[1], p[2]));
    }
    finish_obstacle(o);
    if (!o.boxes.empty() && std::all_of(o.normals.begin(), o.normals.end(),
                                        [](const glm::dvec3 &n) { return n == glm::dvec3(0.0); }))
        throw ani::Failure(ANI_ERR_INVALID_ARGUMENT,
                           std::string("model '") + name_of(scene_->models[i]) +
                               "' has a mesh without area (every triangle is degenerate)");
    o.shape = build_shape(i, state.center, linear, glm::dvec3(0.0));
    triangle_count_ += o.boxes.size();
    obstacles_.push_back(std::move(o));
}

// An obstacle's triangles from its corners (3 per triangle, world space): their boxes, unit
// normals and planes, and its bounding sphere.
void EventBake::finish_obstacle(Obstacle &o) {
    for (size_t k = 0; k + 2 < o.corners.size(); k += 3) {
        Box box{o.corners[k], o.corners[k]};
        for (size_t j = 1; j < 3; ++j) {
            box.lo = glm::min(box.lo, o.corners[k + j]);
            box.hi = glm::max(box.hi, o.corners[k + j]);
        }
        o.boxes.push_back(box);
        const glm::dvec3 n =
            glm::cross(o.corners[k + 1] - o.corners[k], o.corners[k + 2] - o.corners[k]);
        o.normals.push_back(glm::length(n) > 0.0 ? glm::normalize(n) : glm::dvec3(0.0));
        o.offsets.push_back(glm::dot(o.normals.back(), o.corners[k]));
    }
    glm::dvec3 sum(0.0);
    for (const auto &c : o.corners) sum += c;
    o.center = o.corners.empty() ? glm::dvec3(0.0) : sum / static_cast<double>(o.corners.size());
    for (const auto &c : o.corners) o.radius = std::max(o.radius, glm::length(c - o.center));
}

// Model i's triangles as a MeshShape: model-space vertices turned and scaled by `linear`,
// relative to `origin` (its center for a body, the world's origin for an obstacle).
std::shared_ptr<const MeshShape> EventBake::build_shape(uint32_t i, const ani_vec3 &center,
                                                        const glm::dmat3 &linear,
                                                        const glm::dvec3 &origin) const {
    const ani_mesh_view &mesh = *scene_->models[i].mesh;
    std::vector<glm::dvec3> vertices;
    vertices.reserve(mesh.vertex_count);
    for (uint32_t k = 0; k < mesh.vertex_count; ++k) {
        const double *p = mesh.positions + 3 * static_cast<size_t>(k);
        vertices.push_back(vec(center) - origin + linear * glm::dvec3(p[0], p[1], p[2]));
    }
    std::vector<std::array<uint32_t, 3>> triangles(mesh.triangle_count);
    for (uint32_t k = 0; k < mesh.triangle_count; ++k)
        for (uint32_t c = 0; c < 3; ++c)
            triangles[k][c] = mesh.triangles[3 * static_cast<size_t>(k) + c];
    try {
        return std::make_shared<const MeshShape>(
            MeshShape::build(std::move(vertices), std::move(triangles)));
    } catch (const std::exception &e) {
        throw ani::Failure(ANI_ERR_INVALID_ARGUMENT,
                           std::string("model '") + name_of(scene_->models[i]) + "': " + e.what());
    }
}

// Free from t with the given state: the closed form of physics.md's four cases.
void EventBake::activate(Body &b, double t, const ani_body_state &start) {
    const ani_motion_segment s =
        free_segment(b.model, *scene_->models[b.model].desc, start, t, t_end_, ani(gravity_));
    b.mode = Body::Mode::kFree;
    b.active = true;
    if (b.sphere)
        if (auto r = sphere_radius(b.model, t)) b.radius = *r; // its keys may have scaled it
    b.t0 = t;
    b.path = Path{vec(s.p0), vec(s.v0), vec(s.a)};
    b.free_a = b.path.a;
    b.motion = s.motion;
    b.support = -1;
    if (b.carrier >= 0) --riders_;
    b.carrier = -1;
    b.support_v = glm::dvec3(0.0);
    b.carrier_until = kNever;
    b.support_edges.clear();
    b.settles_at = kNever;
    start_spin(b, t);
    if (b.turning() && b.pivot != glm::dvec3(0.0)) { // its path is its centre of mass's
        const glm::dvec3 arm = b.spin.at(t) * b.pivot;
        b.path.p += arm;
        // Its velocity leaving its keys, or from an earlier bake, is its origin's; a model free
        // from the start is thrown with the model's velocity at its centre of mass.
        const ani_physics_model &m = scene_->models[b.model];
        const bool goes_on = t == t_begin_ && ANI_PHYSICS_MODEL_HAS_TURNING(&m) && m.start_turning;
        if (b.keys_end > 0.0 || goes_on) b.path.v += glm::cross(b.spin.rate(t), arm);
    }
    b.shape.reset();
    if (!b.sphere && !b.turns && t >= b.keys_end) { // its keys no longer turn or scale it
        const ani_model_state state = keyed(b.model, t, nullptr);
        b.shape = build_shape(b.model, ani(glm::dvec3(0.0)), linear_part(state), glm::dvec3(0.0));
    }
    ++b.version;
}

// Without Dynamics, a model released from its keys rests where the contact left it.
void EventBake::stop(Body &b) {
    b.path = Path{b.path.p, glm::dvec3(0.0), glm::dvec3(0.0)};
    b.free_a = glm::dvec3(0.0);
    b.motion = ANI_MOTION_REST;
}

// The state a model leaves its keys with at time t (physics.md: where and how fast).
ani_body_state EventBake::leaving_keys(uint32_t i, double t) {
    glm::dvec3 v;
    const ani_model_state s = keyed(i, t, &v);
    ani_body_state state{};
    state.motion = ANI_MOTION_KEYED;
    state.center = s.center;
    state.velocity = ani(v);
    return state;
}

void EventBake::emit(const ani_motion_segment &s) {
    auto finite = [](const ani_vec3 &v) {
        return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
    };
    if (!finite(s.p0) || !finite(s.v0) || !finite(s.a) || !std::isfinite(s.t0) ||
        !std::isfinite(s.t1))
        throw ani::Failure(ANI_ERR_FAILED, std::string("model '") +
                                               name_of(scene_->models[s.model]) +
                                               "' would move to a value that is not finite");
    sink_->segment(sink_->context, &s);
}

// (A body keyed since before this slice reports its keyed span from where the slice starts.)
void EventBake::emit_keyed(uint32_t i, double t0, double t1) {
    t0 = std::max(t0, t_begin_);
    if (!(t1 > t0)) return;
    ani_motion_segment s{};
    s.model = i;
    s.motion = ANI_MOTION_KEYED;
    s.t0 = t0;
    s.t1 = t1;
    emit(s);
}

void EventBake::emit_free(uint32_t i, const ani_body_state &start, double free_at) {
    if (free_at >= t_end_) return;
    emit(free_segment(i, *scene_->models[i].desc, start, free_at, t_end_, ani(gravity_)));
}

// Reports a body's free segment up to t: from where it started, or from where this slice
// starts for a segment that began in an earlier slice (which reported its part).
void EventBake::close_segment(Body &b, double t) {
    const double from = std::max(b.t0, t_begin_);
    if (t <= from && !(t == t_end_ && from == t_end_)) return;
    ani_motion_segment s{};
    s.model = b.model;
    s.motion = b.motion;
    s.t0 = from;
    s.t1 = t;
    s.p0 = ani(from == b.t0 ? b.path.p : b.path.at(from - b.t0));
    s.v0 = ani(from == b.t0 ? b.path.v : b.path.velocity(from - b.t0));
    s.a = ani(b.path.a);
    emit(s);
}

void EventBake::restart(Body &b, double t, const glm::dvec3 &velocity, bool stop) {
    close_segment(b, t);
    const glm::dvec3 p = b.path.at(t - b.t0);
    b.t0 = t;
    b.path = stop ? Path{p, glm::dvec3(0.0), glm::dvec3(0.0)} : Path{p, velocity, b.path.a};
    b.motion = stop ? ANI_MOTION_REST : ANI_MOTION_FREE;
    if (b.supported() && !stop) aim_friction(b); // on its support: friction against it now
    b.settles_at = kNever;
    ++b.version;
}

// ---- where bodies are ------------------------------------------------------------------

// A body's pose at t: its keys', or its free path's center with its keys' rotation and
// scale (which always come from the keys).
Pose EventBake::pose(const Body &b, double t) const {
    if (b.carried()) { // where its carrier takes it (it does not turn meanwhile)
        Pose p = pose(bodies_[static_cast<size_t>(b.carried_by)], t);
        p.center += b.carried_offset;
        p.linear = b.carried_linear;
        return p;
    }
    glm::dvec3 v;
    const ani_model_state s = keyed(b.model, t, &v);
    Pose p;
    p.linear = b.turning() ? glm::dmat3(glm::mat3_cast(b.spin.at(t))) * b.scale : linear_part(s);
    if (b.keyed()) {
        p.center = vec(s.center);
        p.velocity = v;
    } else {
        p.center = b.path.at(t - b.t0);
        p.velocity = b.path.velocity(t - b.t0);
        const glm::dvec3 pivot = b.hinge ? b.hinge->pivot : b.pivot; // what `path` follows
        if (b.turning() && pivot != glm::dvec3(0.0)) { // the origin, from the centre of mass
            const glm::dvec3 arm = b.spin.at(t) * pivot;
            p.center -= arm;
            p.velocity -= glm::cross(b.spin.rate(t), arm);
        }
    }
    return p;
}

const ani_mesh_view &EventBake::mesh_of(const Body &b) const {
    return *scene_->models[b.model].mesh;
}

glm::dvec3 EventBake::vertex(const ani_mesh_view &mesh, uint32_t k) const {
    const double *p = mesh.positions + 3 * static_cast<size_t>(k);
    return {p[0], p[1], p[2]};
}

// A body's triangles where its pose puts them, for mesh distances.
PlacedMesh EventBake::placed(const Body &b, const Pose &p) const {
    const ani_mesh_view &mesh = mesh_of(b);
    PlacedMesh out{p.center,      {}, mesh.triangles, mesh.triangle_count, b.edges.data(),
                   b.edges.size()};
    out.vertices.reserve(mesh.vertex_count);
    for (uint32_t k = 0; k < mesh.vertex_count; ++k)
        out.vertices.push_back(p.center + p.linear * vertex(mesh, k));
    return out;
}

PlacedMesh EventBake::placed(const Obstacle &o) {
    return {o.center,
            o.shape->vertices,
            o.shape->triangles.empty() ? nullptr : &o.shape->triangles[0][0],
            o.shape->triangles.size(),
            o.shape->edges.data(),
            o.shape->edges.size()};
}

// The farthest a vertex of the mesh is from the model's origin, in model space.
double EventBake::mesh_reach(const ani_mesh_view &mesh) {
    double r = 0.0;
    for (uint32_t k = 0; k < mesh.vertex_count; ++k) {
        const double *p = mesh.positions + 3 * static_cast<size_t>(k);
        r = std::max(r, glm::length(glm::dvec3(p[0], p[1], p[2])));
    }
    return r;
}

// The acceleration a body has now: its path's, or none under its keys.
glm::dvec3 EventBake::acceleration(const Body &b) {
    return b.driven() ? glm::dvec3(0.0) : b.path.a;
}

double EventBake::body_size(const Body &b) const {
    if (b.sphere) return b.radius;
    if (b.shape) return 0.5 * glm::length(b.shape->bounds().hi - b.shape->bounds().lo);
    if (b.turns) return b.turning_reach;
    return b.reach;
}

// The vertices of a free model that is not a sphere, relative to its centre, as placed at t.
std::vector<glm::dvec3> EventBake::placed_vertices(const Body &b, double t) const {
    if (b.shape) return b.shape->vertices;
    const glm::dmat3 turn = glm::dmat3(glm::mat3_cast(b.spin.at(t)));
    std::vector<glm::dvec3> out;
    for (const glm::dvec3 &v : b.hinge ? b.hinge->vertices : b.turning_vertices)
        out.push_back(turn * v);
    return out;
}

// A free sphere that rotates, or a model that turns (bake_response.cpp, its last section), starts
// turning where it becomes free for good: with the host's orientation and angular velocity when the
// bake goes on from an earlier one; otherwise with its keys' orientation and, free from t = 0, the
// model's angular velocity, or, after its last key, the keys' own turning rate there (a backward
// difference over 1e-6 s: the keys end there, so a central difference would halve it).
void EventBake::start_spin(Body &b, double t) {
    if (b.spin.on) emit_spin(b, t);
    b.spin = Spin{};
    if (!((b.sphere || b.turns) && b.dynamics && b.material.rotates && t >= b.keys_end)) return;
    const ani_physics_model &m = scene_->models[b.model];
    b.spin.on = true;
    b.spin.moments = b.moments;
    b.spin.principal = b.principal;
    if (t == t_begin_ && ANI_PHYSICS_MODEL_HAS_TURNING(&m) && m.start_turning) {
        const ani_quat &q = m.start_orientation;
        b.spin.start(t, glm::normalize(glm::dquat(q.w, q.x, q.y, q.z)),
                     vec(m.start_angular_velocity));
        return;
    }
    const glm::dquat at_keys = orientation_of_angles(vec(keyed(b.model, t, nullptr).angles));
    if (b.keys_end <= 0.0) {
        Spin from_zero = b.spin;
        from_zero.start(0.0, orientation_of_angles(vec(keyed(b.model, 0.0, nullptr).angles)),
                        b.material.angular_velocity);
        b.spin.start(t, from_zero.at(t), from_zero.rate(t));
        return;
    }
    const double h = 1e-6 * std::max(1.0, std::abs(t));
    const glm::dquat before = orientation_of_angles(vec(keyed(b.model, t - h, nullptr).angles));
    b.spin.start(t, at_keys, angular_velocity_between(before, at_keys, h));
}

// A body's angular velocity changes at t: its rotation segment so far is reported.
void EventBake::turn(Body &b, double t, const glm::dvec3 &w) {
    if (w == b.spin.rate(t)) return;
    emit_spin(b, t);
    b.spin.start(t, b.spin.at(t), w);
}

// Its motion so far reported, its path starts again at t where it is.
void EventBake::rebase(Body &b, double t) {
    close_segment(b, t);
    b.path = from_now(b, t);
    b.t0 = t;
    ++b.version;
}

// Its turn so far reported, it turns on from t at the angular velocity it has then, at a
// constant rate.
void EventBake::restart_spin(Body &b, double t) {
    emit_spin(b, t);
    b.spin.start(t, b.spin.at(t), b.spin.rate(t));
}

// Reports a turning body's rotation from the start of its stretch (or of this slice) to t.
void EventBake::emit_spin(const Body &b, double t) {
    const double from = std::max(b.spin.t0, t_begin_);
    if (!(t > from)) return;
    const glm::dquat q = b.spin.at(from);
    const glm::dvec3 w = b.spin.rate(from);
    if (!std::isfinite(q.w) || !std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z) ||
        !std::isfinite(w.x) || !std::isfinite(w.y) || !std::isfinite(w.z))
        throw ani::Failure(ANI_ERR_FAILED, std::string("model '") +
                                               name_of(scene_->models[b.model]) +
                                               "' would turn to a value that is not finite");
    // What the four kinds of segment share: the model, the span and the orientation at its start.
    auto segment = [&](auto s) {
        s.model = b.model;
        s.t0 = from;
        s.t1 = t;
        s.q0 = ani_quat{q.w, q.x, q.y, q.z};
        return s;
    };
    if (b.spin.hinge) { // tipping over an edge
        if (!sink_->hinge) return;
        ani_hinge_segment s = segment(ani_hinge_segment{});
        s.axis = ani(b.spin.axis);
        double angle, rate;
        b.spin.hinge->evaluate(from, angle, rate);
        s.angle0 = angle;
        s.rate0 = rate;
        s.omega2 = b.spin.hinge->omega2();
        s.pivot = ani(b.hinge ? b.hinge->pivot : b.pivot);
        sink_->hinge(sink_->context, &s);
    } else if (b.spin.alpha != glm::dvec3(0.0)) { // friction turns it on its support
        if (!sink_->spin_up) return;
        ani_spin_up_segment s = segment(ani_spin_up_segment{});
        s.w0 = ani(w);
        s.alpha = ani(b.spin.alpha);
        sink_->spin_up(sink_->context, &s);
    } else if (b.spin.torque_free() || b.pivot != glm::dvec3(0.0)) { // the closed form's terms
        if (!sink_->free_rotation) return;
        ani_free_rotation_segment s = segment(ani_free_rotation_segment{});
        s.w0 = ani(w);
        s.moments = ani(b.spin.moments);
        const glm::dquat &p = b.spin.principal;
        s.principal = ani_quat{p.w, p.x, p.y, p.z};
        s.pivot = ani(b.pivot);
        sink_->free_rotation(sink_->context, &s);
    } else {
        if (!sink_->rotation) return;
        ani_rotation_segment s = segment(ani_rotation_segment{});
        s.w = ani(w);
        sink_->rotation(sink_->context, &s);
    }
}

// A model that `rotates` must be able to: its mesh closed (it turns about its centre of mass,
// which an open mesh has not). physics.custom turns spheres, and any other closed model about its
// centre of mass, as its keys scale it at `t` (where it becomes free): its shape for those.
std::optional<EventBake::TurningShape> EventBake::check_turning(uint32_t i, bool sphere, double t) {
    const ani_physics_model &m = scene_->models[i];
    if (!ANI_MODEL_DESC_HAS_BODY(m.desc) || !m.desc->rotates || !m.desc->dynamics)
        return std::nullopt;
    std::string why;
    if (!m.mesh->is_sphere && !is_closed(*m.mesh, &why))
        throw ani::Failure(ANI_ERR_INVALID_ARGUMENT,
                           std::string("model '") + name_of(m) +
                               "' cannot rotate: its mesh is not closed (" + why +
                               "); turn Rotates off or close the mesh");
    if (sphere) return std::nullopt; // its spin: start_spin
    return turning_shape(i, t);
}

EventBake::TurningShape EventBake::turning_shape(uint32_t i, double t) const {
    const ani_physics_model &m = scene_->models[i];
    const double mass = m.desc->mass;
    if (!(mass > 0.0) || !std::isfinite(mass))
        throw ani::Failure(ANI_ERR_INVALID_ARGUMENT, std::string("model '") + name_of(m) +
                                                         "' needs a finite mass > 0 to rotate");
    TurningShape shape;
    const ani_vec3 s = keyed(i, t, nullptr).scale;
    shape.scale = glm::dmat3(glm::scale(glm::dmat4(1.0), vec(s)));
    std::vector<double> positions;
    for (uint32_t k = 0; k < m.mesh->vertex_count; ++k) {
        const glm::dvec3 p = shape.scale * vertex(*m.mesh, k);
        positions.insert(positions.end(), {p.x, p.y, p.z});
    }
    ani_mesh_view scaled = *m.mesh;
    scaled.positions = positions.data();
    scaled.is_sphere = 0;
    shape.mass = mass_properties(scaled, mass);
    // About its centre of mass, which is its origin to within 1e-9 of its size (a cube centred
    // on its origin turns about it exactly).
    double size = 0.0;
    for (uint32_t k = 0; k < m.mesh->vertex_count; ++k)
        size = std::max(size, glm::length(shape.scale * vertex(*m.mesh, k)));
    if (glm::length(shape.mass.center_of_mass) > 1e-9 * size)
        shape.pivot = shape.mass.center_of_mass;
    for (uint32_t k = 0; k < m.mesh->vertex_count; ++k) {
        const glm::dvec3 p = shape.scale * vertex(*m.mesh, k) - shape.pivot;
        shape.vertices.push_back(p);
        shape.reach = std::max(shape.reach, glm::length(p));
    }
    return shape;
}

// Body b turns from its contacts once free after its last key, with its shape there.
void EventBake::set_turning(Body &b, TurningShape shape) {
    b.turns = true;
    b.turning_vertices = std::move(shape.vertices);
    b.turning_reach = shape.reach;
    b.scale = shape.scale;
    b.pivot = shape.pivot;
    // A spherical top (a cube): one moment about every axis (their mean, equal to rounding);
    // otherwise (a box) it turns without torque as its principal moments and axes say, and so
    // does one turned about a pivot (reported as free-rotation segments, which carry it).
    const glm::dvec3 moments = shape.mass.principal_moments;
    b.inv_inertia = 3.0 / (moments.x + moments.y + moments.z);
    if (moments.z - moments.x > 1e-9 * moments.z || b.pivot != glm::dvec3(0.0)) {
        b.moments = moments;
        b.principal = shape.mass.principal_orientation;
    }
}

} // namespace physics_custom::bake
