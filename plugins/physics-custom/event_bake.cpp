#include "event_bake.hpp"

#include "free_motion.hpp"
#include "response.hpp"
#include "time_of_impact.hpp"

#include <animator/plugin_cpp.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtx/euler_angles.hpp>

#include <cmath>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace physics_custom {

namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();

glm::dvec3 vec(const ani_vec3 &v) { return {v.x, v.y, v.z}; }
ani_vec3 ani(const glm::dvec3 &v) { return {v.x, v.y, v.z}; }

const char *name_of(const ani_physics_model &m) { return m.desc && m.desc->name ? m.desc->name : "?"; }

// A movable sphere once it is free.
struct Body {
    uint32_t model = 0;
    double radius = 0.0;
    bool dynamics = false;
    bool active = false;  // free (past its keys) and colliding
    double free_at = kNever;
    double t0 = 0.0;      // start of the current segment
    Path path;            // center(t) = path.at(t - t0)
    int motion = ANI_MOTION_FREE;
};

// The triangles of a static model, in world space, with their bounding sphere.
struct Obstacle {
    uint32_t model = 0;
    std::vector<glm::dvec3> corners; // 3 per triangle
    std::vector<Box> boxes;          // 1 per triangle
    glm::dvec3 center{0.0};
    double radius = 0.0;
};

struct Hit {
    double t = kNever;
    int body = -1;
    int other_body = -1;     // or
    int obstacle = -1;       // or
    bool activation = false;
    Contact contact;
};

glm::dmat4 model_matrix(const ani_model_state &s) {
    return glm::translate(glm::dmat4(1.0), vec(s.center)) *
           glm::eulerAngleXYZ(glm::radians(s.angles.x), glm::radians(s.angles.y), glm::radians(s.angles.z)) *
           glm::scale(glm::dmat4(1.0), vec(s.scale));
}

bool uniform(const ani_vec3 &s) { return s.x == s.y && s.y == s.z && s.x > 0.0; }

ani_model_state keyed_state(const ani_physics_scene &scene, uint32_t m, double t, glm::dvec3 *velocity) {
    ani_model_state state{};
    ani_vec3 v{};
    if (scene.evaluate_keyed(scene.host_context, m, t, &state, &v) != ANI_OK)
        throw ani::Failure(ANI_ERR_FAILED, std::string("cannot evaluate the keys of model '") + name_of(scene.models[m]) + "'");
    if (velocity) *velocity = vec(v);
    return state;
}

class EventBake {
  public:
    EventBake(const ani_physics_scene &scene, double t_begin, double t_end, const ani_bake_sink &sink,
              const ani_host *host)
        : scene_(scene), t_begin_(t_begin), t_end_(t_end), sink_(sink), host_(host),
          gravity_(vec(gravity_vector(scene.gravity, scene.down_axis))) {}

    void run() {
        classify();
        find_overlaps(t_begin_);
        double now = t_begin_;
        std::size_t events_at_once = 0;
        double last_event = -kNever;
        while (true) {
            const Hit hit = earliest(now);
            if (!(hit.t <= t_end_)) break;
            events_at_once = hit.t == last_event ? events_at_once + 1 : 0;
            last_event = hit.t;
            if (events_at_once > 100000)
                throw ani::Failure(ANI_ERR_FAILED, "models keep colliding at t = " + std::to_string(hit.t) +
                                                       " s without moving apart");
            now = hit.t;
            respond(hit);
            if (hit.activation) find_overlaps(now);
            if (!ignored_.empty()) release_separated(now);
            if (sink_.progress && ++reports_ % 1024 == 0 &&
                !sink_.progress(sink_.context, (now - t_begin_) / std::max(t_end_ - t_begin_, 1e-300)))
                throw ani::Failure(ANI_ERR_CANCELLED, "the bake was cancelled");
        }
        for (Body &b : bodies_)
            if (b.active) close_segment(b, t_end_);
    }

  private:
    // Keyed spans are reported as they are; the rest of each model's time is free flight,
    // with collisions for the spheres, and without for the others.
    void classify() {
        for (uint32_t i = 0; i < scene_.model_count; ++i) {
            const ani_physics_model &m = scene_.models[i];
            if (!m.desc) throw ani::Failure(ANI_ERR_INVALID_ARGUMENT, "a model has no description");
            const ani_time_span span = m.keyed_span_count ? m.keyed_spans[0] : ani_time_span{t_begin_, t_begin_};
            const double keyed_until = std::min(std::max(span.end, t_begin_), t_end_);
            if (keyed_until > t_begin_) emit_keyed(i, t_begin_, keyed_until);
            const bool free_now = span.end <= t_begin_;
            const bool free_in_range = free_now || span.end < t_end_;
            if (!free_in_range) continue; // keyed throughout this bake
            const double free_at = free_now ? t_begin_ : keyed_until;
            // Where the host's cache knows the state (a resumed bake), it says; otherwise the
            // model leaves its keys now.
            const ani_body_state start =
                free_now && m.start.motion != ANI_MOTION_KEYED ? m.start : leaving_keys(i, free_at);
            const ani_model_desc &d = *m.desc;
            const bool movable = d.dynamics || d.gravity;

            // A static model (it never moves again) is an obstacle made of its triangles.
            if (!movable && free_now && m.mesh && m.group == i) {
                add_obstacle(i, t_begin_);
                emit_free(i, start, free_at);
                continue;
            }
            const std::optional<double> radius = sphere_radius(i, free_at);
            if (movable && radius && m.group == i) {
                Body b;
                b.model = i;
                b.radius = *radius;
                b.dynamics = d.dynamics != 0;
                b.free_at = free_at;
                bodies_.push_back(b);
                if (free_now) activate(bodies_.back(), t_begin_, start);
                continue;
            }
            if (movable && m.mesh && !radius && m.group == i)
                log_once("model '" + std::string(name_of(m)) +
                         "' is not a sphere: collisions of other shapes are not computed by physics.custom yet, "
                         "so it moves through other models");
            emit_free(i, start, free_at);
        }
    }

    std::optional<double> sphere_radius(uint32_t i, double t) {
        const ani_physics_model &m = scene_.models[i];
        if (!m.mesh || !m.mesh->is_sphere) return std::nullopt;
        if (glm::length(vec(m.mesh->bound_center)) > 1e-9 * m.mesh->bound_radius) return std::nullopt;
        const ani_model_state s = keyed_state(scene_, i, t, nullptr);
        if (!uniform(s.scale)) return std::nullopt;
        return m.mesh->bound_radius * s.scale.x;
    }

    void add_obstacle(uint32_t i, double t) {
        const ani_mesh_view &mesh = *scene_.models[i].mesh;
        const glm::dmat4 world = model_matrix(keyed_state(scene_, i, t, nullptr));
        Obstacle o;
        o.model = i;
        for (uint32_t k = 0; k < 3 * mesh.triangle_count; ++k) {
            const double *p = mesh.positions + 3 * static_cast<size_t>(mesh.triangles[k]);
            o.corners.push_back(glm::dvec3(world * glm::dvec4(p[0], p[1], p[2], 1.0)));
        }
        for (size_t k = 0; k + 2 < o.corners.size(); k += 3) {
            Box box{o.corners[k], o.corners[k]};
            for (size_t j = 1; j < 3; ++j) {
                box.lo = glm::min(box.lo, o.corners[k + j]);
                box.hi = glm::max(box.hi, o.corners[k + j]);
            }
            o.boxes.push_back(box);
        }
        glm::dvec3 sum(0.0);
        for (const auto &c : o.corners) sum += c;
        o.center = o.corners.empty() ? glm::dvec3(0.0) : sum / static_cast<double>(o.corners.size());
        for (const auto &c : o.corners) o.radius = std::max(o.radius, glm::length(c - o.center));
        obstacles_.push_back(std::move(o));
    }

    void activate(Body &b, double t, const ani_body_state &start) {
        const ani_motion_segment s = free_segment(b.model, *scene_.models[b.model].desc, start, t, t_end_, ani(gravity_));
        b.active = true;
        b.t0 = t;
        b.path = Path{vec(s.p0), vec(s.v0), vec(s.a)};
        b.motion = s.motion;
    }

    // The state a model leaves its keys with at time t (physics.md: where and how fast).
    ani_body_state leaving_keys(uint32_t i, double t) {
        glm::dvec3 v;
        const ani_model_state s = keyed_state(scene_, i, t, &v);
        ani_body_state state{};
        state.motion = ANI_MOTION_KEYED;
        state.center = s.center;
        state.velocity = ani(v);
        return state;
    }

    void emit(const ani_motion_segment &s) {
        auto finite = [](const ani_vec3 &v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
        if (!finite(s.p0) || !finite(s.v0) || !finite(s.a) || !std::isfinite(s.t0) || !std::isfinite(s.t1))
            throw ani::Failure(ANI_ERR_FAILED, std::string("model '") + name_of(scene_.models[s.model]) +
                                                   "' would move to a value that is not finite");
        sink_.segment(sink_.context, &s);
    }

    void emit_keyed(uint32_t i, double t0, double t1) {
        ani_motion_segment s{};
        s.model = i;
        s.motion = ANI_MOTION_KEYED;
        s.t0 = t0;
        s.t1 = t1;
        emit(s);
    }

    void emit_free(uint32_t i, const ani_body_state &start, double free_at) {
        if (free_at >= t_end_) return;
        emit(free_segment(i, *scene_.models[i].desc, start, free_at, t_end_, ani(gravity_)));
    }

    void close_segment(Body &b, double t) {
        if (t <= b.t0 && !(t == t_end_ && b.t0 == t_end_)) return;
        ani_motion_segment s{};
        s.model = b.model;
        s.motion = b.motion;
        s.t0 = b.t0;
        s.t1 = t;
        s.p0 = ani(b.path.p);
        s.v0 = ani(b.path.v);
        s.a = ani(b.path.a);
        emit(s);
    }

    void restart(Body &b, double t, const glm::dvec3 &velocity, bool stop) {
        close_segment(b, t);
        const glm::dvec3 p = b.path.at(t - b.t0);
        b.t0 = t;
        b.path = stop ? Path{p, glm::dvec3(0.0), glm::dvec3(0.0)} : Path{p, velocity, b.path.a};
        b.motion = stop ? ANI_MOTION_REST : ANI_MOTION_FREE;
    }

    // The path of a body from `now`, for time-of-impact queries over [0, t_end - now].
    Path from_now(const Body &b, double now) const {
        return Path{b.path.at(now - b.t0), b.path.velocity(now - b.t0), b.path.a};
    }

    bool overlaps_obstacle(const Body &b, const Obstacle &o, double t) const {
        const glm::dvec3 c = b.path.at(t - b.t0);
        if (glm::length(c - o.center) > b.radius + o.radius) return false;
        for (size_t k = 0; k + 2 < o.corners.size(); k += 3)
            if (glm::length(c - closest_point_on_triangle(c, o.corners[k], o.corners[k + 1], o.corners[k + 2])) < b.radius)
                return true;
        return false;
    }

    bool overlaps_body(const Body &a, const Body &b, double t) const {
        return glm::length(a.path.at(t - a.t0) - b.path.at(t - b.t0)) < a.radius + b.radius;
    }

    // Reports pairs that overlap at t (at the start, or when a body becomes free inside
    // another) and ignores them until they separate.
    void find_overlaps(double t) {
        for (size_t i = 0; i < bodies_.size(); ++i) {
            if (!bodies_[i].active) continue;
            for (size_t o = 0; o < obstacles_.size(); ++o)
                if (overlaps_obstacle(bodies_[i], obstacles_[o], t))
                    ignore(static_cast<int>(i), -1 - static_cast<int>(o), bodies_[i].model, obstacles_[o].model, t);
            for (size_t j = i + 1; j < bodies_.size(); ++j)
                if (bodies_[j].active && overlaps_body(bodies_[i], bodies_[j], t))
                    ignore(static_cast<int>(i), static_cast<int>(j), bodies_[i].model, bodies_[j].model, t);
        }
    }

    void ignore(int a, int b, uint32_t model_a, uint32_t model_b, double t) {
        if (!ignored_.insert({a, b}).second) return;
        log_once("models '" + std::string(name_of(scene_.models[model_a])) + "' and '" +
                 name_of(scene_.models[model_b]) + "' overlap at t = " + std::to_string(t) +
                 " s; their contact is ignored until they separate");
    }

    // Forgets the ignored pairs that no longer overlap.
    void release_separated(double t) {
        for (auto it = ignored_.begin(); it != ignored_.end();) {
            const Body &a = bodies_[static_cast<size_t>(it->first)];
            const bool still = it->second >= 0 ? overlaps_body(a, bodies_[static_cast<size_t>(it->second)], t)
                                               : overlaps_obstacle(a, obstacles_[static_cast<size_t>(-1 - it->second)], t);
            it = still ? std::next(it) : ignored_.erase(it);
        }
    }

    bool is_ignored(int a, int b) const {
        return !ignored_.empty() && (ignored_.count({a, b}) || ignored_.count({b, a}));
    }

    Hit earliest(double now) const {
        Hit best;
        const double horizon = t_end_ - now;
        for (size_t i = 0; i < bodies_.size(); ++i) {
            const Body &b = bodies_[i];
            if (!b.active) {
                if (b.free_at < best.t && b.free_at >= now) {
                    best = Hit{};
                    best.t = b.free_at;
                    best.body = static_cast<int>(i);
                    best.activation = true;
                }
                continue;
            }
            if (b.motion == ANI_MOTION_REST) continue; // resting bodies are hit, they do not hit
            const Path p = from_now(b, now);
            for (size_t o = 0; o < obstacles_.size(); ++o) {
                if (is_ignored(static_cast<int>(i), -1 - static_cast<int>(o))) continue;
                const Obstacle &ob = obstacles_[o];
                // Broad phase: the swept sphere must reach the obstacle's bounding sphere.
                const Path still{ob.center, glm::dvec3(0.0), glm::dvec3(0.0)};
                const double limit = std::min(horizon, best.t - now);
                if (!(glm::length(p.p - ob.center) <= b.radius + ob.radius) &&
                    !sphere_sphere(p, b.radius, still, ob.radius, limit))
                    continue;
                // Each triangle only if the swept sphere's box reaches the triangle's box.
                Box reach = swept_box(p, limit);
                reach.lo -= glm::dvec3(b.radius);
                reach.hi += glm::dvec3(b.radius);
                for (size_t k = 0; k + 2 < ob.corners.size(); k += 3) {
                    if (!reach.overlaps(ob.boxes[k / 3])) continue;
                    const auto c = sphere_triangle(p, b.radius, ob.corners[k], ob.corners[k + 1], ob.corners[k + 2],
                                                   std::min(horizon, best.t - now));
                    if (c && now + c->t < best.t) {
                        best = Hit{};
                        best.t = now + c->t;
                        best.body = static_cast<int>(i);
                        best.obstacle = static_cast<int>(o);
                        best.contact = *c;
                    }
                }
            }
            for (size_t j = 0; j < bodies_.size(); ++j) {
                const Body &other = bodies_[j];
                if (j == i || !other.active || (other.motion != ANI_MOTION_REST && j < i)) continue;
                if (is_ignored(static_cast<int>(i), static_cast<int>(j))) continue;
                const auto c = sphere_sphere(p, b.radius, from_now(other, now), other.radius, std::min(horizon, best.t - now));
                if (c && now + c->t < best.t) {
                    best = Hit{};
                    best.t = now + c->t;
                    best.body = static_cast<int>(i);
                    best.other_body = static_cast<int>(j);
                    best.contact = *c;
                }
            }
        }
        return best;
    }

    void respond(const Hit &hit) {
        Body &b = bodies_[static_cast<size_t>(hit.body)];
        const double t = hit.t;
        if (hit.activation) {
            activate(b, t, leaving_keys(b.model, t));
            return;
        }
        const glm::dvec3 n = hit.contact.normal;
        const glm::dvec3 v = b.path.velocity(t - b.t0);
        ani_collision_event e{};
        e.t = t;
        e.a = b.model;
        e.normal = ani(n);
        e.point = ani(hit.contact.point);
        if (hit.obstacle >= 0) {
            e.b = obstacles_[static_cast<size_t>(hit.obstacle)].model;
            e.speed = std::max(0.0, -glm::dot(v, n));
            // Off a model without Dynamics: a reflection; without Dynamics itself it stops.
            restart(b, t, reflect(v, n), !b.dynamics);
        } else {
            Body &o = bodies_[static_cast<size_t>(hit.other_body)];
            const glm::dvec3 vo = o.path.velocity(t - o.t0);
            e.b = o.model;
            e.speed = std::max(0.0, -glm::dot(v - vo, n));
            if (b.dynamics && o.dynamics) {
                const double ma = scene_.models[b.model].desc->mass, mb = scene_.models[o.model].desc->mass;
                const auto [va, vb] = elastic_exchange(ma, v, mb, vo, n);
                restart(b, t, va, false);
                restart(o, t, vb, false);
            } else {
                // A model without Dynamics stops at the contact; one with Dynamics reflects off
                // it as off a wall moving at its velocity then.
                restart(b, t, b.dynamics ? reflect_off_moving_wall(v, vo, n) : glm::dvec3(0.0), !b.dynamics);
                restart(o, t, o.dynamics ? reflect_off_moving_wall(vo, v, -n) : glm::dvec3(0.0), !o.dynamics);
            }
        }
        if (sink_.event) sink_.event(sink_.context, &e);
    }

    void log_once(const std::string &message) {
        if (host_ && host_->log) host_->log(host_, ANI_LOG_WARNING, "physics.custom", message.c_str());
    }

    const ani_physics_scene &scene_;
    double t_begin_, t_end_;
    const ani_bake_sink &sink_;
    const ani_host *host_;
    glm::dvec3 gravity_;
    std::vector<Body> bodies_;
    std::vector<Obstacle> obstacles_;
    // Pairs that started overlapping (physics.md): reported once, ignored until they separate.
    // Keys: (body, other body) or (body, -1 - obstacle).
    std::set<std::pair<int, int>> ignored_;
    std::size_t reports_ = 0;
};

} // namespace

void bake_scene(const ani_physics_scene &scene, double t_begin, double t_end, const ani_bake_sink &sink,
                const ani_host *host) {
    EventBake(scene, t_begin, t_end, sink, host).run();
}

} // namespace physics_custom
