#include "event_bake.hpp"

#include "event_queue.hpp"
#include "free_motion.hpp"
#include "grid.hpp"
#include "impulse.hpp"
#include "keyed_contact.hpp"
#include "material.hpp"
#include "mesh_contact.hpp"
#include "mass_properties.hpp"
#include "mesh_distance.hpp"
#include "overlap_memory.hpp"
#include "polynomial.hpp"
#include "response.hpp"
#include "scene_print.hpp"
#include "simultaneous_contact.hpp"
#include "spin.hpp"
#include "time_of_impact.hpp"
#include "turning_contact.hpp"
#include "zeno.hpp"

#include <animator/plugin_cpp.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtx/euler_angles.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iomanip>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace physics_custom {

namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();

glm::dvec3 vec(const ani_vec3 &v) {
    return {v.x, v.y, v.z};
}
ani_vec3 ani(const glm::dvec3 &v) {
    return {v.x, v.y, v.z};
}

const char *name_of(const ani_physics_model &m) {
    return m.desc && m.desc->name ? m.desc->name : "?";
}

// A model that takes part in collisions and moves: a sphere (Dynamics or Gravity on), or any
// model with a mesh while its keys drive it (a moving wall). Over the bake a body is keyed (its
// keys move it), free (a closed-form segment), or waiting (keyed, but with nothing to collide).
struct Body {
    enum class Mode { kKeyed, kFree };
    uint32_t model = 0;
    bool sphere = false; // the seed's sphere special case; otherwise the model's triangles
    double radius = 0.0; // for a sphere: its radius when free
    double reach = 0.0;  // the farthest a vertex is from the model's origin, in model space
    std::vector<std::array<uint32_t, 2>> edges; // not a sphere: its mesh's edges, each once
    bool dynamics = false;
    Mode mode = Mode::kFree;
    bool active = false;      // free and colliding, or keyed and colliding
    double keys_end = kNever; // when its last key passes (then it is free)
    double resume_at =
        kNever;              // released from its keys at a contact: the next key, where they resume
    double keyed_from = 0.0; // start of the current keyed stretch (to report it)
    double t0 = 0.0;         // start of the current free segment
    Path path;               // free: center(t) = path.at(t - t0)
    int motion = ANI_MOTION_FREE;
    uint64_t version =
        0; // counts the changes of path: events predicted against an older one are stale
    bool in_grid = false; // free spheres only
    Cell cell{};
    int ignored_obstacles = 0;    // obstacles it overlapped and does not collide with until apart
    int overlapped_obstacles = 0; // obstacles it overlapped and touches at that depth until apart
    glm::dvec3 free_a{0.0};       // its acceleration when nothing holds it up (gravity, or none)
    // Resting or sliding on a flat part of a static model: that model, the plane of the face
    // (n . x = d), and the boundary of the flat region it is on (edge start, end, and outward
    // normal in the plane), where it leaves the support.
    int support = -1;
    glm::dvec3 support_n{0.0};
    // A model that is not a sphere, free after its last key: its triangles, turned and scaled as
    // its last key left them, relative to its center (the seed's mesh-mesh tests).
    std::shared_ptr<const MeshShape> shape;
    double support_d = 0.0;
    std::vector<std::array<glm::dvec3, 3>> support_edges;
    // Where it touches the support, relative to its center: a sphere's lowest point, or the
    // vertices of a mesh in the support's plane. It leaves the support when all have left it.
    std::vector<glm::dvec3> support_feet;
    double grazed_until = -kNever; // not a sphere: when the obstacles it grazed count again
    Material material;             // restitution, friction, turning (issue 18)
    Spin spin;                  // a free sphere that rotates: its orientation and angular velocity
    double settles_at = kNever; // put on its support by the Zeno rule: the accumulation time
    // A model that is not a sphere and turns from its contacts once free (Rotates on; a
    // spherical top whose centre of mass is its origin, such as a cube; check_turning): its
    // vertices scaled as its keys leave it (about its centre of mass, which its origin is), the
    // farthest of them, its inverse moment of inertia, and its keys' scale, which its turn
    // (spin) is applied after.
    bool turns = false;
    std::vector<glm::dvec3> turning_vertices;
    double turning_reach = 0.0;
    double inv_inertia = 0.0;
    glm::dmat3 scale{1.0};

    bool keyed() const { return mode == Mode::kKeyed; }
    bool free_sphere() const { return sphere && mode == Mode::kFree; }
    // Turning from its contacts now (free after its last key): its pose is its spin's.
    bool turning() const { return turns && spin.on; }
    bool still() const {
        return mode == Mode::kFree &&
               (motion == ANI_MOTION_REST ||
                (path.v == glm::dvec3(0.0) && path.a == glm::dvec3(0.0))) &&
               (!turning() || spin.w == glm::dvec3(0.0));
    }
};

// The triangles of a static model, in world space, with their bounding sphere.
struct Obstacle {
    uint32_t model = 0;
    std::vector<glm::dvec3> corners;        // 3 per triangle
    std::vector<Box> boxes;                 // 1 per triangle
    std::vector<glm::dvec3> normals;        // 1 per triangle, unit (0 for a triangle without area)
    std::vector<double> offsets;            // 1 per triangle: its plane is normal . x = offset
    std::shared_ptr<const MeshShape> shape; // in world space, for the mesh-mesh tests
    // A closed mesh turned inside out: a room, for the models inside it (built when needed).
    mutable std::shared_ptr<const MeshShape> room;
    glm::dvec3 center{0.0};
    double radius = 0.0;
};

// Where a body is and how it is placed at one time: world = center + linear * model-space point.
struct Pose {
    glm::dvec3 center{0.0}, velocity{0.0};
    glm::dmat3 linear{1.0};
};

// A body's earliest predicted event.
enum class EventKind {
    kNone,
    kActivation,
    kResume,
    kBody,
    kObstacle,
    kCell,
    kRelease,
    kRecheck,
    kLeave,
    kSettle
};
struct Predicted {
    double t = kNever;
    EventKind kind = EventKind::kNone;
    int other = -1;             // the other body, or the obstacle
    uint64_t other_version = 0; // the other body's version when predicted
    Contact contact;
    std::vector<glm::dvec3> points; // a turning model's: every point touching with the contact
    Exit exit;                      // for kCell
};

Predicted predicted(double t, EventKind kind, int other = -1, uint64_t other_version = 0,
                    const Contact &contact = {}) {
    Predicted p;
    p.t = t;
    p.kind = kind;
    p.other = other;
    p.other_version = other_version;
    p.contact = contact;
    return p;
}

// Bodies from which on the grid pays for its cell crossings.
constexpr std::size_t kGridFrom = 16;

glm::dmat3 linear_part(const ani_model_state &s) {
    return glm::dmat3(glm::eulerAngleXYZ(glm::radians(s.angles.x), glm::radians(s.angles.y),
                                         glm::radians(s.angles.z))) *
           glm::dmat3(glm::scale(glm::dmat4(1.0), vec(s.scale)));
}

bool uniform(const ani_vec3 &s) {
    return s.x == s.y && s.y == s.z && s.x > 0.0;
}

ani_model_state keyed_state(const ani_physics_scene &scene, uint32_t m, double t,
                            glm::dvec3 *velocity) {
    ani_model_state state{};
    ani_vec3 v{};
    if (scene.evaluate_keyed(scene.host_context, m, t, &state, &v) != ANI_OK)
        throw ani::Failure(ANI_ERR_FAILED, std::string("cannot evaluate the keys of model '") +
                                               name_of(scene.models[m]) + "'");
    if (velocity) *velocity = vec(v);
    return state;
}

double frobenius(const glm::dmat3 &m) {
    double sum = 0.0;
    for (int c = 0; c < 3; ++c) sum += glm::dot(m[c], m[c]);
    return std::sqrt(sum);
}

class EventBake {
  public:
    EventBake(const ani_physics_scene &scene, double t_begin, double t_end,
              const ani_bake_sink &sink, const ani_host *host, const BakeOptions &options,
              OverlapMemory &memory)
        : scene_(&scene), t_begin_(t_begin), t_end_(t_end), sink_(&sink), host_(host),
          options_(options), gravity_(vec(gravity_vector(scene.gravity, scene.down_axis))),
          memory_(memory) {
        memory_.begin(t_begin);
        set_horizon();
    }

    void run() {
        fingerprint_ = scene_print(*scene_);
        classify();
        build_broad_phase();
        queue_ = std::make_unique<EventQueue>(bodies_.size());
        predicted_.assign(bodies_.size(), Predicted{});
        for (size_t i = 0; i < bodies_.size(); ++i)
            if (bodies_[i].active) {
                find_overlaps(static_cast<int>(i), t_begin_);
                try_settle(static_cast<int>(i), t_begin_);
            }
        for (size_t i = 0; i < bodies_.size(); ++i) predict(static_cast<int>(i), t_begin_);
        advance_to_end();
    }

    // Whether a bake of `scene` from t_begin is the next slice of this one: it starts where this
    // one stopped, and the scene is the same (the models, their meshes, physics flags, keyed
    // spans, key times and the states at their keys; gravity). The host rebuilds the scene for
    // every call, and an edit before where the bake stopped makes it bake from earlier.
    bool continues(const ani_physics_scene &scene, double t_begin,
                   const BakeOptions &options) const {
        return t_begin == t_end_ && options.broad_phase == options_.broad_phase &&
               scene_print(scene) == fingerprint_;
    }

    // The next slice, [t_end of the last, t_end]: the events predicted beyond the last slice's
    // end are still valid, so it goes on from them, as one bake would (issue 16: the editor's
    // slices each started over, and redid the predictions and advancements of every body).
    void resume(const ani_physics_scene &scene, double t_end, const ani_bake_sink &sink) {
        scene_ = &scene;
        sink_ = &sink;
        t_begin_ = t_end_;
        t_end_ = t_end;
        set_horizon();
        for (uint32_t i = 0; i < scene_->model_count; ++i)
            if (!is_body_[i]) emit_unmoved(i);
        advance_to_end();
    }

  private:
    // Predictions look past the slice's end (the slices that follow use them): as far again as
    // has been baked, at least 10 s, so that a bake cut into slices predicts a body again only
    // a few times more than one whole bake (each time the baked span doubles).
    void set_horizon() { horizon_ = std::max(horizon_, t_end_ + std::max(10.0, t_end_)); }

    // Processes the events up to t_end and reports every body's motion to t_end.
    void advance_to_end() {
        std::size_t events_at_once = 0;
        double last_event = -kNever;
        while (!bodies_.empty() && queue_->top_time() <= t_end_) {
            const int i = static_cast<int>(queue_->top());
            const Predicted event = predicted_[static_cast<size_t>(i)];
            const double now = event.t;
            events_at_once = now == last_event ? events_at_once + 1 : 0;
            last_event = now;
            if (events_at_once > 100000 + 10 * bodies_.size())
                throw ani::Failure(ANI_ERR_FAILED,
                                   "models keep colliding at t = " + std::to_string(now) +
                                       " s without moving apart");
            handle(i, event, now);
            if (sink_->progress && ++reports_ % 1024 == 0 &&
                !sink_->progress(sink_->context,
                                 (now - t_begin_) / std::max(t_end_ - t_begin_, 1e-300)))
                throw ani::Failure(ANI_ERR_CANCELLED, "the bake was cancelled");
        }
        for (Body &b : bodies_) {
            if (b.keyed())
                emit_keyed(b.model, b.keyed_from, t_end_);
            else if (b.active)
                close_segment(b, t_end_);
            if (b.spin.on) emit_spin(b, t_end_);
        }
        report_counts();
    }

    // Sorts the models: static ones with a mesh are obstacles; spheres that can move and models
    // with a mesh that are keyed during the bake are bodies; the rest (jointed parts, models
    // without a mesh, free models that are not spheres) move without collisions.
    void classify() {
        for (uint32_t i = 0; i < scene_->model_count; ++i) {
            const ani_physics_model &m = scene_->models[i];
            if (!m.desc) throw ani::Failure(ANI_ERR_INVALID_ARGUMENT, "a model has no description");
            const ani_time_span span =
                m.keyed_span_count ? m.keyed_spans[0] : ani_time_span{t_begin_, t_begin_};
            const double keyed_until = std::min(std::max(span.end, t_begin_), t_end_);
            const bool free_now = span.end <= t_begin_;
            // A model released from its keys in an earlier bake is still free where that bake
            // left it (the host's cache says so), until its next key.
            const bool released = !free_now && m.start.motion != ANI_MOTION_KEYED;
            const ani_model_desc &d = *m.desc;
            const Material material = material_of(d); // refuses values out of range
            const bool movable = d.dynamics || d.gravity;
            const bool solid = m.mesh && m.mesh->triangle_count > 0 && m.group == i;
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
            const std::optional<double> radius =
                sphere_radius(i, free_now ? t_begin_ : keyed_until);
            if (solid && (movable || keyed_here)) {
                const bool turns =
                    check_turning(i, radius.has_value(), free_now ? t_begin_ : span.end);
                is_body_.back() = true;
                Body b;
                b.model = i;
                b.sphere = radius.has_value();
                b.radius = radius.value_or(0.0);
                b.reach = mesh_reach(*m.mesh);
                if (!b.sphere) b.edges = edges_of(m.mesh->triangles, m.mesh->triangle_count);
                b.dynamics = d.dynamics != 0;
                b.material = material;
                b.keys_end = free_now ? t_begin_ : span.end;
                if (turns) set_turning(b, b.keys_end);
                bodies_.push_back(b);
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
                body.path.p = body.keyed() ? vec(keyed_state(*scene_, i, t_begin_, nullptr).center)
                                           : body.path.p;

                continue;
            }
            emit_unmoved(i);
        }
    }

    // The motion of a model that is not a body over [t_begin, t_end] (in every slice of a bake):
    // a static model held by its keys, then at rest; any other model keyed, then free without
    // collisions.
    void emit_unmoved(uint32_t i) {
        const ani_physics_model &m = scene_->models[i];
        const ani_time_span span =
            m.keyed_span_count ? m.keyed_spans[0] : ani_time_span{t_begin_, t_begin_};
        const double keyed_until = std::min(std::max(span.end, t_begin_), t_end_);
        const bool free_now = span.end <= t_begin_;
        if (keyed_until > t_begin_) emit_keyed(i, t_begin_, keyed_until);
        if (!(free_now || span.end < t_end_)) return; // keyed throughout this slice
        emit_free(i, start_of(i, free_now ? t_begin_ : keyed_until),
                  free_now ? t_begin_ : keyed_until);
    }

    // Whether a model's keys from t_begin to its last key all place it the same way and leave it
    // still (checked at each key and half-way between keys).
    bool keys_hold_still(uint32_t i, double last) const {
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
        const ani_model_state first = keyed_state(*scene_, i, t_begin_, &v0);
        auto same = [](const ani_vec3 &a, const ani_vec3 &b) {
            return a.x == b.x && a.y == b.y && a.z == b.z;
        };
        for (double t : times) {
            glm::dvec3 v;
            const ani_model_state s = keyed_state(*scene_, i, t, &v);
            if (v != glm::dvec3(0.0) || !same(s.center, first.center) ||
                !same(s.angles, first.angles) || !same(s.scale, first.scale))
                return false;
        }
        return true;
    }

    // The state a model is in at t: the host's cache where a resumed bake starts, otherwise its
    // keys' (physics.md: where and how fast it leaves them).
    ani_body_state start_of(uint32_t i, double t) {
        const ani_physics_model &m = scene_->models[i];
        if (t == t_begin_ && m.start.motion != ANI_MOTION_KEYED) return m.start;
        return leaving_keys(i, t);
    }

    // The first of the model's keys after t (the end of its keys if none is in between).
    double next_key(uint32_t i, double t) const {
        const ani_physics_model &m = scene_->models[i];
        if (m.struct_size >= offsetof(ani_physics_model, key_count) + sizeof(m.key_count) &&
            m.key_times)
            for (uint32_t k = 0; k < m.key_count; ++k)
                if (m.key_times[k] > t) return m.key_times[k];
        return m.keyed_span_count ? m.keyed_spans[0].end : t;
    }

    std::optional<double> sphere_radius(uint32_t i, double t) {
        const ani_physics_model &m = scene_->models[i];
        if (!m.mesh || !m.mesh->is_sphere) return std::nullopt;
        if (glm::length(vec(m.mesh->bound_center)) > 1e-9 * m.mesh->bound_radius)
            return std::nullopt;
        const ani_model_state s = keyed_state(*scene_, i, t, nullptr);
        if (!uniform(s.scale)) return std::nullopt;
        return m.mesh->bound_radius * s.scale.x;
    }

    void add_obstacle(uint32_t i, double t) {
        const ani_mesh_view &mesh = *scene_->models[i].mesh;
        const ani_model_state state = keyed_state(*scene_, i, t, nullptr);
        const glm::dmat3 linear = linear_part(state);
        Obstacle o;
        o.model = i;
        for (uint32_t k = 0; k < 3 * mesh.triangle_count; ++k) {
            const double *p = mesh.positions + 3 * static_cast<size_t>(mesh.triangles[k]);
            o.corners.push_back(vec(state.center) + linear * glm::dvec3(p[0], p[1], p[2]));
        }
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
        if (!o.boxes.empty() &&
            std::all_of(o.normals.begin(), o.normals.end(),
                        [](const glm::dvec3 &n) { return n == glm::dvec3(0.0); }))
            throw ani::Failure(ANI_ERR_INVALID_ARGUMENT,
                               std::string("model '") + name_of(scene_->models[i]) +
                                   "' has a mesh without area (every triangle is degenerate)");
        glm::dvec3 sum(0.0);
        for (const auto &c : o.corners) sum += c;
        o.center =
            o.corners.empty() ? glm::dvec3(0.0) : sum / static_cast<double>(o.corners.size());
        for (const auto &c : o.corners) o.radius = std::max(o.radius, glm::length(c - o.center));
        o.shape = build_shape(i, state.center, linear, glm::dvec3(0.0));
        triangle_count_ += o.boxes.size();
        obstacles_.push_back(std::move(o));
    }

    // Model i's triangles as a MeshShape: model-space vertices turned and scaled by `linear`,
    // relative to `origin` (its center for a body, the world's origin for an obstacle).
    std::shared_ptr<const MeshShape> build_shape(uint32_t i, const ani_vec3 &center,
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
            throw ani::Failure(ANI_ERR_INVALID_ARGUMENT, std::string("model '") +
                                                             name_of(scene_->models[i]) +
                                                             "': " + e.what());
        }
    }

    // With many bodies, a grid over the region where they start and the obstacles are; free
    // spheres that leave it, keyed bodies and meshes are tested against every body. With few,
    // every body is tested against every other (the grid's crossings would cost more than they
    // save).
    void build_broad_phase() {
        if (bodies_.empty() || options_.broad_phase == BroadPhase::kAllPairs ||
            (options_.broad_phase == BroadPhase::kAutomatic && bodies_.size() < kGridFrom))
            return;
        double widest = 0.0;
        Box region{bodies_[0].path.p, bodies_[0].path.p};
        for (const Body &b : bodies_) {
            if (!b.sphere) continue;
            widest = std::max(widest, 2.0 * b.radius);
            region.lo = glm::min(region.lo, b.path.p);
            region.hi = glm::max(region.hi, b.path.p);
        }
        if (!(widest > 0.0)) return;
        for (const Obstacle &o : obstacles_)
            for (const Box &box : o.boxes) {
                region.lo = glm::min(region.lo, box.lo);
                region.hi = glm::max(region.hi, box.hi);
            }
        // A little wider than the largest sphere, so rounding at a wall cannot hide a contact.
        const double cell = widest * (1.0 + 1e-6);
        region.lo -= glm::dvec3(cell);
        region.hi += glm::dvec3(cell);
        grid_ = std::make_unique<UniformGrid>(region, cell);
        for (size_t i = 0; i < bodies_.size(); ++i)
            if (bodies_[i].active) file(static_cast<int>(i), t_begin_);
    }

    // Files an active body: a free sphere under its cell, any other among the bodies outside
    // the grid.
    void file(int i, double t) {
        Body &b = bodies_[static_cast<size_t>(i)];
        if (grid_ && b.free_sphere()) {
            b.cell = grid_->cell_of(b.path.at(t - b.t0));
            b.in_grid = grid_->inside(b.cell);
            if (b.in_grid) {
                grid_->insert(static_cast<uint32_t>(i), b.cell);
                return;
            }
        }
        outside_.push_back(i);
    }

    void unfile(int i) {
        Body &b = bodies_[static_cast<size_t>(i)];
        if (b.in_grid) {
            grid_->remove(static_cast<uint32_t>(i), b.cell);
            b.in_grid = false;
            return;
        }
        const auto at = std::find(outside_.begin(), outside_.end(), i);
        if (at != outside_.end()) outside_.erase(at);
    }

    // Free from t with the given state: the closed form of physics.md's four cases.
    void activate(Body &b, double t, const ani_body_state &start) {
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
        b.support_edges.clear();
        b.settles_at = kNever;
        start_spin(b, t);
        b.shape.reset();
        if (!b.sphere && !b.turns && t >= b.keys_end) { // its keys no longer turn or scale it
            const ani_model_state state = keyed_state(*scene_, b.model, t, nullptr);
            b.shape =
                build_shape(b.model, ani(glm::dvec3(0.0)), linear_part(state), glm::dvec3(0.0));
        }
        ++b.version;
    }

    // Without Dynamics, a model released from its keys rests where the contact left it.
    static void stop(Body &b) {
        b.path = Path{b.path.p, glm::dvec3(0.0), glm::dvec3(0.0)};
        b.free_a = glm::dvec3(0.0);
        b.motion = ANI_MOTION_REST;
    }

    // The state a model leaves its keys with at time t (physics.md: where and how fast).
    ani_body_state leaving_keys(uint32_t i, double t) {
        glm::dvec3 v;
        const ani_model_state s = keyed_state(*scene_, i, t, &v);
        ani_body_state state{};
        state.motion = ANI_MOTION_KEYED;
        state.center = s.center;
        state.velocity = ani(v);
        return state;
    }

    void emit(const ani_motion_segment &s) {
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
    void emit_keyed(uint32_t i, double t0, double t1) {
        t0 = std::max(t0, t_begin_);
        if (!(t1 > t0)) return;
        ani_motion_segment s{};
        s.model = i;
        s.motion = ANI_MOTION_KEYED;
        s.t0 = t0;
        s.t1 = t1;
        emit(s);
    }

    void emit_free(uint32_t i, const ani_body_state &start, double free_at) {
        if (free_at >= t_end_) return;
        emit(free_segment(i, *scene_->models[i].desc, start, free_at, t_end_, ani(gravity_)));
    }

    // Reports a body's free segment up to t: from where it started, or from where this slice
    // starts for a segment that began in an earlier slice (which reported its part).
    void close_segment(Body &b, double t) {
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

    void restart(Body &b, double t, const glm::dvec3 &velocity, bool stop) {
        close_segment(b, t);
        const glm::dvec3 p = b.path.at(t - b.t0);
        b.t0 = t;
        b.path = stop ? Path{p, glm::dvec3(0.0), glm::dvec3(0.0)} : Path{p, velocity, b.path.a};
        b.motion = stop ? ANI_MOTION_REST : ANI_MOTION_FREE;
        b.settles_at = kNever;
        ++b.version;
    }

    // ---- where bodies are ------------------------------------------------------------------

    // The path of a free body from `now`, for time-of-impact queries over [0, t_end - now].
    Path from_now(const Body &b, double now) const {
        return Path{b.path.at(now - b.t0), b.path.velocity(now - b.t0), b.path.a};
    }

    // A body's pose at t: its keys', or its free path's center with its keys' rotation and
    // scale (which always come from the keys).
    Pose pose(const Body &b, double t) const {
        glm::dvec3 v;
        const ani_model_state s = keyed_state(*scene_, b.model, t, &v);
        Pose p;
        p.linear = b.turning() ? glm::dmat3(glm::mat3_cast(b.spin.at(t))) * b.scale
                               : linear_part(s);
        if (b.keyed()) {
            p.center = vec(s.center);
            p.velocity = v;
        } else {
            p.center = b.path.at(t - b.t0);
            p.velocity = b.path.velocity(t - b.t0);
        }
        return p;
    }

    const ani_mesh_view &mesh_of(const Body &b) const { return *scene_->models[b.model].mesh; }

    glm::dvec3 vertex(const ani_mesh_view &mesh, uint32_t k) const {
        const double *p = mesh.positions + 3 * static_cast<size_t>(k);
        return {p[0], p[1], p[2]};
    }

    // A body's triangles where its pose puts them, for mesh distances.
    PlacedMesh placed(const Body &b, const Pose &p) const {
        const ani_mesh_view &mesh = mesh_of(b);
        PlacedMesh out{p.center,      {}, mesh.triangles, mesh.triangle_count, b.edges.data(),
                       b.edges.size()};
        out.vertices.reserve(mesh.vertex_count);
        for (uint32_t k = 0; k < mesh.vertex_count; ++k)
            out.vertices.push_back(p.center + p.linear * vertex(mesh, k));
        return out;
    }

    static PlacedMesh placed(const Obstacle &o) {
        return {o.center,
                o.shape->vertices,
                o.shape->triangles.empty() ? nullptr : &o.shape->triangles[0][0],
                o.shape->triangles.size(),
                o.shape->edges.data(),
                o.shape->edges.size()};
    }

    // The farthest a vertex of the mesh is from the model's origin, in model space.
    static double mesh_reach(const ani_mesh_view &mesh) {
        double r = 0.0;
        for (uint32_t k = 0; k < mesh.vertex_count; ++k) {
            const double *p = mesh.positions + 3 * static_cast<size_t>(k);
            r = std::max(r, glm::length(glm::dvec3(p[0], p[1], p[2])));
        }
        return r;
    }

    // The nearest point of a mesh body (at pose p) to q.
    glm::dvec3 nearest_on_mesh(const Body &b, const Pose &p, const glm::dvec3 &q) const {
        const ani_mesh_view &mesh = mesh_of(b);
        glm::dvec3 best = p.center;
        double best_d = kNever;
        for (uint32_t k = 0; k < mesh.triangle_count; ++k) {
            const uint32_t *tri = mesh.triangles + 3 * static_cast<size_t>(k);
            const glm::dvec3 c =
                closest_point_on_triangle(q, p.center + p.linear * vertex(mesh, tri[0]),
                                          p.center + p.linear * vertex(mesh, tri[1]),
                                          p.center + p.linear * vertex(mesh, tri[2]));
            const double d = glm::length(q - c);
            if (d < best_d) {
                best_d = d;
                best = c;
            }
        }
        return best;
    }

    glm::dvec3 nearest_on_obstacle(const Obstacle &o, const glm::dvec3 &q) const {
        glm::dvec3 best = o.center;
        double best_d = kNever;
        for (size_t k = 0; k + 2 < o.corners.size(); k += 3) {
            const glm::dvec3 c =
                closest_point_on_triangle(q, o.corners[k], o.corners[k + 1], o.corners[k + 2]);
            const double d = glm::length(q - c);
            if (d < best_d) {
                best_d = d;
                best = c;
            }
        }
        return best;
    }

    // How fast any point of a body can move around time t, from its pose and one a moment
    // later (the speed of its center plus the rate of its rotation and scale times its reach).
    double point_speed(const Body &b, double t, double dt) const {
        if (b.free_sphere())
            return glm::length(b.path.velocity(t - b.t0)) + glm::length(b.path.a) * dt;
        if (b.turning()) // its centre's speed, and |w| times its reach from its centre of mass
            return glm::length(b.path.velocity(t - b.t0)) + glm::length(b.path.a) * dt +
                   glm::length(b.spin.w) * b.turning_reach;
        const double h = std::max(1e-6, dt);
        const Pose p = pose(b, t), q = pose(b, t + h);
        const double reach = b.sphere ? 0.0 : b.reach;
        const double turning = frobenius(q.linear - p.linear) / h * reach;
        const double speed = std::max(glm::length(p.velocity), glm::length(q.velocity)) + turning;
        // Keyed motion is known only by evaluation: a margin for its changes within the step.
        return b.keyed() ? 1.5 * speed + 1e-12 : speed + glm::length(b.path.a) * dt;
    }

    // The velocity of the material point of body b at `point` at time t (a keyed model turning
    // or scaling moves each of its points differently).
    glm::dvec3 point_velocity(const Body &b, const glm::dvec3 &point, double t) const {
        if (b.turning())
            return b.path.velocity(t - b.t0) + glm::cross(b.spin.w, point - b.path.at(t - b.t0));
        if (!b.keyed()) return b.path.velocity(t - b.t0); // free: it translates
        const Pose p = pose(b, t);
        if (b.sphere) return p.velocity;
        const glm::dvec3 local = glm::inverse(p.linear) * (point - p.center);
        const double h = 1e-6 * std::max(1.0, std::abs(t));
        const Pose before = pose(b, t - h), after = pose(b, t + h);
        return ((after.center + after.linear * local) - (before.center + before.linear * local)) /
               (2.0 * h);
    }

    // ---- overlaps at the start -------------------------------------------------------------

    double gap_between(const Body &a, const Body &b, double t, Contact *contact = nullptr) const {
        if (!a.sphere && !b.sphere) return mesh_gap(a, b, t, contact);
        const Body &s = a.sphere ? a : b, &o = a.sphere ? b : a;
        const Pose ps = pose(s, t), po = pose(o, t);
        glm::dvec3 nearest;
        double gap;
        const double rs = radius_at(s, ps);
        if (o.sphere) {
            const double ro = radius_at(o, po);
            nearest = po.center + (glm::length(ps.center - po.center) > 0.0
                                       ? glm::normalize(ps.center - po.center) * ro
                                       : glm::dvec3(0.0));
            gap = glm::length(ps.center - po.center) - rs - ro;
        } else {
            const double reach = o.reach * frobenius(po.linear);
            const double far = glm::length(ps.center - po.center) - rs - reach;
            // While far apart, the bounding spheres' gap is a lower bound that is enough.
            if (far > 0.25 * (rs + reach) && !contact) return far;
            nearest = nearest_on_mesh(o, po, ps.center);
            gap = glm::length(ps.center - nearest) - rs;
        }
        if (contact) {
            glm::dvec3 n = ps.center - nearest;
            n = glm::length(n) > 0.0 ? glm::normalize(n) : glm::dvec3(0, 1, 0);
            if (&s != &a) n = -n; // from b towards a
            contact->normal = n;
            contact->point = nearest;
            contact->t = t;
        }
        return gap;
    }

    // Two models that are not spheres: the distance between their surfaces.
    double mesh_gap(const Body &a, const Body &b, double t, Contact *contact) const {
        const Pose pa = pose(a, t), pb = pose(b, t);
        const double ra = a.reach * frobenius(pa.linear), rb = b.reach * frobenius(pb.linear);
        const double far = glm::length(pa.center - pb.center) - ra - rb;
        if (far > 0.25 * (ra + rb) && !contact) return far;
        glm::dvec3 on_a, on_b, n;
        const double gap = mesh_distance(placed(a, pa), placed(b, pb), on_a, on_b, n);
        if (contact) fill_contact(on_a, on_b, n, t, contact);
        return gap;
    }

    static void fill_contact(const glm::dvec3 &on_a, const glm::dvec3 &on_b, const glm::dvec3 &n,
                             double t, Contact *contact) {
        contact->normal = n;
        contact->point = 0.5 * (on_a + on_b);
        contact->t = t;
    }

    double gap_to_obstacle(const Body &b, const Obstacle &o, double t,
                           Contact *contact = nullptr) const {
        const Pose p = pose(b, t);
        if (!b.sphere) {
            const double reach = b.reach * frobenius(p.linear);
            const double far = glm::length(p.center - o.center) - reach - o.radius;
            if (far > 0.25 * (reach + o.radius) && !contact) return far;
            glm::dvec3 on_a, on_b, n;
            const double gap = mesh_distance(placed(b, p), placed(o), on_a, on_b, n);
            if (contact) fill_contact(on_a, on_b, n, t, contact);
            return gap;
        }
        const glm::dvec3 c = p.center;
        const double r = radius_at(b, p);
        const double far = glm::length(c - o.center) - r - o.radius;
        if (far > 0.25 * (r + o.radius) && !contact) return far;
        const glm::dvec3 nearest = nearest_on_obstacle(o, c);
        if (contact) {
            const glm::dvec3 n = c - nearest;
            contact->normal = glm::length(n) > 0.0 ? glm::normalize(n) : glm::dvec3(0, 1, 0);
            contact->point = nearest;
            contact->t = t;
        }
        return glm::length(c - nearest) - r;
    }

    // A sphere's radius at a pose: a keyed sphere's scale may change under its keys.
    double radius_at(const Body &b, const Pose &p) const {
        if (!b.keyed()) return b.radius;
        return scene_->models[b.model].mesh->bound_radius * frobenius(p.linear) / std::sqrt(3.0);
    }

    // Whether a sphere is closer to an obstacle than `gap` (negative: overlapping by more).
    bool within_obstacle(const Body &b, const Obstacle &o, double t, double gap) const {
        if (!b.sphere) return false;
        if (b.free_sphere()) {
            const glm::dvec3 c = b.path.at(t - b.t0);
            if (glm::length(c - o.center) > b.radius + o.radius + gap) return false;
            for (size_t k = 0; k + 2 < o.corners.size(); k += 3)
                if (glm::length(c - closest_point_on_triangle(c, o.corners[k], o.corners[k + 1],
                                                              o.corners[k + 2])) < b.radius + gap)
                    return true;
            return false;
        }
        return gap_to_obstacle(b, o, t) < gap;
    }

    bool within_body(const Body &a, const Body &b, double t, double gap) const {
        if (!a.sphere && !b.sphere) return false;
        if (a.free_sphere() && b.free_sphere())
            return glm::length(a.path.at(t - a.t0) - b.path.at(t - b.t0)) <
                   a.radius + b.radius + gap;
        return gap_between(a, b, t) < gap;
    }

    // Overlapping: closer than touching (which allows for the single precision of meshes).
    bool overlaps_obstacle(const Body &b, const Obstacle &o, double t) const {
        return within_obstacle(b, o, t, -touching(b));
    }
    bool overlaps_body(const Body &a, const Body &b, double t) const {
        return within_body(a, b, t, -touching(a) - touching(b));
    }
    // Apart: farther than touching, so that a pair left alone is not met again at once.
    bool apart_from_obstacle(const Body &b, const Obstacle &o, double t) const {
        // A model that is not a sphere has no distance to an obstacle here: the pair it grazed
        // is left alone while it moves a quarter of its size.
        if (!b.sphere) return t >= b.grazed_until;
        return !within_obstacle(b, o, t, touching(b));
    }
    bool apart_from_body(const Body &a, const Body &b, double t) const {
        return !within_body(a, b, t, touching(a) + touching(b));
    }

    // A contact met with no speed along its normal (a sphere rolling over the rim of a table,
    // grazing an edge) is not a collision: reflecting would change nothing and find the same
    // contact again at once. The pair is left alone until they are apart.
    static bool grazing(const glm::dvec3 &relative_velocity, const glm::dvec3 &n) {
        return -glm::dot(relative_velocity, n) <=
               1e-9 * std::max(1.0, glm::length(relative_velocity));
    }

    // Meshes are read in single precision, so a sphere placed on a face can be inside it by a
    // few 1e-8 of its radius: that much is touching, not overlapping.
    static double touching(const Body &b) { return 1e-6 * b.radius; }

    // How close counts as touching for conservative advancement: a trillionth of the size.
    static double tolerance(const Body &b) {
        return 1e-12 * std::max(1.0, b.sphere ? b.radius : b.reach);
    }

    // Calls f(j) for every active body that body i could meet: its grid neighbours and the
    // bodies outside the grid, or every body when i itself is outside.
    template <class F> void for_candidates(int i, F &&f) const {
        const Body &b = bodies_[static_cast<size_t>(i)];
        if (b.in_grid) {
            grid_->for_neighbours(b.cell, [&](uint32_t j) {
                if (static_cast<int>(j) != i) f(static_cast<int>(j));
            });
            for (int j : outside_)
                if (j != i) f(j);
        } else {
            for (size_t j = 0; j < bodies_.size(); ++j)
                if (static_cast<int>(j) != i && bodies_[j].active) f(static_cast<int>(j));
        }
    }

    // ---- pairs that overlap when they start to collide (physics.md) -------------------------

    // An overlap found: the contact there (the normal from the other towards the body) and how
    // deep they are into each other along it.
    struct Seen {
        Contact contact;
        double depth = 0.0;
    };

    // Finds the pairs with body i that overlap at t (at the start, when i becomes free inside
    // another, or when its keys take it back inside one) and treats each as touching.
    void find_overlaps(int i, double t) {
        for (size_t o = 0; o < obstacles_.size(); ++o) {
            const int other = -1 - static_cast<int>(o);
            if (is_overlapped(i, other) || is_ignored(i, other)) continue;
            if (auto seen =
                    overlap_with_obstacle(bodies_[static_cast<size_t>(i)], obstacles_[o], t))
                meet_overlap(i, other, *seen, t);
        }
        // Collected first: a collision refiles the bodies it moves.
        std::vector<std::pair<int, Seen>> found;
        for_candidates(i, [&](int j) {
            if (is_overlapped(i, j) || is_ignored(i, j)) return;
            const Body &b = bodies_[static_cast<size_t>(i)], &o = bodies_[static_cast<size_t>(j)];
            if (!overlaps_body(b, o, t)) return;
            Seen seen;
            seen.depth = -gap_between(b, o, t, &seen.contact);
            found.emplace_back(j, seen);
        });
        for (const auto &[j, seen] : found)
            if (!is_overlapped(i, j) && !is_ignored(i, j)) meet_overlap(i, j, seen, t);
    }

    // Whether body b overlaps obstacle o at t. A sphere: closer to it than its radius, the normal
    // from its nearest point towards the sphere's center. Any other mesh: their surfaces cross
    // (an edge of one passes through a face of the other, beyond what single precision allows;
    // a mesh wholly inside another is not seen). Its depth and normal then come from planes: the
    // plane through the obstacle's point nearest to the body's center, facing that center (a
    // floor's plane, for a box sunk into it), has vertices of the body behind it, and the plane
    // through the body's point nearest to the obstacle's center vertices of the obstacle; the
    // lesser depth of the two, with that side's normal.
    std::optional<Seen> overlap_with_obstacle(const Body &b, const Obstacle &o, double t) const {
        Seen seen;
        if (b.sphere) {
            if (!overlaps_obstacle(b, o, t)) return std::nullopt;
            seen.depth = -gap_to_obstacle(b, o, t, &seen.contact);
            return seen;
        }
        const Pose p = pose(b, t);
        const double reach = b.reach * frobenius(p.linear);
        if (glm::length(p.center - o.center) > reach + o.radius) return std::nullopt;
        const double touching = 1e-6 * reach; // single-precision meshes
        const PlacedMesh body = placed(b, p);
        if (!surfaces_cross(body, placed(o), touching)) return std::nullopt;
        // How deep the vertices of one are behind the plane of the other's point nearest to q.
        auto behind = [](const std::vector<glm::dvec3> &vertices, const glm::dvec3 &q,
                         const glm::dvec3 &nearest, glm::dvec3 &n) {
            if (!(glm::length(q - nearest) > 0.0)) return -kNever;
            n = glm::normalize(q - nearest);
            double depth = -kNever;
            for (const glm::dvec3 &v : vertices) depth = std::max(depth, glm::dot(n, nearest - v));
            return depth;
        };
        const glm::dvec3 on_obstacle = nearest_on_obstacle(o, p.center);
        const glm::dvec3 on_body = nearest_on_mesh(b, p, o.center);
        glm::dvec3 n_body(0.0), n_obstacle(0.0);
        const double body_depth = behind(body.vertices, p.center, on_obstacle, n_body);
        const double obstacle_depth = behind(o.shape->vertices, o.center, on_body, n_obstacle);
        if (!(body_depth > 0.0) && !(obstacle_depth > 0.0)) return std::nullopt;
        const bool body_side =
            body_depth > 0.0 && (!(obstacle_depth > 0.0) || body_depth <= obstacle_depth);
        seen.contact.normal = body_side ? n_body : -n_obstacle;
        seen.contact.point = body_side ? on_obstacle : on_body;
        seen.contact.t = t;
        seen.depth = body_side ? body_depth : obstacle_depth;
        return seen;
    }

    // An overlapping pair is touching (physics.md): neither moves deeper into the other. Spheres
    // touch at the distance they have now, a mesh touches a static model moved back by its
    // depth along the normal, until they are apart; other pairs (keyed models) are left alone
    // until apart. Along the normal, approaching, they collide at once; pulled into each other
    // with no speed, a model with Dynamics rests on a static model and one without stops; moving
    // apart, they are let go. Said once per bake, naming both.
    void meet_overlap(int i, int other, const Seen &seen, double t) {
        Body &b = bodies_[static_cast<size_t>(i)];
        const uint32_t model_b = model_of(other);
        if (const OverlapRecord *earlier = memory_.active(b.model, model_b, t)) {
            // Found by an earlier slice of this bake: treated as it was then.
            treat_as_touching(i, other, *earlier);
            return;
        }
        const Body *o = other >= 0 ? &bodies_[static_cast<size_t>(other)] : nullptr;
        const glm::dvec3 n = seen.contact.normal;
        OverlapRecord record;
        record.model_a = b.model;
        record.model_b = model_b;
        record.since = t;
        // A model its keys drive (at the start, or put back inside another at its next key) is
        // where its keys say: the pair is left alone until apart.
        const bool keyed = b.keyed() || (o && o->keyed());
        if (keyed) {
            report_overlap(i, other, t, seen.depth, seen.contact.normal);
            memory_.add(record);
            treat_as_touching(i, other, record);
            return;
        }
        if (!o && b.free_sphere()) {
            record.kind = OverlapRecord::Kind::kContactDistance;
            record.contact = b.radius - seen.depth;
        } else if (o && b.free_sphere() && o->free_sphere()) {
            record.kind = OverlapRecord::Kind::kContactDistance;
            record.contact = b.radius + o->radius - seen.depth;
        } else if (!o && b.shape) {
            record.kind = OverlapRecord::Kind::kShift;
            record.shift = seen.depth * n;
        }
        if (record.kind == OverlapRecord::Kind::kContactDistance && !(record.contact > 0.0))
            record.kind = OverlapRecord::Kind::kIgnored; // concentric: no direction to touch in
        report_overlap(i, other, t, seen.depth, seen.contact.normal);
        memory_.add(record);
        treat_as_touching(i, other, record);

        const glm::dvec3 point = seen.contact.point;
        const glm::dvec3 relative =
            point_velocity(b, point, t) - (o ? point_velocity(*o, point, t) : glm::dvec3(0.0));
        const glm::dvec3 pull = acceleration(b) - (o ? acceleration(*o) : glm::dvec3(0.0));
        const double along = glm::dot(relative, n);
        const double still = 1e-9 * std::max(1.0, glm::length(relative));
        if (along < -still) { // approaching: the collision they would have had on touching
            if (o) {
                collide_bodies(i, other, seen.contact, t);
                if (predicted_.size() == bodies_.size()) predict(other, t);
            } else {
                collide_obstacle(i, obstacles_[static_cast<size_t>(-1 - other)], seen.contact, {},
                                 t);
            }
        } else if (along <= still && glm::dot(pull, n) < 0.0 && !o) {
            // Pressed into a static model with no speed: held where it is.
            if (!b.dynamics)
                restart(b, t, glm::dvec3(0.0), true); // without Dynamics it stops at a contact
            else if (b.sphere)
                try_settle(i, t);
            else
                settle_on(i, -1 - other, n, t);
        }
    }

    void treat_as_touching(int i, int other, const OverlapRecord &record) {
        if (record.kind == OverlapRecord::Kind::kIgnored) {
            ignore(i, other, record.since);
            return;
        }
        if (overlaps_.emplace(pair_key(i, other), record).second && other < 0)
            ++bodies_[static_cast<size_t>(i)].overlapped_obstacles;
    }

    // `normal` points from the other towards body i.
    void report_overlap(int i, int other, double t, double depth, const glm::dvec3 &normal) {
        const uint32_t a = bodies_[static_cast<size_t>(i)].model, b = model_of(other);
        if (memory_.reported_before(a, b, t) || !reported_.insert(pair_key(i, other)).second)
            return;
        const bool finite = std::isfinite(depth) && std::isfinite(normal.x) &&
                            std::isfinite(normal.y) && std::isfinite(normal.z);
        if (sink_->overlap && finite) {
            ani_overlap o{};
            o.t = t;
            o.a = a;
            o.b = b;
            o.normal = ani_vec3{normal.x, normal.y, normal.z};
            o.depth = depth;
            sink_->overlap(sink_->context, &o);
        }
        log_warning("models '" + std::string(name_of(scene_->models[a])) + "' and '" +
                    name_of(scene_->models[b]) + "' overlap at t = " + short_number(t) + " s by " +
                    short_number(depth) +
                    " m: treated as touching (neither moves deeper into the other; approaching, "
                    "they collide at once; moving apart, they are let go)");
    }

    static std::string short_number(double x) {
        std::ostringstream out;
        out << std::setprecision(4) << (std::abs(x) < 1e-12 ? 0.0 : x);
        return out.str();
    }

    uint32_t model_of(int other) const {
        return other >= 0 ? bodies_[static_cast<size_t>(other)].model
                          : obstacles_[static_cast<size_t>(-1 - other)].model;
    }

    // The acceleration a body has now: its path's, or none under its keys.
    static glm::dvec3 acceleration(const Body &b) { return b.keyed() ? glm::dvec3(0.0) : b.path.a; }

    bool is_overlapped(int a, int b) const {
        return !overlaps_.empty() && overlaps_.count(pair_key(a, b));
    }

    const OverlapRecord *overlap_of(int a, int b) const {
        if (overlaps_.empty()) return nullptr;
        const auto it = overlaps_.find(pair_key(a, b));
        return it == overlaps_.end() ? nullptr : &it->second;
    }

    // The radius a free sphere touches obstacle o with: its own, or less while it overlaps it.
    double radius_against(int i, int o) const {
        const Body &b = bodies_[static_cast<size_t>(i)];
        if (b.overlapped_obstacles == 0) return b.radius;
        const OverlapRecord *r = overlap_of(i, -1 - o);
        return r && r->kind == OverlapRecord::Kind::kContactDistance
                   ? std::min(b.radius, r->contact)
                   : b.radius;
    }

    // How far a mesh body is moved for its tests against obstacle o while it overlaps it.
    glm::dvec3 shift_against(int i, int o) const {
        const OverlapRecord *r = bodies_[static_cast<size_t>(i)].overlapped_obstacles > 0
                                     ? overlap_of(i, -1 - o)
                                     : nullptr;
        return r && r->kind == OverlapRecord::Kind::kShift ? r->shift : glm::dvec3(0.0);
    }

    // Two free spheres that overlapped touch at the distance they had: their radii, scaled.
    void radii_against(int i, int j, double &ri, double &rj) const {
        const OverlapRecord *r = overlap_of(i, j);
        if (!r || r->kind != OverlapRecord::Kind::kContactDistance) return;
        const double scale = std::min(1.0, r->contact / (ri + rj));
        ri *= scale;
        rj *= scale;
    }

    // Whether a body that overlapped obstacle o is apart from it now (then the pair is as any).
    bool apart_after_overlap(int i, int o, double t) const {
        const Body &b = bodies_[static_cast<size_t>(i)];
        const OverlapRecord *r = overlap_of(i, -1 - o);
        if (!r || r->kind != OverlapRecord::Kind::kShift || !b.shape)
            return apart_from_obstacle(b, obstacles_[static_cast<size_t>(o)], t);
        return !overlap_with_obstacle(b, obstacles_[static_cast<size_t>(o)], t);
    }

    void unoverlap(int i, int other, double t) {
        if (!overlaps_.erase(pair_key(i, other))) return;
        if (other < 0) --bodies_[static_cast<size_t>(i)].overlapped_obstacles;
        memory_.close(bodies_[static_cast<size_t>(i)].model, model_of(other), t);
    }

    static std::pair<int, int> pair_key(int a, int b) {
        return b >= 0 && b < a ? std::make_pair(b, a) : std::make_pair(a, b);
    }

    // Leaves the pair alone until they are apart (overlapping keyed models, or a grazing contact).
    void ignore(int i, int other, double t) {
        if (!ignored_.insert(pair_key(i, other)).second) return;
        if (other < 0) {
            Body &b = bodies_[static_cast<size_t>(i)];
            ++b.ignored_obstacles;
            if (!b.sphere) b.grazed_until = t + recheck_after(b, t);
        }
    }

    void unignore(int i, int other, double t) {
        if (ignored_.erase(pair_key(i, other))) {
            if (other < 0) --bodies_[static_cast<size_t>(i)].ignored_obstacles;
            memory_.close(bodies_[static_cast<size_t>(i)].model, model_of(other), t);
        }
    }

    void forget_ignored(int i, double t) {
        std::vector<std::pair<int, int>> mine;
        for (const auto &key : ignored_)
            if (key.first == i || key.second == i) mine.push_back(key);
        for (const auto &[a, b] : mine) unignore(i, a == i ? b : a, t);
    }

    bool is_ignored(int a, int b) const {
        return !ignored_.empty() && ignored_.count(pair_key(a, b));
    }

    // ---- predictions -----------------------------------------------------------------------

    // Predicts body i's earliest event after `now`: leaving or resuming its keys, leaving its
    // cell, meeting a body or an obstacle, or separating from one it overlapped.
    void predict(int i, double now) {
        Body &b = bodies_[static_cast<size_t>(i)];
        Predicted next;
        if (b.keyed())
            next = predicted(b.keys_end, EventKind::kActivation);
        else if (b.resume_at < kNever)
            next = predicted(b.resume_at, EventKind::kResume);
        if (b.settles_at < next.t) next = predicted(b.settles_at, EventKind::kSettle);
        if (!b.active) {
            set_prediction(i, next);
            return;
        }
        ++count_.predictions;
        if (b.ignored_obstacles > 0 || b.overlapped_obstacles > 0) recheck_obstacles(i, now, next);
        if (b.still() && b.sphere) { // still spheres are met, they do not meet: the movers predict
            set_prediction(i, next);
            return;
        }
        double limit = std::min(horizon_, next.t) - now;
        if (b.in_grid)
            if (auto exit = first_exit(from_now(b, now), grid_->bounds(b.cell), limit)) {
                limit = exit->t;
                next = predicted(now + exit->t, EventKind::kCell);
                next.exit = *exit;
            }
        std::size_t tested = 0;
        for_candidates(i, [&](int j) {
            const Body &o = bodies_[static_cast<size_t>(j)];
            if (!o.active) return;
            if (!is_ignored(i, j)) {
                ++tested;
                std::optional<Contact> c;
                if (b.free_sphere() && o.free_sphere()) {
                    double rb = b.radius, ro = o.radius;
                    radii_against(i, j, rb, ro);
                    c = sphere_sphere(from_now(b, now), rb, from_now(o, now), ro, limit);
                } else if (b.shape && o.shape) {
                    if (!(b.still() && o.still()))
                        c = mesh_pair(*b.shape, from_now(b, now), *o.shape, from_now(o, now),
                                      limit);
                } else if (!(b.still() && o.still()))
                    c = advance(i, j, -1, now, limit); // may find them overlapping, and ignore them
                if (c) {
                    next = predicted(now + c->t, EventKind::kBody, j, o.version, *c);
                    limit = c->t;
                }
            }
            if (is_ignored(i, j) || is_overlapped(i, j)) predict_release(i, j, now, limit, next);
        });
        count_.done += tested;
        count_.skipped += (bodies_.size() - 1) - tested;
        if (b.support >= 0) predict_leave(i, now, limit, next);
        if (b.shape)
            predict_mesh_obstacles(i, now, limit, next); // exact: it translates
        else
            predict_obstacles(i, now, limit, next); // spheres exact; keyed models by advancement
        if (b.ignored_obstacles > 0 || b.overlapped_obstacles > 0) recheck_obstacles(i, now, next);
        // Nothing within the window: it looks again at its end.
        if (next.t > horizon_) next = predicted(horizon_, EventKind::kRecheck);
        set_prediction(i, next);
    }

    // Two overlapping bodies: the moment they are apart again.
    void predict_release(int i, int j, double now, double &limit, Predicted &next) {
        const Body &b = bodies_[static_cast<size_t>(i)], &o = bodies_[static_cast<size_t>(j)];
        std::optional<double> s;
        if (b.free_sphere() && o.free_sphere()) {
            // |d|^2 - R^2 turns non-negative.
            const Path path = from_now(b, now), other = from_now(o, now);
            const glm::dvec3 d = path.p - other.p, e = path.v - other.v,
                             h = 0.5 * (path.a - other.a);
            const double reach = b.radius + o.radius + touching(b) + touching(o);
            Quartic gap = {glm::dot(d, d) - reach * reach, 2.0 * glm::dot(d, e),
                           glm::dot(e, e) + 2.0 * glm::dot(d, h), 2.0 * glm::dot(e, h),
                           glm::dot(h, h)};
            for (double &c : gap) c = -c;
            s = first_contact(gap, 0.0, limit);
        } else if (apart_from_body(b, o, now)) {
            s = 0.0;
        } else {
            // Looked at again after either has moved a quarter of the smaller size.
            const double size =
                std::min(b.sphere ? b.radius : b.reach, o.sphere ? o.radius : o.reach);
            const double speed = point_speed(b, now, 0.0) + point_speed(o, now, 0.0);
            if (speed > 0.0) s = std::min(limit, 0.25 * size / speed);
        }
        if (s && now + *s < next.t) {
            next = predicted(now + *s, EventKind::kRelease, j);
            limit = *s;
        }
    }

    // Conservative advancement (keyed_contact.hpp) between body i and body j, or obstacle
    // `obstacle` when j < 0, over [now, now + limit]. Returns the contact, times from now.
    std::optional<Contact> advance(int i, int j, int obstacle, double now, double limit) {
        const Body &b = bodies_[static_cast<size_t>(i)];
        const Body *o = j >= 0 ? &bodies_[static_cast<size_t>(j)] : nullptr;
        const Obstacle *ob = obstacle >= 0 ? &obstacles_[static_cast<size_t>(obstacle)] : nullptr;
        Approach approach;
        approach.gap = [&](double t) {
            return o ? gap_between(b, *o, t) : gap_to_obstacle(b, *ob, t);
        };
        approach.closing_speed = [&](double t, double dt) {
            return point_speed(b, t, dt) + (o ? point_speed(*o, t, dt) : 0.0);
        };
        const double tol = std::max(tolerance(b), o ? tolerance(*o) : 0.0);
        const ApproachOutcome out = advance_to_contact(approach, now, now + limit, tol);
        ++count_.advancements;
        switch (out.kind) {
        case ApproachOutcome::kContact: {
            Contact c;
            if (o)
                gap_between(b, *o, out.t, &c);
            else
                gap_to_obstacle(b, *ob, out.t, &c);
            c.t = out.t - now;
            return c;
        }
        case ApproachOutcome::kOverlapping: {
            // Found inside each other by the advancement (keys that put it there): left alone
            // until apart, and said once.
            const int other = o ? j : -1 - obstacle;
            Contact c;
            const double gap = o ? gap_between(b, *o, out.t, &c) : gap_to_obstacle(b, *ob, out.t, &c);
            report_overlap(i, other, out.t, -gap, c.normal);
            OverlapRecord record;
            record.model_a = b.model;
            record.model_b = model_of(other);
            record.since = out.t;
            memory_.add(record);
            ignore(i, other, out.t);
            return std::nullopt;
        }
        case ApproachOutcome::kUndecided:
            // Too long within a hair of each other: look again from there.
            if (out.t > now) {
                Contact c;
                c.t = out.t - now;
                c.normal = glm::dvec3(0.0);
                return c;
            }
            return std::nullopt;
        case ApproachOutcome::kNone:
            break;
        }
        return std::nullopt;
    }

    void predict_obstacles(int i, double now, double limit, Predicted &next) {
        const Body &b = bodies_[static_cast<size_t>(i)];
        std::size_t tested = 0;
        for (size_t o = 0; o < obstacles_.size(); ++o) {
            if (b.ignored_obstacles > 0 && is_ignored(i, -1 - static_cast<int>(o))) continue;
            const Obstacle &ob = obstacles_[o];
            if (b.turning()) {
                // Resting or sliding on it without turning: it leaves it by predict_leave.
                if (b.support == static_cast<int>(o) && b.spin.w == glm::dvec3(0.0)) continue;
                ++tested;
                predict_turning_obstacle(i, o, now, limit, next);
                if (next.kind == EventKind::kObstacle && next.t - now < limit) limit = next.t - now;
                continue;
            }
            if (!b.free_sphere()) {
                ++tested;
                if (auto c = advance(i, -1, static_cast<int>(o), now, limit)) {
                    next = predicted(now + c->t, EventKind::kObstacle, static_cast<int>(o), 0, *c);
                    limit = c->t;
                }
                continue;
            }
            const Path path = from_now(b, now);
            const double r = radius_against(i, static_cast<int>(o)); // less while overlapping
            // Broad phase: the swept sphere must reach the obstacle's bounding sphere.
            const Path fixed{ob.center, glm::dvec3(0.0), glm::dvec3(0.0)};
            if (!(glm::length(path.p - ob.center) <= r + ob.radius) &&
                !sphere_sphere(path, r, fixed, ob.radius, limit))
                continue;
            // Each triangle only if the swept sphere's box reaches the triangle's box.
            Box reach = swept_box(path, limit);
            reach.lo -= glm::dvec3(r);
            reach.hi += glm::dvec3(r);
            const bool on_it = b.support == static_cast<int>(o);
            for (size_t k = 0; k + 2 < ob.corners.size(); k += 3) {
                if (!reach.overlaps(ob.boxes[k / 3])) continue;
                if (on_it && in_support_plane(b, ob, k / 3)) continue; // it slides on these
                ++tested;
                if (auto c = sphere_triangle(path, r, ob.corners[k], ob.corners[k + 1],
                                             ob.corners[k + 2], limit)) {
                    next = predicted(now + c->t, EventKind::kObstacle, static_cast<int>(o), 0, *c);
                    limit = c->t;
                }
            }
        }
        count_.done += tested;
        count_.skipped += triangle_count_ - std::min(tested, triangle_count_);
    }

    // The seed's mesh-mesh tests (mesh_contact.hpp), counted.
    std::optional<Contact> mesh_pair(const MeshShape &a, const Path &pa, const MeshShape &b,
                                     const Path &pb, double limit) {
        PairStats stats;
        auto c = mesh_mesh(a, pa, b, pb, limit, &stats);
        count_.mesh_tests += stats.primitive_tests;
        return c;
    }

    // A free model that is not a sphere against the static models.
    void predict_mesh_obstacles(int i, double now, double limit, Predicted &next) {
        const Body &b = bodies_[static_cast<size_t>(i)];
        if (b.still()) return;
        const Path path = from_now(b, now), fixed{};
        for (size_t o = 0; o < obstacles_.size(); ++o) {
            if (b.ignored_obstacles > 0 && is_ignored(i, -1 - static_cast<int>(o))) continue;
            // While it overlaps the obstacle, it is tested moved out by its depth (touching).
            const glm::dvec3 shift = shift_against(i, static_cast<int>(o));
            const Path moved{path.p + shift, path.v, path.a};
            if (auto c = mesh_pair(*b.shape, moved, shape_facing(obstacles_[o], moved.p), fixed,
                                   limit)) {
                c->point -= shift;
                next = predicted(now + c->t, EventKind::kObstacle, static_cast<int>(o), 0, *c);
                limit = c->t;
            }
        }
    }

    // A closed static mesh is solid from outside; for a model inside it (a box in a cube used
    // as a room) it is a room, its faces met from within.
    const MeshShape &shape_facing(const Obstacle &o, const glm::dvec3 &p) const {
        if (!o.shape->closed || !inside(o, p)) return *o.shape;
        if (!o.room) {
            std::vector<std::array<uint32_t, 3>> reversed = o.shape->triangles;
            for (auto &t : reversed) std::swap(t[1], t[2]);
            o.room = std::make_shared<const MeshShape>(
                MeshShape::build(o.shape->vertices, std::move(reversed)));
        }
        return *o.room;
    }

    // Whether p is inside a closed obstacle: a ray from it crosses its surface an odd number of
    // times (in a direction that no axis-aligned edge or face of a generated mesh lies along).
    static bool inside(const Obstacle &o, const glm::dvec3 &p) {
        const Box box = o.shape->bounds();
        if (p.x < box.lo.x || p.y < box.lo.y || p.z < box.lo.z || p.x > box.hi.x ||
            p.y > box.hi.y || p.z > box.hi.z)
            return false;
        const glm::dvec3 ray = glm::normalize(glm::dvec3(1.0, 0.0137, 0.0291)) *
                               (2.0 * glm::length(box.hi - box.lo) + 1.0);
        int crossings = 0;
        for (size_t k = 0; k + 2 < o.corners.size(); k += 3) {
            // Both faces of the triangle: the seed's test is one-sided.
            if (ray_triangle(p, ray, o.corners[k], o.corners[k + 1], o.corners[k + 2]) ||
                ray_triangle(p, ray, o.corners[k], o.corners[k + 2], o.corners[k + 1]))
                ++crossings;
        }
        return crossings % 2 == 1;
    }

    // ---- resting and sliding on static models ---------------------------------------------

    static bool in_support_plane(const Body &b, const Obstacle &o, size_t k) {
        return glm::dot(o.normals[k], b.support_n) > 1.0 - 1e-9 &&
               std::abs(o.offsets[k] - b.support_d) <= 1e-9 * (1.0 + std::abs(b.support_d));
    }

    // A free sphere touching the face of a static model, not moving into or out of it, with its
    // acceleration not pulling it away, rests or slides on it: the face holds it up (the part of
    // its acceleration into the face is cancelled) until it slides off the flat region the face
    // belongs to. Without this a ball placed on a floor under gravity would meet the floor with
    // zero speed at every instant.
    bool try_settle(int i, double t) {
        Body &b = bodies_[static_cast<size_t>(i)];
        if (!b.free_sphere() || b.support >= 0 || b.motion == ANI_MOTION_REST) return false;
        const glm::dvec3 c = b.path.at(t - b.t0), v = b.path.velocity(t - b.t0);
        const double tol = touching(b);
        for (size_t o = 0; o < obstacles_.size(); ++o) {
            const Obstacle &ob = obstacles_[o];
            if (glm::length(c - ob.center) > b.radius + ob.radius + tol) continue;
            if (b.ignored_obstacles > 0 && is_ignored(i, -1 - static_cast<int>(o))) continue;
            const double r = radius_against(i, static_cast<int>(o)); // less while overlapping
            Box near{c - glm::dvec3(r + tol), c + glm::dvec3(r + tol)};
            for (size_t k = 0; k < ob.boxes.size(); ++k) {
                const glm::dvec3 n = ob.normals[k];
                if (n == glm::dvec3(0.0) || !near.overlaps(ob.boxes[k])) continue;
                const double h =
                    glm::dot(n, c) - ob.offsets[k]; // height of the center above the face's plane
                if (std::abs(h - r) > tol) continue;
                const glm::dvec3 q = closest_point_on_triangle(
                    c, ob.corners[3 * k], ob.corners[3 * k + 1], ob.corners[3 * k + 2]);
                if (glm::length((c - q) - h * n) > tol)
                    continue; // nearest to an edge or a corner, not the face
                if (glm::dot(b.free_a, n) > 0.0) continue; // pulled away from it
                if (std::abs(glm::dot(v, n)) > 1e-9 * std::max(1.0, glm::length(v)))
                    continue; // bouncing
                Body held = b;
                held.t0 = t;
                held.path = Path{c - (h - r) * n, v - glm::dot(v, n) * n,
                                 b.free_a - glm::dot(b.free_a, n) * n};
                held.support = static_cast<int>(o);
                held.support_n = n;
                held.support_d = ob.offsets[k];
                held.support_edges = support_boundary(ob, held);
                held.support_feet = {-r * n};
                if (leaves_support(held, t, 1e-9 * std::max(1.0, std::abs(t))))
                    continue; // on the rim of the flat region, on its way off
                close_segment(b, t);
                held.motion = ANI_MOTION_FREE;
                ++held.version;
                b = std::move(held);
                return true;
            }
        }
        return false;
    }

    // A free model that is not a sphere, meeting a face of a static model with no speed along its
    // normal and pulled into it, rests or slides on the flat region of that face's plane.
    bool settle_on(int i, int o, const glm::dvec3 &n, double t) {
        Body &b = bodies_[static_cast<size_t>(i)];
        // (A turning model settles only while it does not turn.)
        if (!(b.shape || (b.turning() && b.spin.w == glm::dvec3(0.0))) || b.support >= 0 ||
            b.motion == ANI_MOTION_REST || !(glm::dot(b.free_a, n) < 0.0))
            return false;
        const Obstacle &ob = obstacles_[static_cast<size_t>(o)];
        const glm::dvec3 c = b.path.at(t - b.t0), v = b.path.velocity(t - b.t0);
        // Where its tests against the obstacle place it: moved out by its depth while it
        // overlaps it (held at that depth).
        const glm::dvec3 placed_c = c + shift_against(i, o);
        // The face: one of the obstacle's, in the plane through the contact with normal n.
        int face = -1;
        for (size_t k = 0; k < ob.normals.size() && face < 0; ++k)
            if (glm::dot(ob.normals[k], n) > 1.0 - 1e-9) face = static_cast<int>(k);
        if (face < 0) return false;
        Body held = b;
        held.support = o;
        held.support_n = n;
        // Of the faces facing that way, the plane the body touches: the nearest below its center.
        double best = kNever;
        for (size_t k = 0; k < ob.normals.size(); ++k)
            if (glm::dot(ob.normals[k], n) > 1.0 - 1e-9) {
                const double below = glm::dot(n, placed_c) - ob.offsets[k];
                if (below >= 0.0 && below < best) {
                    best = below;
                    held.support_d = ob.offsets[k];
                }
            }
        if (!(best < kNever)) return false;
        held.support_edges = support_boundary(ob, held);
        if (held.support_edges.empty()) return false;
        held.support_feet.clear();
        const std::vector<glm::dvec3> corners = placed_vertices(b, t);
        const double size = std::max(1.0, 2.0 * body_size(b));
        for (const glm::dvec3 &corner : corners)
            if (std::abs(glm::dot(n, placed_c + corner) - held.support_d) <= 1e-9 * size)
                held.support_feet.push_back(corner);
        if (held.support_feet.empty()) return false;
        held.t0 = t;
        held.path = Path{c, v - glm::dot(v, n) * n, b.free_a - glm::dot(b.free_a, n) * n};
        if (leaves_support(held, t, 1e-9 * std::max(1.0, std::abs(t)))) return false;
        close_segment(b, t);
        held.motion = ANI_MOTION_FREE;
        ++held.version;
        b = std::move(held);
        return true;
    }

    // The edges that bound the flat region of an obstacle in a body's support plane: those of
    // its triangles in that plane that only one of them has, with their outward normal.
    static std::vector<std::array<glm::dvec3, 3>> support_boundary(const Obstacle &o,
                                                                   const Body &b) {
        auto less = [](const glm::dvec3 &x, const glm::dvec3 &y) {
            return x.x != y.x ? x.x < y.x : x.y != y.y ? x.y < y.y : x.z < y.z;
        };
        struct Edge {
            glm::dvec3 a, b, third;
            int count;
        };
        std::vector<Edge> edges;
        for (size_t k = 0; k < o.boxes.size(); ++k) {
            if (!in_support_plane(b, o, k)) continue;
            for (int e = 0; e < 3; ++e) {
                glm::dvec3 p = o.corners[3 * k + static_cast<size_t>(e)],
                           q = o.corners[3 * k + static_cast<size_t>((e + 1) % 3)];
                if (less(q, p)) std::swap(p, q);
                edges.push_back({p, q, o.corners[3 * k + static_cast<size_t>((e + 2) % 3)], 1});
            }
        }
        std::sort(edges.begin(), edges.end(), [&](const Edge &x, const Edge &y) {
            return less(x.a, y.a) || (x.a == y.a && less(x.b, y.b));
        });
        std::vector<std::array<glm::dvec3, 3>> boundary;
        for (size_t k = 0; k < edges.size();) {
            size_t same = k + 1;
            while (same < edges.size() && edges[same].a == edges[k].a &&
                   edges[same].b == edges[k].b)
                ++same;
            if (same == k + 1) {
                const Edge &e = edges[k];
                glm::dvec3 m = glm::normalize(glm::cross(e.b - e.a, b.support_n));
                if (glm::dot(m, e.third - e.a) > 0.0) m = -m; // away from the triangle
                boundary.push_back({e.a, e.b, m});
            }
            k = same;
        }
        return boundary;
    }

    // When the last of the points it touches the support with leaves the flat region, within
    // [now, now + limit]. (A model that cannot turn tips over nothing: it is held until it is
    // wholly past the rim.)
    std::optional<double> leaves_support(const Body &b, double now, double limit) const {
        const Path c = from_now(b, now);
        std::optional<double> last;
        for (const glm::dvec3 &foot : b.support_feet) {
            const Path p{c.p + foot, c.v, c.a};
            std::optional<double> first;
            for (const auto &[ea, eb, m] : b.support_edges) {
                const auto s = upward_root(glm::dot(m, p.p - ea), glm::dot(m, p.v),
                                           0.5 * glm::dot(m, p.a), limit);
                if (!s || (first && *s >= *first)) continue;
                const glm::dvec3 e = eb - ea;
                const double along = glm::dot(p.at(*s) - ea, e) / glm::dot(e, e);
                if (along < -1e-9 || along > 1.0 + 1e-9)
                    continue; // it passes the line beyond this edge
                first = s;
            }
            if (!first) return std::nullopt; // this one stays on within the window
            last = last ? std::max(*last, *first) : *first;
        }
        return last;
    }

    void predict_leave(int i, double now, double limit, Predicted &next) {
        if (auto s = leaves_support(bodies_[static_cast<size_t>(i)], now, limit);
            s && now + *s < next.t)
            next = predicted(now + *s, EventKind::kLeave);
    }

    // Nothing holds it up any more: its own acceleration again.
    void unsupport(Body &b, double t) {
        if (b.support < 0) return;
        const glm::dvec3 v = b.path.velocity(t - b.t0);
        close_segment(b, t);
        b.path = Path{b.path.at(t - b.t0), v, b.free_a};
        b.t0 = t;
        b.support = -1;
        b.support_edges.clear();
        b.support_feet.clear();
        b.settles_at = kNever;
        ++b.version;
    }

    // After a contact: a body knocked off its support loses it; one that comes to slide on a
    // face gains one.
    void after_contact(int i, double t) {
        Body &b = bodies_[static_cast<size_t>(i)];
        if (b.support >= 0) {
            const glm::dvec3 v = b.path.velocity(t - b.t0);
            if (std::abs(glm::dot(v, b.support_n)) > 1e-9 * std::max(1.0, glm::length(v)))
                unsupport(b, t);
        }
        try_settle(i, t);
    }

    // A body overlapping an obstacle is checked again after it has moved by a fraction of its
    // radius (or at its next event, if sooner), and collides with it again once apart.
    void recheck_obstacles(int i, double now, Predicted &next) {
        const Body &b = bodies_[static_cast<size_t>(i)];
        for (size_t o = 0; o < obstacles_.size(); ++o)
            if (is_ignored(i, -1 - static_cast<int>(o)) &&
                apart_from_obstacle(b, obstacles_[o], now))
                unignore(i, -1 - static_cast<int>(o), now);
        for (size_t o = 0; o < obstacles_.size() && b.overlapped_obstacles > 0; ++o)
            if (is_overlapped(i, -1 - static_cast<int>(o)) &&
                apart_after_overlap(i, static_cast<int>(o), now))
                unoverlap(i, -1 - static_cast<int>(o), now);
        if ((b.ignored_obstacles == 0 && b.overlapped_obstacles == 0) || b.still()) return;
        const double wait = recheck_after(b, now);
        if (wait < kNever && now + wait < next.t) next = predicted(now + wait, EventKind::kRecheck);
    }

    // How long a body takes to move a quarter of its size (about), to look again at an obstacle
    // it overlaps or grazed.
    double recheck_after(const Body &b, double now) const {
        const double size = body_size(b);
        const double speed = point_speed(b, now, 0.0) + std::sqrt(glm::length(b.path.a) * size);
        return speed > 0.0 ? 0.25 * size / speed : kNever;
    }

    double body_size(const Body &b) const {
        if (b.sphere) return b.radius;
        if (b.shape) return 0.5 * glm::length(b.shape->bounds().hi - b.shape->bounds().lo);
        if (b.turns) return b.turning_reach;
        return b.reach;
    }

    // The vertices of a free model that is not a sphere, relative to its centre, as placed at t.
    std::vector<glm::dvec3> placed_vertices(const Body &b, double t) const {
        if (b.shape) return b.shape->vertices;
        const glm::dmat3 turn = glm::dmat3(glm::mat3_cast(b.spin.at(t)));
        std::vector<glm::dvec3> out;
        for (const glm::dvec3 &v : b.turning_vertices) out.push_back(turn * v);
        return out;
    }

    void set_prediction(int i, const Predicted &p) {
        predicted_[static_cast<size_t>(i)] = p;
        queue_->set(static_cast<size_t>(i), p.t);
    }

    // ---- events ----------------------------------------------------------------------------

    void handle(int i, const Predicted &event, double now) {
        Body &b = bodies_[static_cast<size_t>(i)];
        switch (event.kind) {
        case EventKind::kNone:
            break;
        case EventKind::kActivation: // its last key: free from here, as physics.md says
            if (b.keyed()) emit_keyed(b.model, b.keyed_from, now);
            unfile(i);
            activate(b, now, leaving_keys(b.model, now));
            b.resume_at = kNever;
            file(i, now);
            // Pairs left alone while its keys held it inside another are, now that it is free,
            // touching (physics.md): found again as it is now.
            forget_ignored(i, now);
            find_overlaps(i, now);
            try_settle(i, now);
            break;
        case EventKind::kResume: // released at a contact, its next key takes it back
            close_segment(b, now);
            unfile(i);
            b.mode = Body::Mode::kKeyed;
            b.keyed_from = now;
            b.resume_at = kNever;
            ++b.version;
            file(i, now);
            find_overlaps(i, now);
            break;
        case EventKind::kCell: {
            ++count_.crossings;
            grid_->remove(static_cast<uint32_t>(i), b.cell);
            b.cell[static_cast<size_t>(event.exit.axis)] += event.exit.direction;
            if (grid_->inside(b.cell)) {
                grid_->insert(static_cast<uint32_t>(i), b.cell);
            } else {
                b.in_grid = false;
                outside_.push_back(i);
            }
            break;
        }
        case EventKind::kBody: {
            Body &o = bodies_[static_cast<size_t>(event.other)];
            if (o.version != event.other_version) {
                ++count_.stale; // the other body changed course since: predict again
                break;
            }
            if (event.contact.normal == glm::dvec3(0.0)) break; // undecided: look again
            if (grazing(point_velocity(b, event.contact.point, now) -
                            point_velocity(o, event.contact.point, now),
                        event.contact.normal)) {
                ignore(i, event.other, now);
                break;
            }
            collide_bodies(i, event.other, event.contact, now);
            predict(event.other, now);
            break;
        }
        case EventKind::kObstacle:
            if (event.contact.normal == glm::dvec3(0.0)) break;
            if (grazing(point_velocity(b, event.contact.point, now), event.contact.normal)) {
                if (!settle_on(i, event.other, event.contact.normal, now))
                    ignore(i, -1 - event.other, now);
                break;
            }
            collide_obstacle(i, obstacles_[static_cast<size_t>(event.other)], event.contact,
                             event.points, now);
            break;
        case EventKind::kRelease:
            unignore(i, event.other, now);
            unoverlap(i, event.other, now);
            break;
        case EventKind::kRecheck:
            break; // predict() rechecks
        case EventKind::kLeave:
            unsupport(b, now);
            break;
        case EventKind::kSettle: // the Zeno bounces' accumulation time: resting from here
            close_segment(b, now);
            b.path = from_now(b, now);
            b.t0 = now;
            b.settles_at = kNever;
            ++b.version;
            break;
        }
        predict(i, now);
    }

    // A keyed body that collides is released from its keys (physics.md): free from the contact
    // until its next key, with the velocity its keys gave it, or at rest without Dynamics.
    void release(int i, double t) {
        Body &b = bodies_[static_cast<size_t>(i)];
        emit_keyed(b.model, b.keyed_from, t);
        unfile(i);
        const ani_body_state start = leaving_keys(b.model, t);
        activate(b, t, start);
        if (!b.dynamics) stop(b);
        b.resume_at = next_key(b.model, t);
        file(i, t);
        ++count_.releases;
    }

    void collide_obstacle(int i, const Obstacle &o, const Contact &contact,
                          const std::vector<glm::dvec3> &points, double t) {
        Body &b = bodies_[static_cast<size_t>(i)];
        if (b.keyed()) release(i, t);
        const glm::dvec3 n = contact.normal;
        const glm::dvec3 v = b.path.velocity(t - b.t0);
        ani_collision_event e{};
        e.t = t;
        e.a = b.model;
        e.b = o.model;
        e.normal = ani(n);
        e.point = ani(contact.point);
        e.speed = std::max(0.0, -glm::dot(v, n));
        if (b.turning()) { // turning_response.inc: the speed of the touching point
            e.speed = std::max(0.0, -glm::dot(point_velocity(b, contact.point, t), n));
            if (!b.dynamics)
                restart(b, t, glm::dvec3(0.0), true);
            else if (respond_turning_to_obstacle(i, o, contact, points, t)) {
                report(e); // resting from the Zeno bounces' accumulation time
                return;
            }
            after_contact(i, t);
            report(e);
            return;
        }
        // Off a model without Dynamics: a reflection; without Dynamics itself it stops. With
        // restitution or friction: the contact impulse (sphere_response.inc, mesh_response.inc).
        if (!b.dynamics || !sphere_responds(b, scene_->models[o.model]))
            restart(b, t, reflect(v, n), !b.dynamics);
        else if (respond_to_obstacle(i, o, n, v, t)) {
            report(e); // resting from the Zeno bounces' accumulation time
            return;
        }
        after_contact(i, t);
        report(e);
    }

    void collide_bodies(int i, int j, const Contact &contact, double t) {
        Body &b = bodies_[static_cast<size_t>(i)], &o = bodies_[static_cast<size_t>(j)];
        const glm::dvec3 n = contact.normal;
        if (b.turning() || o.turning()) { // turning_response.inc
            const ImpulseBody ib = impulse_body(b, contact.point, t),
                              io = impulse_body(o, contact.point, t);
            const bool b_wall = b.keyed(), o_wall = o.keyed();
            ani_collision_event e{};
            e.t = t;
            e.a = b.model;
            e.b = o.model;
            e.normal = ani(n);
            e.point = ani(contact.point);
            e.speed = std::max(0.0, -glm::dot(point_velocity_of(ib) - point_velocity_of(io), n));
            if (b_wall) release(i, t);
            if (o_wall) release(j, t);
            respond_turning_pair(b, ib, b_wall, o, io, o_wall, n, t);
            after_contact(i, t);
            after_contact(j, t);
            report(e);
            return;
        }
        // A keyed body is a wall of infinite mass moving as its keys say, for the free body it
        // meets: that one reflects off it with the relative velocity (physics.md).
        const glm::dvec3 v = point_velocity(b, contact.point, t),
                         vo = point_velocity(o, contact.point, t);
        const bool b_wall = b.keyed() && !o.keyed(), o_wall = o.keyed() && !b.keyed();
        if (b.keyed()) release(i, t);
        if (o.keyed()) release(j, t);
        ani_collision_event e{};
        e.t = t;
        e.a = b.model;
        e.b = o.model;
        e.normal = ani(n);
        e.point = ani(contact.point);
        e.speed = std::max(0.0, -glm::dot(v - vo, n));
        if (b_wall || o_wall) {
            Body &free = b_wall ? o : b;
            const glm::dvec3 v_free = b_wall ? vo : v, v_wall = b_wall ? v : vo,
                             n_free = b_wall ? -n : n;
            if (free.dynamics && sphere_responds(free, scene_->models[(b_wall ? b : o).model]))
                respond_to_wall(free, v_free, v_wall, n_free, (b_wall ? b : o).material, t);
            else
                restart(free, t,
                        free.dynamics ? reflect_off_moving_wall(v_free, v_wall, n_free)
                                      : glm::dvec3(0.0),
                        !free.dynamics);
        } else if (b.dynamics && o.dynamics && sphere_responds(b, scene_->models[o.model])) {
            respond_to_sphere(b, v, o, vo, n, t);
        } else if (b.dynamics && o.dynamics) {
            const double ma = scene_->models[b.model].desc->mass,
                         mb = scene_->models[o.model].desc->mass;
            const auto [va, vb] = elastic_exchange(ma, v, mb, vo, n);
            restart(b, t, va, false);
            restart(o, t, vb, false);
        } else {
            // A model without Dynamics stops at the contact; one with Dynamics reflects off it as
            // off a wall moving at its velocity then.
            if (b.dynamics && sphere_responds(b, scene_->models[o.model]))
                respond_to_wall(b, v, vo, n, o.material, t);
            else
                restart(b, t, b.dynamics ? reflect_off_moving_wall(v, vo, n) : glm::dvec3(0.0),
                        !b.dynamics);
            if (o.dynamics && sphere_responds(o, scene_->models[b.model]))
                respond_to_wall(o, vo, v, -n, b.material, t);
            else
                restart(o, t, o.dynamics ? reflect_off_moving_wall(vo, v, -n) : glm::dvec3(0.0),
                        !o.dynamics);
        }
        after_contact(i, t);
        after_contact(j, t);
        report(e);
    }

#include "sphere_response.inc"
#include "mesh_response.inc"
#include "turning_response.inc"

    void report(const ani_collision_event &e) {
        auto finite = [](const ani_vec3 &v) {
            return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
        };
        if (!finite(e.normal) || !finite(e.point) || !std::isfinite(e.speed) || !std::isfinite(e.t))
            throw ani::Failure(ANI_ERR_FAILED, std::string("the contact of models '") +
                                                   name_of(scene_->models[e.a]) + "' and '" +
                                                   name_of(scene_->models[e.b]) +
                                                   "' is not finite");
        ++count_.collisions;
        if (sink_->event) sink_->event(sink_->context, &e);
    }

    // The work counted, for `animator bake --stats` (ABI 1.1 hosts).
    void report_counts() {
        if (!sink_->count) return;
        const std::pair<const char *, std::size_t> counts[] = {
            {"pair tests done", count_.done},
            {"pair tests skipped", count_.skipped},
            {"predictions", count_.predictions},
            {"stale predictions", count_.stale},
            {"cell crossings", count_.crossings},
            {"collisions", count_.collisions},
            {"conservative advancements", count_.advancements},
            {"releases from keys", count_.releases},
            {"mesh feature tests", count_.mesh_tests},
        };
        // Each slice reports its own work: the host adds them up.
        for (size_t k = 0; k < std::size(counts); ++k) {
            const double value = static_cast<double>(counts[k].second);
            sink_->count(sink_->context, counts[k].first, value - counted_[k]);
            counted_[k] = value;
        }
    }

    // A model that `rotates` must be able to: its mesh closed (it turns about its centre of mass,
    // which an open mesh has not). physics.custom turns spheres, and other models whose three
    // principal moments are equal (spherical tops: a cube, a regular polyhedron) with their
    // centre of mass at their origin, as their keys scale them at `t` (where they become free):
    // true for those. Any other model with Rotates on moves without turning, and the log says so
    // once per bake.
    bool check_turning(uint32_t i, bool sphere, double t) {
        const ani_physics_model &m = scene_->models[i];
        if (!ANI_MODEL_DESC_HAS_BODY(m.desc) || !m.desc->rotates || !m.desc->dynamics) return false;
        std::string why;
        if (!m.mesh->is_sphere && !is_closed(*m.mesh, &why))
            throw ani::Failure(ANI_ERR_INVALID_ARGUMENT,
                               std::string("model '") + name_of(m) +
                                   "' cannot rotate: its mesh is not closed (" + why +
                                   "); turn Rotates off or close the mesh");
        if (sphere) return false; // its spin: sphere_response.inc
        const TurningShape shape = turning_shape(i, t);
        const glm::dvec3 moments = shape.mass.principal_moments;
        const bool top = moments.z - moments.x <= 1e-9 * moments.z;
        const bool centred =
            glm::length(shape.mass.center_of_mass) <= 1e-9 * std::max(shape.reach, 1e-300);
        if (top && centred) return true;
        if (t_begin_ == 0.0)
            log_warning(std::string("model '") + name_of(m) +
                        "' has Rotates on, but physics.custom turns only spheres and models "
                        "whose three principal moments are equal with their centre of mass at "
                        "their origin (a cube) so far: it moves without turning (physics.bullet "
                        "turns it)");
        return false;
    }

    // A model's mesh scaled as its keys leave it at t, as a uniform solid of its mass.
    struct TurningShape {
        std::vector<glm::dvec3> vertices;
        MassProperties mass;
        double reach = 0.0;
        glm::dmat3 scale{1.0};
    };
    TurningShape turning_shape(uint32_t i, double t) const {
        const ani_physics_model &m = scene_->models[i];
        const double mass = m.desc->mass;
        if (!(mass > 0.0) || !std::isfinite(mass))
            throw ani::Failure(ANI_ERR_INVALID_ARGUMENT,
                               std::string("model '") + name_of(m) +
                                   "' needs a finite mass > 0 to rotate");
        TurningShape shape;
        const ani_vec3 s = keyed_state(*scene_, i, t, nullptr).scale;
        shape.scale = glm::dmat3(glm::scale(glm::dmat4(1.0), vec(s)));
        std::vector<double> positions;
        for (uint32_t k = 0; k < m.mesh->vertex_count; ++k) {
            const glm::dvec3 p = shape.scale * vertex(*m.mesh, k);
            shape.vertices.push_back(p);
            shape.reach = std::max(shape.reach, glm::length(p));
            positions.insert(positions.end(), {p.x, p.y, p.z});
        }
        ani_mesh_view scaled = *m.mesh;
        scaled.positions = positions.data();
        scaled.is_sphere = 0;
        shape.mass = mass_properties(scaled, mass);
        return shape;
    }

    // Body b turns from its contacts once free after its last key (at keys_end).
    void set_turning(Body &b, double keys_end) {
        TurningShape shape = turning_shape(b.model, keys_end);
        b.turns = true;
        b.turning_vertices = std::move(shape.vertices);
        b.turning_reach = shape.reach;
        b.scale = shape.scale;
        // A spherical top: one moment about every axis (their mean, equal to rounding).
        const glm::dvec3 moments = shape.mass.principal_moments;
        b.inv_inertia = 3.0 / (moments.x + moments.y + moments.z);
    }

    void log_warning(const std::string &message) {
        if (host_ && host_->log)
            host_->log(host_, ANI_LOG_WARNING, "physics.custom", message.c_str());
    }

    const ani_physics_scene *scene_; // this call's (the host builds it anew for each)
    double t_begin_, t_end_;
    const ani_bake_sink *sink_;
    const ani_host *host_;
    BakeOptions options_;
    glm::dvec3 gravity_;
    std::vector<Body> bodies_;
    std::vector<Obstacle> obstacles_;
    std::size_t triangle_count_ = 0;
    std::unique_ptr<UniformGrid> grid_; // with many bodies
    std::vector<int> outside_;          // active bodies not in the grid (all of them without one)
    std::unique_ptr<EventQueue> queue_;
    std::vector<Predicted> predicted_; // each body's earliest event
    // Pairs left alone until they are apart: overlapping keyed models, grazing contacts. Keys:
    // (body, other body) with the lower first, or (body, -1 - obstacle).
    std::set<std::pair<int, int>> ignored_;
    // Pairs that overlapped and touch at that depth until apart (physics.md), same keys.
    std::map<std::pair<int, int>, OverlapRecord> overlaps_;
    std::set<std::pair<int, int>> reported_; // overlaps said in this slice
    OverlapMemory &memory_;                  // overlaps found by the earlier slices of the bake
    struct {
        std::size_t done = 0, skipped = 0, predictions = 0, stale = 0, crossings = 0,
                    collisions = 0, advancements = 0, releases = 0, mesh_tests = 0;
    } count_;
    std::size_t reports_ = 0;
    std::array<double, 9> counted_{}; // the counts reported by the earlier slices
    std::vector<bool> is_body_;       // per model: a body (the others are reported each slice)
    double horizon_ = 0.0;            // how far predictions look
    ScenePrint fingerprint_;          // the scene the bake goes on with
};

} // namespace

struct BakeInProgress::State {
    OverlapMemory overlaps;
    std::unique_ptr<EventBake> bake; // the last slice's, to go on with
};

BakeInProgress::BakeInProgress() : state_(std::make_unique<State>()) {}
BakeInProgress::~BakeInProgress() = default;

void bake_scene(const ani_physics_scene &scene, double t_begin, double t_end,
                const ani_bake_sink &sink, const ani_host *host, const BakeOptions &options,
                BakeInProgress *in_progress) {
    if (!in_progress) {
        OverlapMemory one_bake;
        EventBake(scene, t_begin, t_end, sink, host, options, one_bake).run();
        return;
    }
    auto &state = *in_progress->state_;
    try {
        if (state.bake && state.bake->continues(scene, t_begin, options)) {
            state.bake->resume(scene, t_end, sink);
            return;
        }
        state.bake.reset();
        auto bake =
            std::make_unique<EventBake>(scene, t_begin, t_end, sink, host, options, state.overlaps);
        bake->run();
        state.bake = std::move(bake);
    } catch (...) {
        state.bake.reset(); // cancelled or failed half-way: the next bake starts afresh
        throw;
    }
}

} // namespace physics_custom
