// The event-driven bake's time of impact (physics.md, "Where the code is"): the gaps between
// bodies and obstacles, conservative advancement, and each body's earliest predicted event
// (predict). Relies on time_of_impact.hpp, mesh_contact.hpp, mesh_distance.hpp and
// turning_contact.hpp for the mathematics, and on bake_broad_phase.cpp for the candidates.
#include "event_bake_detail.hpp"

namespace physics_custom::bake {

namespace {
constexpr double kContactSlack = 1e-9; // turning_contact.hpp's contact slack (m)

// The first contact within `limit` of a sphere (centre on `path`, radius r) with the triangles
// of `ob` as they stand, exact (sphere_triangle), each tested only where the swept sphere's box
// reaches the triangle's, and not where skip(triangle) says. `tested` counts the triangles
// tested.
template <class Skip>
std::optional<Contact> sphere_against_triangles(const Path &path, double r, const Obstacle &ob,
                                                double limit, Skip skip, std::size_t &tested) {
    Box reach = swept_box(path, limit);
    reach.lo -= glm::dvec3(r);
    reach.hi += glm::dvec3(r);
    std::optional<Contact> first;
    for (size_t k = 0; k + 2 < ob.corners.size(); k += 3) {
        if (!reach.overlaps(ob.boxes[k / 3]) || skip(k / 3)) continue;
        ++tested;
        if (auto c = sphere_triangle(path, r, ob.corners[k], ob.corners[k + 1], ob.corners[k + 2],
                                     limit)) {
            first = c;
            limit = c->t;
        }
    }
    return first;
}
} // namespace

// The nearest point of a mesh body (at pose p) to q.
glm::dvec3 EventBake::nearest_on_mesh(const Body &b, const Pose &p, const glm::dvec3 &q) const {
    const ani_mesh_view &mesh = mesh_of(b);
    glm::dvec3 best = p.center;
    double best_d = kNever;
    for (uint32_t k = 0; k < mesh.triangle_count; ++k) {
        const uint32_t *tri = mesh.triangles + 3 * static_cast<size_t>(k);
        const glm::dvec3 c = closest_point_on_triangle(
            q, p.center + p.linear * vertex(mesh, tri[0]),
            p.center + p.linear * vertex(mesh, tri[1]), p.center + p.linear * vertex(mesh, tri[2]));
        const double d = glm::length(q - c);
        if (d < best_d) {
            best_d = d;
            best = c;
        }
    }
    return best;
}

glm::dvec3 EventBake::nearest_on_obstacle(const Obstacle &o, const glm::dvec3 &q) const {
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
double EventBake::point_speed(const Body &b, double t, double dt) const {
    if (b.free_sphere()) return glm::length(b.path.velocity(t - b.t0)) + glm::length(b.path.a) * dt;
    if (b.turning()) // its centre's speed, and |w| times its reach from its centre of mass
        return glm::length(b.path.velocity(t - b.t0)) + glm::length(b.path.a) * dt +
               b.spin.rate_bound() * b.turning_reach_now();
    const double h = std::max(1e-6, dt);
    const Pose p = pose(b, t), q = pose(b, t + h);
    const double reach = b.sphere ? 0.0 : b.reach;
    const double turning = frobenius(q.linear - p.linear) / h * reach;
    const double speed = std::max(glm::length(p.velocity), glm::length(q.velocity)) + turning;
    // Keyed motion is known only by evaluation: a margin for its changes within the step.
    return b.driven() ? 1.5 * speed + 1e-12 : speed + glm::length(b.path.a) * dt;
}

// The velocity of the material point of body b at `point` at time t (a keyed model turning
// or scaling moves each of its points differently).
glm::dvec3 EventBake::point_velocity(const Body &b, const glm::dvec3 &point, double t) const {
    if (b.turning())
        return b.path.velocity(t - b.t0) + glm::cross(b.spin.rate(t), point - b.path.at(t - b.t0));
    if (!b.driven()) return b.path.velocity(t - b.t0); // free: it translates
    const Pose p = pose(b, t);
    if (b.sphere) return p.velocity;
    const glm::dvec3 local = glm::inverse(p.linear) * (point - p.center);
    const double h = 1e-6 * std::max(1.0, std::abs(t));
    const Pose before = pose(b, t - h), after = pose(b, t + h);
    return ((after.center + after.linear * local) - (before.center + before.linear * local)) /
           (2.0 * h);
}

// ---- gaps, and overlaps at the start -------------------------------------------------

double EventBake::gap_between(const Body &a, const Body &b, double t, Contact *contact) const {
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
double EventBake::mesh_gap(const Body &a, const Body &b, double t, Contact *contact) const {
    const Pose pa = pose(a, t), pb = pose(b, t);
    const double ra = a.reach * frobenius(pa.linear), rb = b.reach * frobenius(pb.linear);
    const double far = glm::length(pa.center - pb.center) - ra - rb;
    if (far > 0.25 * (ra + rb) && !contact) return far;
    glm::dvec3 on_a, on_b, n;
    const double gap = mesh_distance(placed(a, pa), placed(b, pb), on_a, on_b, n);
    if (contact) fill_contact(on_a, on_b, n, t, contact);
    return gap;
}

void EventBake::fill_contact(const glm::dvec3 &on_a, const glm::dvec3 &on_b, const glm::dvec3 &n,
                             double t, Contact *contact) {
    contact->normal = n;
    contact->point = 0.5 * (on_a + on_b);
    contact->t = t;
}

double EventBake::gap_to_obstacle(const Body &b, const Obstacle &o, double t,
                                  Contact *contact) const {
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
double EventBake::radius_at(const Body &b, const Pose &p) const {
    if (!b.keyed()) return b.radius;
    return scene_->models[b.model].mesh->bound_radius * frobenius(p.linear) / std::sqrt(3.0);
}

// Whether a sphere is closer to an obstacle than `gap` (negative: overlapping by more).
bool EventBake::within_obstacle(const Body &b, const Obstacle &o, double t, double gap) const {
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

bool EventBake::within_body(const Body &a, const Body &b, double t, double gap) const {
    if (!a.sphere && !b.sphere) return false;
    if (a.free_sphere() && b.free_sphere())
        return glm::length(a.path.at(t - a.t0) - b.path.at(t - b.t0)) < a.radius + b.radius + gap;
    return gap_between(a, b, t) < gap;
}

// Overlapping: closer than touching (which allows for the single precision of meshes).
bool EventBake::overlaps_obstacle(const Body &b, const Obstacle &o, double t) const {
    return within_obstacle(b, o, t, -touching(b));
}

bool EventBake::overlaps_body(const Body &a, const Body &b, double t) const {
    return within_body(a, b, t, -touching(a) - touching(b));
}

// Apart: farther than touching, so that a pair left alone is not met again at once.
bool EventBake::apart_from_obstacle(const Body &b, const Obstacle &o, double t) const {
    // A model that is not a sphere has no distance to an obstacle here: the pair it grazed
    // is left alone while it moves a quarter of its size.
    if (!b.sphere) return t >= b.grazed_until;
    return !within_obstacle(b, o, t, touching(b));
}

bool EventBake::apart_from_body(const Body &a, const Body &b, double t) const {
    return !within_body(a, b, t, touching(a) + touching(b));
}

// A contact met with no speed along its normal (a sphere rolling over the rim of a table,
// grazing an edge) is not a collision: reflecting would change nothing and find the same
// contact again at once. The pair is left alone until they are apart.
bool EventBake::grazing(const glm::dvec3 &relative_velocity, const glm::dvec3 &n) {
    return -glm::dot(relative_velocity, n) <= 1e-9 * std::max(1.0, glm::length(relative_velocity));
}

// Meshes are read in single precision, so a sphere placed on a face can be inside it by a
// few 1e-8 of its radius: that much is touching, not overlapping.
double EventBake::touching(const Body &b) {
    return 1e-6 * b.radius;
}

// How close counts as touching for conservative advancement: a trillionth of the size.
double EventBake::tolerance(const Body &b) {
    return 1e-12 * std::max(1.0, b.sphere ? b.radius : b.reach);
}

// ---- predictions -----------------------------------------------------------------------

// Predicts body i's earliest event after `now`: leaving or resuming its keys, leaving its
// cell, meeting a body or an obstacle, or separating from one it overlapped.
void EventBake::predict(int i, double now) {
    Body &b = bodies_[static_cast<size_t>(i)];
    Predicted next;
    if (b.keyed())
        next = predicted(b.keys_end, EventKind::kActivation);
    else if (b.resume_at < kNever)
        next = predicted(b.resume_at, EventKind::kResume);
    if (b.settles_at < next.t) next = predicted(b.settles_at, EventKind::kSettle);
    if (b.carrier >= 0 && b.carrier_until < next.t) // its carrier's next key (bake_carrier.cpp)
        next = predicted(b.carrier_until, EventKind::kCarrier);
    if (b.carried() && b.carried_until < next.t) // the end of the span it sticks to its carrier
        next = predicted(b.carried_until, EventKind::kCarrier);
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
    predict_friction(i, now, limit, next);
    if (b.in_grid)
        if (auto exit = first_exit(from_now(b, now), grid_->bounds(b.cell), limit)) {
            limit = exit->t;
            next = predicted(now + exit->t, EventKind::kCell);
            next.exit = *exit;
        }
    std::size_t tested = 0;
    const bool free_sphere = b.free_sphere();
    const Path here = from_now(b, now);
    for_candidates(i, [&](int j) {
        const Body &o = bodies_[static_cast<size_t>(j)];
        if (!o.active) return;
        if (free_sphere && o.free_sphere()) {
            // Two free spheres (the gas): neither carries the other nor tips over an edge. (Kept
            // apart from the general branch below: folded into it, the 10,000-ball gas took 5%
            // more time.)
            if (!is_ignored(i, j)) {
                ++tested;
                const Path there = from_now(o, now);
                // With the same acceleration, a pair that is not closing cannot meet (what
                // sphere_sphere answers first): half the neighbours, without the call.
                const bool closing =
                    here.a != there.a || glm::dot(here.p - there.p, here.v - there.v) < 0.0;
                double rb = b.radius, ro = o.radius;
                if (closing) radii_against(i, j, rb, ro);
                if (auto c = closing ? sphere_sphere(here, rb, there, ro, limit) : std::nullopt) {
                    next = predicted(now + c->t, EventKind::kBody, j, o.version, *c);
                    limit = c->t;
                }
            }
            if (is_ignored(i, j) || is_overlapped(i, j)) predict_release(i, j, now, limit, next);
            return;
        }
        if (riders_ > 0 && carries(i, j)) return; // held on its face: they move together
        // Tipping over an edge of a body that stands (bake_hinge.cpp): its landing there, or the
        // hinge's end, is the tipping one's own event.
        if (b.hinge && b.hinge->support_body == j) {
            predict_hinge(b, now, next);
            if (next.t - now < limit) limit = next.t - now;
            return;
        }
        if (o.hinge && o.hinge->support_body == i) return;
        if (!is_ignored(i, j)) {
            ++tested;
            std::optional<Contact> c;
            std::vector<glm::dvec3> points; // every point touching, for a turning body
            bool moving_in = false;
            if (sphere_and_translating(i, j, now, limit, next, c)) {
                // exact in the frame of the one that translates (c: their contact, if any)
            } else if (b.shape && o.shape && !b.carried() && !o.carried()) { // both translate
                if (!(b.still() && o.still()))
                    c = mesh_pair(*b.shape, here, *o.shape, from_now(o, now), limit);
            } else if (TurningView vb, vo; (b.turning() || o.turning()) &&
                                           turning_view(i, now, vb) && turning_view(j, now, vo)) {
                // Both turn, or one turns and the other translates without turning (a box with
                // Rotates off, a platform released from its keys): certified advancement.
                if (!(b.still() && o.still()))
                    c = turning_pair_once(i, j, vb, vo, now, limit, points);
                moving_in = true;
            } else if (!(b.still() && o.still()))
                c = advance(i, j, -1, now, limit); // may find them overlapping, and ignore them
            if (c) {
                next = predicted(now + c->t, EventKind::kBody, j, o.version, *c);
                next.points = points;
                next.moving_in = moving_in;
                limit = c->t;
            }
        }
        if (is_ignored(i, j) || is_overlapped(i, j)) predict_release(i, j, now, limit, next);
    });
    count_.done += tested;
    count_.skipped += (bodies_.size() - 1) - tested;
    if (b.supported()) predict_leave(i, now, limit, next);
    if (b.shape && !b.carried())
        predict_mesh_obstacles(i, now, limit, next); // exact: it translates on its path
    else
        predict_obstacles(i, now, limit, next); // spheres exact; keyed or carried: advancement
    if (b.ignored_obstacles > 0 || b.overlapped_obstacles > 0) recheck_obstacles(i, now, next);
    // Nothing within the window: it looks again at its end.
    if (next.t > horizon_) next = predicted(horizon_, EventKind::kRecheck);
    set_prediction(i, next);
}

// Two overlapping bodies: the moment they are apart again.
void EventBake::predict_release(int i, int j, double now, double &limit, Predicted &next) {
    const Body &b = bodies_[static_cast<size_t>(i)], &o = bodies_[static_cast<size_t>(j)];
    std::optional<double> s;
    if (b.free_sphere() && o.free_sphere()) {
        // |d|^2 - R^2 turns non-negative.
        const Path path = from_now(b, now), other = from_now(o, now);
        const glm::dvec3 d = path.p - other.p, e = path.v - other.v, h = 0.5 * (path.a - other.a);
        const double reach = b.radius + o.radius + touching(b) + touching(o);
        Quartic gap = {glm::dot(d, d) - reach * reach, 2.0 * glm::dot(d, e),
                       glm::dot(e, e) + 2.0 * glm::dot(d, h), 2.0 * glm::dot(e, h), glm::dot(h, h)};
        for (double &c : gap) c = -c;
        s = first_contact(gap, 0.0, limit);
    } else if (apart_from_body(b, o, now)) {
        s = 0.0;
    } else {
        // Looked at again after either has moved a quarter of the smaller size.
        const double size = std::min(b.sphere ? b.radius : b.reach, o.sphere ? o.radius : o.reach);
        const double speed = point_speed(b, now, 0.0) + point_speed(o, now, 0.0);
        if (speed > 0.0) s = std::min(limit, 0.25 * size / speed);
    }
    if (s && now + *s < next.t) {
        next = predicted(now + *s, EventKind::kRelease, j);
        limit = *s;
    }
}

// A sphere (free, turning or not) and a body that translates at a constant velocity u without
// turning (a keyed platform between two of its keys, or one that stands: carried_motion). In
// that body's frame, inertial, the sphere's centre is still a parabola, p + (v - u) t + a t^2 / 2,
// and the body's triangles stand: the exact sphere-triangle test of a static model holds, up
// to where u changes (a recheck then, `limit` shortened to it). Conservative advancement
// crawled there: a ball rolling off a moving platform's rim left it in 2.4 million steps of
// about 1e-12 s, its closing-speed bound (every point's speed) far above the gap's opening.
// False where it does not apply; else `contact` is their first contact within `limit`, if any.
bool EventBake::sphere_and_translating(int i, int j, double now, double &limit, Predicted &next,
                                       std::optional<Contact> &contact) {
    const Body &b = bodies_[static_cast<size_t>(i)], &o = bodies_[static_cast<size_t>(j)];
    if (b.sphere == o.sphere) return false;
    const int si = b.sphere ? i : j, mi = b.sphere ? j : i;
    const Body &sphere = bodies_[static_cast<size_t>(si)];
    const Body &mover = bodies_[static_cast<size_t>(mi)];
    if (sphere.keyed() || sphere.carried() || mover.turning() || is_overlapped(i, j)) return false;
    const std::optional<Carried> motion = carried_motion(mi, now);
    if (!motion) return false;
    const double span = std::min(limit, motion->until - now);
    if (!(span > 0.0)) return false;
    if (span < limit) { // where its velocity may change: look again
        if (now + span < next.t) next = predicted(now + span, EventKind::kRecheck);
        limit = span;
    }
    if (sphere.still() && motion->velocity == glm::dvec3(0.0)) return true; // neither moves
    const Path path = from_now(sphere, now);
    const Path relative{path.p, path.v - motion->velocity, path.a};
    std::size_t tested = 0; // counted as the one pair it is (predict)
    std::optional<Contact> first = sphere_against_triangles(
        relative, sphere.radius, face_of(mover, now), span, [](size_t) { return false; }, tested);
    if (first) {
        first->point += motion->velocity * first->t;   // where the mover is then
        if (!b.sphere) first->normal = -first->normal; // from j towards i
        contact = first;
    }
    return true;
}

// Conservative advancement (keyed_contact.hpp) between body i and body j, or obstacle
// `obstacle` when j < 0, over [now, now + limit]. Returns the contact, times from now.
std::optional<Contact> EventBake::advance(int i, int j, int obstacle, double now, double limit) {
    const Body &b = bodies_[static_cast<size_t>(i)];
    const Body *o = j >= 0 ? &bodies_[static_cast<size_t>(j)] : nullptr;
    const Obstacle *ob = obstacle >= 0 ? &obstacles_[static_cast<size_t>(obstacle)] : nullptr;
    Approach approach;
    approach.gap = [&](double t) { return o ? gap_between(b, *o, t) : gap_to_obstacle(b, *ob, t); };
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

void EventBake::predict_obstacles(int i, double now, double limit, Predicted &next) {
    const Body &b = bodies_[static_cast<size_t>(i)];
    std::size_t tested = 0;
    for (size_t o = 0; o < obstacles_.size(); ++o) {
        if (b.ignored_obstacles > 0 && is_ignored(i, -1 - static_cast<int>(o))) continue;
        const Obstacle &ob = obstacles_[o];
        if (b.turning()) {
            // Resting or sliding on it without turning: it leaves it by predict_leave.
            if (b.support == static_cast<int>(o) && b.spin.w == glm::dvec3(0.0)) continue;
            if (b.hinge && b.hinge->support == static_cast<int>(o)) { // tipping over its edge
                predict_hinge(b, now, next);
                if (next.kind == EventKind::kObstacle && next.t - now < limit) limit = next.t - now;
                if (!b.hinge->beyond.empty()) { // the rest of it within reach
                    ++tested;
                    predict_turning_obstacle(i, o, now, limit, next, &b.hinge->beyond);
                    if (next.kind == EventKind::kObstacle && next.t - now < limit)
                        limit = next.t - now;
                }
                continue;
            }
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
        const bool on_it = b.support == static_cast<int>(o);
        if (auto c = sphere_against_triangles(
                path, r, ob, limit,
                [&](size_t k) { return on_it && in_support_plane(b, ob, k); }, // it slides on these
                tested)) {
            next = predicted(now + c->t, EventKind::kObstacle, static_cast<int>(o), 0, *c);
            limit = c->t;
        }
    }
    count_.done += tested;
    count_.skipped += triangle_count_ - std::min(tested, triangle_count_);
}

// The seed's mesh-mesh tests (mesh_contact.hpp), counted.
std::optional<Contact> EventBake::mesh_pair(const MeshShape &a, const Path &pa, const MeshShape &b,
                                            const Path &pb, double limit) {
    PairStats stats;
    auto c = mesh_mesh(a, pa, b, pb, limit, &stats);
    count_.mesh_tests += stats.primitive_tests;
    return c;
}

// A free model that is not a sphere against the static models.
void EventBake::predict_mesh_obstacles(int i, double now, double limit, Predicted &next) {
    const Body &b = bodies_[static_cast<size_t>(i)];
    if (b.still()) return;
    const Path path = from_now(b, now), fixed{};
    for (size_t o = 0; o < obstacles_.size(); ++o) {
        if (b.ignored_obstacles > 0 && is_ignored(i, -1 - static_cast<int>(o))) continue;
        // While it overlaps the obstacle, it is tested moved out by its depth (touching).
        const glm::dvec3 shift = shift_against(i, static_cast<int>(o));
        const Path moved{path.p + shift, path.v, path.a};
        if (auto c =
                mesh_pair(*b.shape, moved, shape_facing(obstacles_[o], moved.p), fixed, limit)) {
            c->point -= shift;
            next = predicted(now + c->t, EventKind::kObstacle, static_cast<int>(o), 0, *c);
            limit = c->t;
        }
    }
}

// A closed static mesh is solid from outside; for a model inside it (a box in a cube used
// as a room) it is a room, its faces met from within.
const MeshShape &EventBake::shape_facing(const Obstacle &o, const glm::dvec3 &p) const {
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
bool EventBake::inside(const Obstacle &o, const glm::dvec3 &p) {
    const Box box = o.shape->bounds();
    if (p.x < box.lo.x || p.y < box.lo.y || p.z < box.lo.z || p.x > box.hi.x || p.y > box.hi.y ||
        p.z > box.hi.z)
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

// A body overlapping an obstacle is checked again after it has moved by a fraction of its
// radius (or at its next event, if sooner), and collides with it again once apart.
void EventBake::recheck_obstacles(int i, double now, Predicted &next) {
    const Body &b = bodies_[static_cast<size_t>(i)];
    for (size_t o = 0; o < obstacles_.size(); ++o)
        if (is_ignored(i, -1 - static_cast<int>(o)) && apart_from_obstacle(b, obstacles_[o], now))
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
double EventBake::recheck_after(const Body &b, double now) const {
    const double size = body_size(b);
    const double speed = point_speed(b, now, 0.0) + std::sqrt(glm::length(b.path.a) * size);
    return speed > 0.0 ? 0.25 * size / speed : kNever;
}

void EventBake::set_prediction(int i, const Predicted &p) {
    predicted_[static_cast<size_t>(i)] = p;
    queue_->set(static_cast<size_t>(i), p.t);
}

// ---- turning models: their time of impact (their response: bake_response.cpp) -----------

// The path of turning body b from `now`, times from now (turning_contact.hpp's form).
TurningPath EventBake::turning_path(const Body &b, double now) const {
    TurningPath path;
    path.c0 = b.path.at(now - b.t0);
    path.v = b.path.velocity(now - b.t0);
    path.a = b.path.a;
    path.q0 = b.spin.at(now);
    path.w = b.spin.w;
    if (b.spin.torque_free() || b.spin.hinge) { // w changes: bounded over all time
        const Spin spin = b.spin;
        path.turn = [spin, now](double t) { return spin.at(now + t); };
        path.turn_rate = [spin, now](double t) { return spin.rate(now + t); };
        path.w_bound = spin.rate_bound();
        path.w_rate_bound = spin.rate_change_bound();
    }
    return path;
}

TurningMesh EventBake::turning_mesh(const Body &b) const {
    const ani_mesh_view &mesh = mesh_of(b);
    const std::vector<glm::dvec3> &vertices = b.hinge ? b.hinge->vertices : b.turning_vertices;
    return {vertices.data(),     vertices.size(), mesh.triangles,
            mesh.triangle_count, b.edges.data(),  b.edges.size()};
}

// A turning body against a static model: the first contact within [now, now + limit] at which
// it moves into the obstacle (contact_moving_in).
void EventBake::predict_turning_obstacle(int i, size_t o, double now, double limit, Predicted &next,
                                         const std::vector<uint32_t> *only) {
    const Body &b = bodies_[static_cast<size_t>(i)];
    const Obstacle &ob = obstacles_[o];
    const TurningPath path = turning_path(b, now);
    // Broad phase: the centre cannot come nearer the obstacle's bounding sphere than it is
    // by more than it travels.
    const double travel = glm::length(path.v) * limit + 0.5 * glm::length(path.a) * limit * limit;
    if (glm::length(path.c0 - ob.center) - b.turning_reach_now() - ob.radius > travel) return;
    const TurningMesh mesh = turning_mesh(b);
    // Of a larger obstacle (a staircase), only the triangles it can reach within a window in
    // which it travels no further than its own size: each step of the advancement tests every
    // pair of triangles, and a model hopping on a face (tipping by microcollisions) makes many
    // short predictions. Past the window, it is predicted again (a recheck).
    double window = limit;
    auto recheck_after_window = [&] {
        if (window < limit && now + window < next.t)
            next = predicted(now + window, EventKind::kRecheck);
    };
    std::vector<uint32_t> near;
    if (only) { // some of its triangles only (bake_hinge.cpp: beyond a hinge's edge)
        near = *only;
    } else if (ob.boxes.size() > 4) {
        const double speed = glm::length(path.v), accel = glm::length(path.a),
                     size = b.turning_reach_now();
        if (travel > size) // speed w + accel w^2 / 2 = size
            window = accel > 0.0
                         ? 2.0 * size / (speed + std::sqrt(speed * speed + 2.0 * accel * size))
                         : size / speed;
        Box reach = swept_box(Path{path.c0, path.v, path.a}, window);
        reach.lo -= glm::dvec3(b.turning_reach_now() + 1e-6);
        reach.hi += glm::dvec3(b.turning_reach_now() + 1e-6);
        for (size_t k = 0; k < ob.boxes.size(); ++k)
            if (reach.overlaps(ob.boxes[k]))
                near.insert(near.end(), ob.shape->triangles[k].begin(),
                            ob.shape->triangles[k].end());
        if (near.empty()) return recheck_after_window();
    }
    const TurningMesh soup{ob.shape->vertices.data(),
                           ob.shape->vertices.size(),
                           !near.empty()                 ? near.data()
                           : ob.shape->triangles.empty() ? nullptr
                                                         : &ob.shape->triangles[0][0],
                           !near.empty() ? near.size() / 3 : ob.shape->triangles.size(),
                           ob.shape->edges.data(),
                           ob.shape->edges.size()};
    const std::optional<TurningContact> moving_in =
        contact_moving_in(b, mesh, path, nullptr, soup, TurningPath{}, now, window,
                          [&](TurningContact &c) { outward(c, path); });
    if (!moving_in) return; // nothing moves: nothing to meet
    const TurningContact &c = *moving_in;
    if (c.kind == TurningContact::kInvalid)
        throw ani::Failure(ANI_ERR_FAILED, std::string("model '") +
                                               name_of(scene_->models[b.model]) +
                                               "' would turn to a value that is not finite");
    if (!c.found() && c.kind != TurningContact::kUndecided) return recheck_after_window();
    if (now + c.t >= next.t) return;
    Contact contact;
    contact.t = c.t;
    contact.point = c.point;
    // Undecided: looked at again from there (a zero normal).
    contact.normal = c.found() ? c.normal : glm::dvec3(0.0);
    next = predicted(now + c.t, EventKind::kObstacle, static_cast<int>(o), 0, contact);
    next.points = c.found() ? c.points : std::vector<glm::dvec3>{};
}

// The first contact of turning body b (mesh mb on path pb) with body o (or, o null, a static
// model: mesh mo on a still path) within [now, now + window] at which a point moves in: one found
// where every point within the contact slack moves away or along (just after a bounce, as it
// leaves, or sliding over it) is passed, the search going on a step later in which no point can
// close the slack (at most 1,000 times; then the contact is reported, and handle() leaves the pair
// alone until apart). `orient` turns each contact's normal from o towards b. A contact of kind
// kNone when none is found; none at all when nothing moves at a contact passed.
std::optional<TurningContact>
EventBake::contact_moving_in(const Body &b, const TurningMesh &mb, const TurningPath &pb,
                             const Body *o, const TurningMesh &mo, const TurningPath &po,
                             double now, double window,
                             const std::function<void(TurningContact &)> &orient) {
    double from = 0.0;
    TurningContact c;
    for (int tries = 0;; ++tries) {
        c = turning_mesh_contact(mb, pb, mo, po, from, window);
        count_.mesh_tests += c.pair_tests;
        orient(c);
        if (!(c.found() && tries < 1000 && !approaching(b, c, now + c.t, o))) return c;
        const double speed =
            point_speed(b, now + c.t, 1e-6) + (o ? point_speed(*o, now + c.t, 1e-6) : 0.0);
        if (!(speed > 0.0)) return std::nullopt;
        from = c.t + std::min(1e-6, 0.5 * kContactSlack / speed); // the bound holds for 1e-6 s
        if (from >= window) {
            c.kind = TurningContact::kNone;
            return c;
        }
    }
}

// Body i seen as turning_contact.hpp sees a turning body. One that turns (not tipping over an
// edge: bake_hinge.cpp) as it turns. A free one that does not turn (a box with Rotates off, a
// platform released from its keys) as a mesh that turns by nothing, its triangles turned and
// scaled as its keys hold them: for as long as they hold them (to its next key, or for ever once
// its keys have ended). False for a sphere, a keyed or carried body, a body on a hinge, and a free
// one whose keys turn or scale it now.
bool EventBake::turning_view(int i, double now, TurningView &view) const {
    const Body &b = bodies_[static_cast<size_t>(i)];
    if (b.sphere || b.hinge || b.carried()) return false;
    if (b.turning()) {
        view.mesh = turning_mesh(b);
        view.path = turning_path(b, now);
        view.reach = b.turning_reach_now();
        return true;
    }
    const Pose p = pose(b, now);
    if (b.keyed()) { // its keys translate it at a constant velocity until its next key
        const std::optional<Carried> m = carried_motion(i, now);
        if (!m) return false;
        view.path.v = m->velocity;
        view.holds = m->until - now;
    } else {
        if (now < b.keys_end) { // released from its keys, until its next key
            const double end = std::min(next_key(b.model, now), b.keys_end);
            if (!(end > now) || !keys_hold_pose(b.model, now, end)) return false;
            view.holds = end - now;
        }
        view.path.v = p.velocity;
        view.path.a = b.path.a;
    }
    const ani_mesh_view &mesh = mesh_of(b);
    view.vertices.resize(mesh.vertex_count);
    for (uint32_t k = 0; k < mesh.vertex_count; ++k) view.vertices[k] = p.linear * vertex(mesh, k);
    view.mesh = {view.vertices.data(), view.vertices.size(), mesh.triangles,
                 mesh.triangle_count,  b.edges.data(),       b.edges.size()};
    view.path.c0 = p.center;
    view.reach = b.reach * frobenius(p.linear);
    return true;
}

// Whether a model's keys hold its angles and scale from t to end, both within one span between
// two keys: equal at t and at four times up to end (for an interpolation at most cubic, equal
// throughout).
bool EventBake::keys_hold_pose(uint32_t model, double t, double end) const {
    const ani_model_state first = keyed(model, t, nullptr);
    for (int k = 1; k <= 4; ++k) {
        const ani_model_state s = keyed(model, t + 0.25 * k * (end - t), nullptr);
        if (!(vec(s.angles) == vec(first.angles)) || !(vec(s.scale) == vec(first.scale)))
            return false;
    }
    return true;
}

// Two bodies of which one turns and the other turns or translates (a box knocked across the one
// it slept on, two tumbling dice, a die against a released platform): their first contact within
// [now, now + limit] at which they move into each other, by the certified advancement of
// turning_contact.hpp, as a turning body meets a static model (predict_turning_obstacle). Where
// a view holds for less than that, it is looked at again then (an undecided contact).
std::optional<Contact> EventBake::predict_turning_pair(int i, int j, const TurningView &vb,
                                                       const TurningView &vo, double now,
                                                       double limit,
                                                       std::vector<glm::dvec3> &points) {
    const Body &b = bodies_[static_cast<size_t>(i)], &o = bodies_[static_cast<size_t>(j)];
    const double holds = std::min(vb.holds, vo.holds);
    const bool cut = holds < limit;
    if (cut) limit = holds;
    auto look_again = [&]() -> std::optional<Contact> {
        if (!cut) return std::nullopt;
        Contact contact;
        contact.t = limit;
        contact.normal = glm::dvec3(0.0);
        return contact;
    };
    const TurningPath &pb = vb.path, &po = vo.path;
    const TurningMesh &mb = vb.mesh, &mo = vo.mesh;
    // Broad phase: the centres cannot come nearer than they are by more than they travel.
    const double travel =
        (glm::length(pb.v - po.v) + 0.5 * glm::length(pb.a - po.a) * limit) * limit;
    if (glm::length(pb.c0 - po.c0) - vb.reach - vo.reach > travel) return look_again();
    const std::optional<TurningContact> moving_in =
        contact_moving_in(b, mb, pb, &o, mo, po, now, limit, [&](TurningContact &c) {
            if (!c.found()) return;
            c.normal = separating_face_normal(mb, pb, mo, po, c.t, kContactSlack + c.gap, c.normal);
            // The normal from o towards b: the side b's centre is on.
            if (glm::dot(c.normal, pb.center(c.t) - c.point) <
                glm::dot(c.normal, po.center(c.t) - c.point))
                c.normal = -c.normal;
        });
    if (!moving_in) return look_again();
    const TurningContact &c = *moving_in;
    if (c.kind == TurningContact::kInvalid)
        throw ani::Failure(ANI_ERR_FAILED, std::string("models '") +
                                               name_of(scene_->models[b.model]) + "' and '" +
                                               name_of(scene_->models[o.model]) +
                                               "' would turn to a value that is not finite");
    if (!c.found() && c.kind != TurningContact::kUndecided) return look_again();
    Contact contact;
    contact.t = c.t;
    contact.point = c.point;
    contact.normal = c.found() ? c.normal : glm::dvec3(0.0); // undecided: looked at again
    points = c.found() ? c.points : std::vector<glm::dvec3>{};
    return contact;
}

// The pair's first contact within [now, now + limit], as predict_turning_pair finds it, or as it
// found it for the other body of the pair at this same time, when both bodies are seen as they
// were then (their paths, turns, vertices and how long their views hold, to the bit). A contact
// found within the earlier window is the first within this one too if it is within it; none found
// within the earlier window means none within this one if it is no longer.
std::optional<Contact> EventBake::turning_pair_once(int i, int j, const TurningView &vb,
                                                    const TurningView &vo, double now, double limit,
                                                    std::vector<glm::dvec3> &points) {
    if (!pair_memos_.empty() && pair_memos_.begin()->second.now != now) pair_memos_.clear();
    const std::pair<int, int> key(std::min(i, j), std::max(i, j));
    if (auto found = pair_memos_.find(key); found != pair_memos_.end()) {
        const PairMemo &m = found->second;
        const bool swapped = m.i != i;
        const TurningView &ours = swapped ? vo : vb, &theirs = swapped ? vb : vo;
        if (same_view(ours, m.view_i, m.vertices_i) && same_view(theirs, m.view_j, m.vertices_j) &&
            (m.contact || limit <= m.limit)) {
            ++count_.reused;
            if (m.contact && m.contact->t > limit) return std::nullopt;
            points = m.contact ? m.points : std::vector<glm::dvec3>{};
            std::optional<Contact> c = m.contact;
            if (c && swapped) c->normal = -c->normal;
            return c;
        }
    }
    std::optional<Contact> c = predict_turning_pair(i, j, vb, vo, now, limit, points);
    // Views whose turn changes (a top that is not spherical) turn by a function: not kept.
    if (vb.path.turn || vo.path.turn) return c;
    PairMemo m;
    m.i = i;
    m.j = j;
    m.now = now;
    m.limit = limit;
    m.vertices_i.assign(vb.mesh.vertices, vb.mesh.vertices + vb.mesh.vertex_count);
    m.vertices_j.assign(vo.mesh.vertices, vo.mesh.vertices + vo.mesh.vertex_count);
    m.view_i.mesh = vb.mesh;
    m.view_i.path = vb.path;
    m.view_i.reach = vb.reach;
    m.view_i.holds = vb.holds;
    m.view_j.mesh = vo.mesh;
    m.view_j.path = vo.path;
    m.view_j.reach = vo.reach;
    m.view_j.holds = vo.holds;
    m.view_i.mesh.vertices = m.view_j.mesh.vertices = nullptr;
    m.contact = c;
    if (c) m.points = points;
    pair_memos_[key] = std::move(m);
    return c;
}

// Whether a view is the one kept (its mesh's vertices compared with the copy kept of them).
bool EventBake::same_view(const TurningView &view, const TurningView &kept,
                          const std::vector<glm::dvec3> &kept_vertices) {
    const TurningPath &p = view.path, &q = kept.path;
    if (p.turn || q.turn || !(p.c0 == q.c0) || !(p.v == q.v) || !(p.a == q.a) || !(p.w == q.w) ||
        !(p.q0 == q.q0) || view.reach != kept.reach || view.holds != kept.holds)
        return false;
    const TurningMesh &m = view.mesh, &k = kept.mesh;
    return m.triangles == k.triangles && m.triangle_count == k.triangle_count &&
           m.edges == k.edges && m.edge_count == k.edge_count &&
           std::equal(m.vertices, m.vertices + m.vertex_count, kept_vertices.begin(),
                      kept_vertices.end());
}

// The normal of a contact with a static model points from it towards the body's centre (for a
// contact found as they leave each other, turning_mesh_contact orients it by their motion).
void EventBake::outward(TurningContact &c, const TurningPath &path) {
    if (c.found() && glm::dot(c.normal, path.center(c.t) - c.point) < 0.0) c.normal = -c.normal;
}

// Whether any point of a contact found at `now` moves into the obstacle (or into body `other`).
bool EventBake::approaching(const Body &b, const TurningContact &c, double now,
                            const Body *other) const {
    const double still = 1e-12 * std::max(1.0, point_speed(b, now, 0.0) +
                                                   (other ? point_speed(*other, now, 0.0) : 0.0));
    std::vector<glm::dvec3> points = c.points;
    if (points.empty()) points.push_back(c.point);
    for (const glm::dvec3 &p : points) {
        const glm::dvec3 v =
            point_velocity(b, p, now) - (other ? point_velocity(*other, p, now) : glm::dvec3(0.0));
        if (glm::dot(v, c.normal) < -still) return true;
    }
    return false;
}

} // namespace physics_custom::bake
