#include "event_bake.hpp"

#include "event_queue.hpp"
#include "free_motion.hpp"
#include "grid.hpp"
#include "polynomial.hpp"
#include "response.hpp"
#include "time_of_impact.hpp"

#include <animator/plugin_cpp.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtx/euler_angles.hpp>

#include <cmath>
#include <limits>
#include <memory>
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
    uint64_t version = 0; // counts the changes of path: events predicted against an older path are stale
    bool in_grid = false;
    Cell cell{};
    int ignored_obstacles = 0; // obstacles it overlapped and does not collide with until apart

    bool still() const { return motion == ANI_MOTION_REST || (path.v == glm::dvec3(0.0) && path.a == glm::dvec3(0.0)); }
};

// The triangles of a static model, in world space, with their bounding sphere.
struct Obstacle {
    uint32_t model = 0;
    std::vector<glm::dvec3> corners; // 3 per triangle
    std::vector<Box> boxes;          // 1 per triangle
    glm::dvec3 center{0.0};
    double radius = 0.0;
};

// A body's earliest predicted event.
enum class EventKind { kNone, kActivation, kBody, kObstacle, kCell, kRelease, kRecheck };
struct Predicted {
    double t = kNever;
    EventKind kind = EventKind::kNone;
    int other = -1;             // the other body, or the obstacle
    uint64_t other_version = 0; // the other body's version when predicted
    Contact contact;
    Exit exit;                  // for kCell
};

Predicted predicted(double t, EventKind kind, int other = -1, uint64_t other_version = 0, const Contact &contact = {}) {
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
              const ani_host *host, const BakeOptions &options)
        : scene_(scene), t_begin_(t_begin), t_end_(t_end), sink_(sink), host_(host), options_(options),
          gravity_(vec(gravity_vector(scene.gravity, scene.down_axis))) {}

    void run() {
        classify();
        build_broad_phase();
        queue_ = std::make_unique<EventQueue>(bodies_.size());
        predicted_.assign(bodies_.size(), Predicted{});
        for (size_t i = 0; i < bodies_.size(); ++i)
            if (bodies_[i].active) find_overlaps(static_cast<int>(i), t_begin_);
        for (size_t i = 0; i < bodies_.size(); ++i) predict(static_cast<int>(i), t_begin_);

        std::size_t events_at_once = 0;
        double last_event = -kNever;
        while (!bodies_.empty() && queue_->top_time() <= t_end_) {
            const int i = static_cast<int>(queue_->top());
            const Predicted event = predicted_[static_cast<size_t>(i)];
            const double now = event.t;
            events_at_once = now == last_event ? events_at_once + 1 : 0;
            last_event = now;
            if (events_at_once > 100000 + 10 * bodies_.size())
                throw ani::Failure(ANI_ERR_FAILED, "models keep colliding at t = " + std::to_string(now) +
                                                       " s without moving apart");
            handle(i, event, now);
            if (sink_.progress && ++reports_ % 1024 == 0 &&
                !sink_.progress(sink_.context, (now - t_begin_) / std::max(t_end_ - t_begin_, 1e-300)))
                throw ani::Failure(ANI_ERR_CANCELLED, "the bake was cancelled");
        }
        for (Body &b : bodies_)
            if (b.active) close_segment(b, t_end_);
        report_counts();
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
                b.path.p = vec(start.center); // where it will be free, for the grid's region
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
        triangle_count_ += o.boxes.size();
        obstacles_.push_back(std::move(o));
    }

    // With many bodies, a grid over the region where they start and the obstacles are; bodies
    // that leave it are tested against every body. With few, every body is tested against
    // every other (the grid's crossings would cost more than they save).
    void build_broad_phase() {
        if (bodies_.empty() || options_.broad_phase == BroadPhase::kAllPairs ||
            (options_.broad_phase == BroadPhase::kAutomatic && bodies_.size() < kGridFrom))
            return;
        double widest = 0.0;
        Box region{bodies_[0].path.p, bodies_[0].path.p};
        for (const Body &b : bodies_) {
            widest = std::max(widest, 2.0 * b.radius);
            region.lo = glm::min(region.lo, b.path.p);
            region.hi = glm::max(region.hi, b.path.p);
        }
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

    // Files an active body under its cell, or among the bodies outside the grid.
    void file(int i, double t) {
        Body &b = bodies_[static_cast<size_t>(i)];
        if (grid_) {
            b.cell = grid_->cell_of(b.path.at(t - b.t0));
            b.in_grid = grid_->inside(b.cell);
            if (b.in_grid) {
                grid_->insert(static_cast<uint32_t>(i), b.cell);
                return;
            }
        }
        outside_.push_back(i);
    }

    void activate(Body &b, double t, const ani_body_state &start) {
        const ani_motion_segment s = free_segment(b.model, *scene_.models[b.model].desc, start, t, t_end_, ani(gravity_));
        b.active = true;
        b.t0 = t;
        b.path = Path{vec(s.p0), vec(s.v0), vec(s.a)};
        b.motion = s.motion;
        ++b.version;
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
        ++b.version;
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

    // Reports the pairs with body i that overlap at t (at the start, or when i becomes free
    // inside another) and ignores them until they separate (physics.md).
    void find_overlaps(int i, double t) {
        Body &b = bodies_[static_cast<size_t>(i)];
        for (size_t o = 0; o < obstacles_.size(); ++o)
            if (overlaps_obstacle(b, obstacles_[o], t)) ignore(i, -1 - static_cast<int>(o), t);
        for_candidates(i, [&](int j) {
            if (overlaps_body(b, bodies_[static_cast<size_t>(j)], t)) ignore(i, j, t);
        });
    }

    static std::pair<int, int> pair_key(int a, int b) { return b >= 0 && b < a ? std::make_pair(b, a) : std::make_pair(a, b); }

    void ignore(int i, int other, double t) {
        if (!ignored_.insert(pair_key(i, other)).second) return;
        const uint32_t model_b = other >= 0 ? bodies_[static_cast<size_t>(other)].model
                                            : obstacles_[static_cast<size_t>(-1 - other)].model;
        if (other < 0) ++bodies_[static_cast<size_t>(i)].ignored_obstacles;
        log_once("models '" + std::string(name_of(scene_.models[bodies_[static_cast<size_t>(i)].model])) + "' and '" +
                 name_of(scene_.models[model_b]) + "' overlap at t = " + std::to_string(t) +
                 " s; their contact is ignored until they separate");
    }

    void unignore(int i, int other) {
        if (ignored_.erase(pair_key(i, other)) && other < 0) --bodies_[static_cast<size_t>(i)].ignored_obstacles;
    }

    bool is_ignored(int a, int b) const { return !ignored_.empty() && ignored_.count(pair_key(a, b)); }

    // Predicts body i's earliest event after `now`: becoming free, leaving its cell, meeting a
    // body or an obstacle, or separating from a body it overlapped.
    void predict(int i, double now) {
        Body &b = bodies_[static_cast<size_t>(i)];
        Predicted next;
        if (!b.active) {
            if (b.free_at >= now) next = predicted(b.free_at, EventKind::kActivation);
            set_prediction(i, next);
            return;
        }
        ++count_.predictions;
        if (b.ignored_obstacles > 0) recheck_obstacles(i, now, next);
        if (b.still()) { // still bodies are met, they do not meet: the movers predict
            set_prediction(i, next);
            return;
        }
        const Path path = from_now(b, now);
        double limit = std::min(t_end_, next.t) - now;
        if (b.in_grid)
            if (auto exit = first_exit(path, grid_->bounds(b.cell), limit)) {
                limit = exit->t;
                next = predicted(now + exit->t, EventKind::kCell);
                next.exit = *exit;
            }
        std::size_t tested = 0;
        for_candidates(i, [&](int j) {
            const Body &o = bodies_[static_cast<size_t>(j)];
            if (!o.active) return;
            const Path other = from_now(o, now);
            if (is_ignored(i, j)) {
                // They overlap: the moment they are apart again (|d|^2 - R^2 turns non-negative).
                const glm::dvec3 d = path.p - other.p, e = path.v - other.v, h = 0.5 * (path.a - other.a);
                const double reach = b.radius + o.radius;
                Quartic gap = {glm::dot(d, d) - reach * reach, 2.0 * glm::dot(d, e), glm::dot(e, e) + 2.0 * glm::dot(d, h),
                               2.0 * glm::dot(e, h), glm::dot(h, h)};
                for (double &c : gap) c = -c;
                if (auto s = first_contact(gap, 0.0, limit); s && now + *s < next.t) {
                    next = predicted(now + *s, EventKind::kRelease, j);
                    limit = *s;
                }
                return;
            }
            ++tested;
            if (auto c = sphere_sphere(path, b.radius, other, o.radius, limit)) {
                next = predicted(now + c->t, EventKind::kBody, j, o.version, *c);
                limit = c->t;
            }
        });
        count_.done += tested;
        count_.skipped += (bodies_.size() - 1) - tested;
        predict_obstacles(i, path, now, limit, next);
        set_prediction(i, next);
    }

    void predict_obstacles(int i, const Path &path, double now, double limit, Predicted &next) {
        const Body &b = bodies_[static_cast<size_t>(i)];
        std::size_t tested = 0;
        for (size_t o = 0; o < obstacles_.size(); ++o) {
            if (b.ignored_obstacles > 0 && is_ignored(i, -1 - static_cast<int>(o))) continue;
            const Obstacle &ob = obstacles_[o];
            // Broad phase: the swept sphere must reach the obstacle's bounding sphere.
            const Path fixed{ob.center, glm::dvec3(0.0), glm::dvec3(0.0)};
            if (!(glm::length(path.p - ob.center) <= b.radius + ob.radius) &&
                !sphere_sphere(path, b.radius, fixed, ob.radius, limit))
                continue;
            // Each triangle only if the swept sphere's box reaches the triangle's box.
            Box reach = swept_box(path, limit);
            reach.lo -= glm::dvec3(b.radius);
            reach.hi += glm::dvec3(b.radius);
            for (size_t k = 0; k + 2 < ob.corners.size(); k += 3) {
                if (!reach.overlaps(ob.boxes[k / 3])) continue;
                ++tested;
                if (auto c = sphere_triangle(path, b.radius, ob.corners[k], ob.corners[k + 1], ob.corners[k + 2], limit)) {
                    next = predicted(now + c->t, EventKind::kObstacle, static_cast<int>(o), 0, *c);
                    limit = c->t;
                }
            }
        }
        count_.done += tested;
        count_.skipped += triangle_count_ - tested;
    }

    // A body overlapping an obstacle is checked again after it has moved by a fraction of its
    // radius (or at its next event, if sooner), and collides with it again once apart.
    void recheck_obstacles(int i, double now, Predicted &next) {
        const Body &b = bodies_[static_cast<size_t>(i)];
        for (size_t o = 0; o < obstacles_.size(); ++o)
            if (is_ignored(i, -1 - static_cast<int>(o)) && !overlaps_obstacle(b, obstacles_[o], now))
                unignore(i, -1 - static_cast<int>(o));
        if (b.ignored_obstacles == 0 || b.still()) return;
        const Path path = from_now(b, now);
        const double speed = glm::length(path.v) + std::sqrt(glm::length(path.a) * b.radius);
        next = predicted(now + 0.25 * b.radius / speed, EventKind::kRecheck);
    }

    void set_prediction(int i, const Predicted &p) {
        predicted_[static_cast<size_t>(i)] = p;
        queue_->set(static_cast<size_t>(i), p.t);
    }

    void handle(int i, const Predicted &event, double now) {
        Body &b = bodies_[static_cast<size_t>(i)];
        switch (event.kind) {
        case EventKind::kNone:
            break;
        case EventKind::kActivation:
            activate(b, now, leaving_keys(b.model, now));
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
            collide_bodies(b, o, event.contact, now);
            predict(event.other, now);
            break;
        }
        case EventKind::kObstacle:
            collide_obstacle(b, obstacles_[static_cast<size_t>(event.other)], event.contact, now);
            break;
        case EventKind::kRelease:
            unignore(i, event.other);
            break;
        case EventKind::kRecheck:
            break; // predict() rechecks
        }
        predict(i, now);
    }

    void collide_obstacle(Body &b, const Obstacle &o, const Contact &contact, double t) {
        const glm::dvec3 n = contact.normal;
        const glm::dvec3 v = b.path.velocity(t - b.t0);
        ani_collision_event e{};
        e.t = t;
        e.a = b.model;
        e.b = o.model;
        e.normal = ani(n);
        e.point = ani(contact.point);
        e.speed = std::max(0.0, -glm::dot(v, n));
        // Off a model without Dynamics: a reflection; without Dynamics itself it stops.
        restart(b, t, reflect(v, n), !b.dynamics);
        report(e);
    }

    void collide_bodies(Body &b, Body &o, const Contact &contact, double t) {
        const glm::dvec3 n = contact.normal;
        const glm::dvec3 v = b.path.velocity(t - b.t0), vo = o.path.velocity(t - o.t0);
        ani_collision_event e{};
        e.t = t;
        e.a = b.model;
        e.b = o.model;
        e.normal = ani(n);
        e.point = ani(contact.point);
        e.speed = std::max(0.0, -glm::dot(v - vo, n));
        if (b.dynamics && o.dynamics) {
            const double ma = scene_.models[b.model].desc->mass, mb = scene_.models[o.model].desc->mass;
            const auto [va, vb] = elastic_exchange(ma, v, mb, vo, n);
            restart(b, t, va, false);
            restart(o, t, vb, false);
        } else {
            // A model without Dynamics stops at the contact; one with Dynamics reflects off it as
            // off a wall moving at its velocity then.
            restart(b, t, b.dynamics ? reflect_off_moving_wall(v, vo, n) : glm::dvec3(0.0), !b.dynamics);
            restart(o, t, o.dynamics ? reflect_off_moving_wall(vo, v, -n) : glm::dvec3(0.0), !o.dynamics);
        }
        report(e);
    }

    void report(const ani_collision_event &e) {
        ++count_.collisions;
        if (sink_.event) sink_.event(sink_.context, &e);
    }

    // The work counted, for `animator bake --stats` (ABI 1.1 hosts).
    void report_counts() {
        if (!sink_.count) return;
        const std::pair<const char *, std::size_t> counts[] = {
            {"pair tests done", count_.done},       {"pair tests skipped", count_.skipped},
            {"predictions", count_.predictions},    {"stale predictions", count_.stale},
            {"cell crossings", count_.crossings},   {"collisions", count_.collisions},
        };
        for (const auto &[name, value] : counts) sink_.count(sink_.context, name, static_cast<double>(value));
    }

    void log_once(const std::string &message) {
        if (host_ && host_->log) host_->log(host_, ANI_LOG_WARNING, "physics.custom", message.c_str());
    }

    const ani_physics_scene &scene_;
    double t_begin_, t_end_;
    const ani_bake_sink &sink_;
    const ani_host *host_;
    BakeOptions options_;
    glm::dvec3 gravity_;
    std::vector<Body> bodies_;
    std::vector<Obstacle> obstacles_;
    std::size_t triangle_count_ = 0;
    std::unique_ptr<UniformGrid> grid_; // with many bodies
    std::vector<int> outside_;          // active bodies not in the grid (all of them without one)
    std::unique_ptr<EventQueue> queue_;
    std::vector<Predicted> predicted_;  // each body's earliest event
    // Pairs that started overlapping (physics.md): reported once, ignored until they separate.
    // Keys: (body, other body) with the lower first, or (body, -1 - obstacle).
    std::set<std::pair<int, int>> ignored_;
    struct {
        std::size_t done = 0, skipped = 0, predictions = 0, stale = 0, crossings = 0, collisions = 0;
    } count_;
    std::size_t reports_ = 0;
};

} // namespace

void bake_scene(const ani_physics_scene &scene, double t_begin, double t_end, const ani_bake_sink &sink,
                const ani_host *host, const BakeOptions &options) {
    EventBake(scene, t_begin, t_end, sink, host, options).run();
}

} // namespace physics_custom
