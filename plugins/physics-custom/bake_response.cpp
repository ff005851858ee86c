// The event-driven bake's response to a contact (physics.md, "Where the code is"): release from
// the keys, the seed's reflections (response.hpp), and the responses with restitution, friction
// and turning (impulse.hpp, simultaneous_contact.hpp), in three sections: spheres, models that
// are not spheres, and models that turn.
#include "event_bake_detail.hpp"

namespace physics_custom::bake {

// A keyed body that collides is released from its keys (physics.md): free from the contact
// until its next key, with the velocity its keys gave it, or at rest without Dynamics.
void EventBake::release(int i, double t) {
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

// The event said for a contact of models a and b at t, met at relative velocity `closing` (its
// speed: how fast they approach along the normal).
ani_collision_event EventBake::collision_event(uint32_t a, uint32_t b, const Contact &contact,
                                               double t, const glm::dvec3 &closing) {
    ani_collision_event e{};
    e.t = t;
    e.a = a;
    e.b = b;
    e.normal = ani(contact.normal);
    e.point = ani(contact.point);
    e.speed = std::max(0.0, -glm::dot(closing, contact.normal));
    return e;
}

void EventBake::collide_obstacle(int i, const Obstacle &o, const Contact &contact,
                                 const std::vector<glm::dvec3> &points, double t) {
    Body &b = bodies_[static_cast<size_t>(i)];
    if (b.keyed()) release(i, t);
    const glm::dvec3 n = contact.normal;
    const glm::dvec3 v = b.path.velocity(t - b.t0);
    // (A turning model's speed is its touching point's.)
    const ani_collision_event e = collision_event(
        b.model, o.model, contact, t, b.turning() ? point_velocity(b, contact.point, t) : v);
    // Off a model without Dynamics: a reflection; without Dynamics itself it stops. With
    // restitution or friction, or turning (which needs Dynamics): the contact impulse (the
    // sections below).
    if (!b.dynamics || (!b.turning() && !sphere_responds(b, o.model)))
        restart(b, t, reflect(v, n), !b.dynamics);
    else if (b.turning() ? respond_turning_to_obstacle(i, o, contact, points, t)
                         : respond_to_obstacle(i, o, n, v, t)) {
        report(e); // resting from the Zeno bounces' accumulation time
        return;
    }
    after_contact(i, t);
    report(e);
}

void EventBake::collide_bodies(int i, int j, const Contact &contact,
                               const std::vector<glm::dvec3> &points, double t) {
    Body &b = bodies_[static_cast<size_t>(i)], &o = bodies_[static_cast<size_t>(j)];
    const glm::dvec3 n = contact.normal;
    if (b.turning() || o.turning()) { // the turning models' section below
        // A keyed body without Dynamics or gravity whose keys hold it still here (a platform
        // between two equal keys) is released from them, as at any contact, and stands: the other
        // meets it as a still one (below), which it may sleep on or tip over.
        for (const int x : {i, j}) {
            const Body &k = bodies_[static_cast<size_t>(x)];
            if (!k.keyed() || k.dynamics || !bodies_[static_cast<size_t>(x == i ? j : i)].turning())
                continue;
            const std::optional<Carried> motion = carried_motion(x, t);
            if (motion && glm::length(motion->velocity) <= 1e-12 && next_key(k.model, t) > t)
                release(x, t);
        }
        if (sleep_on_body(i, j, n, contact.point, t) || sleep_on_body(j, i, -n, contact.point, t)) {
            report(collision_event(b.model, o.model, contact, t,
                                   point_velocity(b, contact.point, t) -
                                       point_velocity(o, contact.point, t)));
            return;
        }
        // A resting body that the blow presses into its support takes it through that support
        // (bake_rest.cpp, "resting on other models"): it stays, as a static model would.
        // So does one without Dynamics that stands (a platform released from its keys).
        const bool b_held = held_by_support(b, n), o_held = held_by_support(o, -n);
        const bool b_still = b_held || (!b.dynamics && immovable(b)),
                   o_still = o_held || (!o.dynamics && immovable(o));
        if (b_still != o_still && (b_still ? o : b).turning() && !b.keyed() && !o.keyed()) {
            const int mover = b_still ? j : i, still = b_still ? i : j;
            Contact towards = contact;
            if (b_still) towards.normal = -n; // from the still one towards the mover
            const ani_collision_event e = collision_event(b.model, o.model, contact, t,
                                                          point_velocity(b, contact.point, t) -
                                                              point_velocity(o, contact.point, t));
            respond_turning_to_held(mover, still, towards, points, t);
            after_contact(mover, t);
            report(e);
            return;
        }
        const ImpulseBody ib = b_held ? ImpulseBody{} : impulse_body(b, contact.point, t),
                          io = o_held ? ImpulseBody{} : impulse_body(o, contact.point, t);
        const bool b_wall = b.keyed(), o_wall = o.keyed();
        const ani_collision_event e = collision_event(
            b.model, o.model, contact, t, point_velocity_of(ib) - point_velocity_of(io));
        if (b_wall) release(i, t);
        if (o_wall) release(j, t);
        respond_turning_pair(b, ib, b_wall || b_held, o, io, o_wall || o_held, n, t);
        after_contact(i, t);
        after_contact(j, t);
        report(e);
        return;
    }
    // A keyed body is a wall of infinite mass moving as its keys say, for the free body it
    // meets: that one reflects off it with the relative velocity (physics.md).
    const glm::dvec3 v = point_velocity(b, contact.point, t),
                     vo = point_velocity(o, contact.point, t);
    // A body still on a carrier, or stuck to one, that the blow presses into it within its
    // friction cone takes the blow through it (bake_rest.cpp, held_by_support): it stays, and the
    // other meets it as a wall moving with the carrier.
    const bool b_held = (b.carrier >= 0 || b.carried()) && !o.keyed() && held_by_support(b, n),
               o_held = (o.carrier >= 0 || o.carried()) && !b.keyed() && held_by_support(o, -n);
    const bool b_wall = (b.keyed() && !o.keyed()) || (b_held && !o_held),
               o_wall = (o.keyed() && !b.keyed()) || (o_held && !b_held);
    if (b.keyed()) release(i, t);
    if (o.keyed()) release(j, t);
    const ani_collision_event e = collision_event(b.model, o.model, contact, t, v - vo);
    if (b_wall || o_wall) {
        Body &free = b_wall ? o : b;
        const glm::dvec3 v_free = b_wall ? vo : v, v_wall = b_wall ? v : vo,
                         n_free = b_wall ? -n : n;
        if (free.dynamics && sphere_responds(free, (b_wall ? b : o).model))
            respond_to_wall(free, v_free, v_wall, n_free, (b_wall ? b : o).material, t);
        else
            restart(free, t,
                    free.dynamics ? reflect_off_moving_wall(v_free, v_wall, n_free)
                                  : glm::dvec3(0.0),
                    !free.dynamics);
    } else if (b.dynamics && o.dynamics && sphere_responds(b, o.model)) {
        respond_to_sphere(b, v, o, vo, n, t);
    } else if (b.dynamics && o.dynamics) {
        const double ma = b.mass, mb = o.mass;
        const auto [va, vb] = elastic_exchange(ma, v, mb, vo, n);
        restart(b, t, va, false);
        restart(o, t, vb, false);
    } else {
        // A model without Dynamics stops at the contact; one with Dynamics reflects off it as
        // off a wall moving at its velocity then.
        if (b.dynamics && sphere_responds(b, o.model))
            respond_to_wall(b, v, vo, n, o.material, t);
        else
            restart(b, t, b.dynamics ? reflect_off_moving_wall(v, vo, n) : glm::dvec3(0.0),
                    !b.dynamics);
        if (o.dynamics && sphere_responds(o, b.model))
            respond_to_wall(o, vo, v, -n, b.material, t);
        else
            restart(o, t, o.dynamics ? reflect_off_moving_wall(vo, v, -n) : glm::dvec3(0.0),
                    !o.dynamics);
    }
    // Off a carrier (a keyed platform, released by the blow and standing still): the Zeno rule
    // puts the model on it once its bounces are too small to follow (bake_carrier.cpp).
    if (!settle_on_carrier(i, j, n, t)) settle_on_carrier(j, i, -n, t);
    after_contact(i, t);
    after_contact(j, t);
    report(e);
}

// Spheres: how a free sphere responds to a contact
// when the pair's restitution or friction is not the seed's (issue 18), and the turning of a
// sphere that `rotates` (start_spin, turn, emit_spin: bake_bodies.cpp). The contact impulse itself
// is impulse.hpp's; the Zeno rule is zeno.hpp's. With e = 1 and mu = 0 the seed's reflections
// (response.hpp) stay in use, bit for bit.

// ---- restitution, friction and spin ----------------------------------------------------

// Whether a body meets the model with something other than the seed's elastic,
// frictionless reflection (a model that is not a sphere: the next section).
bool EventBake::sphere_responds(const Body &b, uint32_t other) const {
    if (!b.sphere) return mesh_responds(b, other);
    const Material &mo = materials_[other];
    return combined_restitution(b.material.restitution, mo.restitution) != 1.0 ||
           combined_friction(b.material.friction, mo.friction) != 0.0;
}

// A free sphere as the impulse module sees it: its contact point at -radius n from its
// centre (n from the other body toward it).
ImpulseBody EventBake::sphere_body(const Body &b, double mass, const glm::dvec3 &v,
                                   const glm::dvec3 &n, double t) {
    ImpulseBody a;
    a.inv_mass = 1.0 / mass;
    if (b.spin.on) a.inv_inertia = glm::dmat3(sphere_inverse_inertia(mass, b.radius));
    a.v = v;
    a.w = b.spin.on ? b.spin.rate(t) : glm::dvec3(0.0);
    a.r = -b.radius * n;
    return a;
}

// Off a static model: the impulse against infinite mass, and the Zeno rule (zeno.hpp) for a
// ball whose bounces on a face have become too small to follow. True when it was put on
// the face (resting or sliding from the accumulation time).
bool EventBake::respond_to_obstacle(int i, const Obstacle &o, const glm::dvec3 &n,
                                    const glm::dvec3 &v, double t) {
    Body &b = bodies_[static_cast<size_t>(i)];
    const Material &mo = materials_[o.model];
    const double e = combined_restitution(b.material.restitution, mo.restitution),
                 mu = combined_friction(b.material.friction, mo.friction);
    const ImpulseBody a = sphere_body(b, 1.0, v, n, t); // against infinite mass: any mass
    const ImpulseResult r = contact_impulse(a, ImpulseBody{}, n, e, mu);
    const double vn = glm::dot(r.va, n), g_n = -glm::dot(b.free_a, n);
    const glm::dvec3 c = b.path.at(t - b.t0), v_t = r.va - vn * n;
    if (zeno_settles(vn, g_n, e, std::max(1.0, glm::length(c)))) {
        // On the face friction goes on acting: it slides, skids or rolls there (bake_rest.cpp).
        const double still = 1e-12 * std::max(1.0, glm::length(v));
        restart(b, t, glm::length(v_t) <= still && mu != 0.0 ? glm::dvec3(0.0) : v_t, false);
        if (b.spin.on) turn(b, t, r.wa);
        if (settle_after_bounces(i, o, n, t)) {
            b.settles_at = zeno_accumulation(t, vn, g_n, e);
            return true;
        }
    }
    restart(b, t, r.va, false);
    if (b.spin.on) turn(b, t, r.wa);
    return false;
}

// Off a keyed model (infinite mass) moving at v_wall where they touch, or off a free model
// without Dynamics, as off a wall moving at its velocity.
void EventBake::respond_to_wall(Body &b, const glm::dvec3 &v, const glm::dvec3 &v_wall,
                                const glm::dvec3 &n, const Material &wall, double t) {
    const double e = combined_restitution(b.material.restitution, wall.restitution),
                 mu = combined_friction(b.material.friction, wall.friction);
    ImpulseBody w;
    w.v = v_wall;
    const ImpulseResult r = contact_impulse(sphere_body(b, 1.0, v, n, t), w, n, e, mu);
    restart(b, t, r.va, false);
    if (b.spin.on) turn(b, t, r.wa);
}

// Two free spheres with Dynamics: the impulse between their masses (n from o toward b).
void EventBake::respond_to_sphere(Body &b, const glm::dvec3 &v, Body &o, const glm::dvec3 &vo,
                                  const glm::dvec3 &n, double t) {
    const double ma = collision_mass(b), mb = collision_mass(o);
    const double e = combined_restitution(b.material.restitution, o.material.restitution),
                 mu = combined_friction(b.material.friction, o.material.friction);
    const ImpulseResult r =
        contact_impulse(sphere_body(b, ma, v, n, t), sphere_body(o, mb, vo, -n, t), n, e, mu);
    restart(b, t, r.va, false);
    restart(o, t, r.vb, false);
    if (b.spin.on) turn(b, t, r.wa);
    if (o.spin.on) turn(o, t, r.wb);
}

// Models that are not spheres: how a free model
// that is not a sphere responds to a contact when the pair's restitution or friction is not the
// seed's (issue 18), while it moves without turning (a model that turns: the last section): it
// is then, for the impulse module, a body of zero inverse inertia: the normal relative velocity of
// the centres becomes -e times it, and Coulomb friction takes at most mu times the normal impulse
// off their tangential relative velocity, never more than stops it. The sphere section's responses
// do exactly that for it (its contact offset does not matter without inertia); this section adds
// what differs: which models take that path, and where the Zeno rule puts one on its support (the
// flat region of the face it met, settle_on, instead of try_settle's sphere test). Unlike a sphere,
// it is put there even while it still slips (mu > 0): it slides on from then at the speed along the
// face it has, without the friction of the bounces too small to follow (at most mu (1 + e) v / (1 -
// e) for normal speed v, below 1e-4 m/s at the threshold); following them would leave it bouncing
// ever lower instead. With e = 1 and mu = 0 the seed's reflections stay in use, bit for bit.

// Whether a model that is not a sphere meets the other with something other than the seed's
// elastic, frictionless reflection.
bool EventBake::mesh_responds(const Body &b, uint32_t other) const {
    if (b.sphere || b.spin.on) return false; // a turning one: the last section
    const Material &mo = materials_[other];
    return combined_restitution(b.material.restitution, mo.restitution) != 1.0 ||
           combined_friction(b.material.friction, mo.friction) != 0.0;
}

// The Zeno rule puts body i on the face of obstacle o it has just met with normal n (from the
// face toward it): a sphere by its own test, another model on the flat region of that face's
// plane, touching it with the vertices that lie in it.
bool EventBake::settle_after_bounces(int i, const Obstacle &o, const glm::dvec3 &n, double t) {
    if (bodies_[static_cast<size_t>(i)].sphere) return try_settle(i, t);
    return settle_on(i, static_cast<int>(&o - obstacles_.data()), n, t);
}

// Models that are not spheres and turn from their contacts (issue 18; check_turning says which).
// Between events such a body's centre of mass (its origin) follows its parabola and it turns at
// constant angular velocity (a spherical top: no torque, so w stays), both closed forms. Its time
// of impact with a static model is turning_contact.hpp's conservative advancement (certified: never
// past the true time, short of it by 1e-13 s at most); against other bodies it is the generic
// advancement (advance()) over its turning pose. At an impact every point touching at once
// shares the impulse (simultaneous_contact.hpp), applied by impulse.hpp with friction at their
// centre of pressure.

// ---- turning models: their response (their time of impact: bake_prediction.cpp) -----------

// Where a turning body touches, as offsets from its centre of mass: each touching point that
// is one of its vertices (within the slack) exactly as its pose places that vertex, so that
// the corners of a face landing flat are exactly symmetric about its centre.
std::vector<glm::dvec3>
EventBake::contact_offsets(const Body &b, const std::vector<glm::dvec3> &points, double t) const {
    const glm::dvec3 c = b.path.at(t - b.t0);
    const std::vector<glm::dvec3> corners = placed_vertices(b, t);
    std::vector<glm::dvec3> offsets;
    for (const glm::dvec3 &p : points) {
        glm::dvec3 best = p - c;
        double nearest = 1e-9;
        for (const glm::dvec3 &r : corners) {
            const double d = glm::length(p - (c + r));
            if (d <= nearest) {
                nearest = d;
                best = r;
            }
        }
        offsets.push_back(best);
    }
    return offsets;
}

// A body as the impulse module sees it at point `point` (t): a turning model or a sphere
// that rotates with its inverse inertia; a keyed model, or one without Dynamics, of infinite
// mass moving as it does there.
// A body's mass for an impulse: refused, naming the model, unless finite and > 0.
double EventBake::collision_mass(const Body &b) const {
    const double m = b.mass;
    if (!(m > 0.0) || !std::isfinite(m))
        throw ani::Failure(ANI_ERR_FAILED, std::string("model '") +
                                               name_of(scene_->models[b.model]) +
                                               "' needs a finite mass > 0 to collide");
    return m;
}

ImpulseBody EventBake::impulse_body(const Body &b, const glm::dvec3 &point, double t) const {
    ImpulseBody x;
    if (b.driven() || !b.dynamics) {
        x.v = point_velocity(b, point, t);
        return x;
    }
    const double m = collision_mass(b);
    x.inv_mass = 1.0 / m;
    x.v = b.path.velocity(t - b.t0);
    x.r = point - b.path.at(t - b.t0);
    if (b.turning()) {
        x.inv_inertia = b.spin.free ? b.spin.inverse_inertia(t) : glm::dmat3(b.inv_inertia);
        x.w = b.spin.rate(t);
    } else if (b.sphere && b.spin.on) {
        x.inv_inertia = glm::dmat3(sphere_inverse_inertia(m, b.radius));
        x.w = b.spin.rate(t);
    }
    return x;
}

// The impulse of a turning body b against something that does not move (a static model, or a
// body held still by its support), touching at `points` (world space; at least the contact's
// point) with normal n towards b: one point's impulse, or several points' together at their
// centre of pressure. `a` receives b as the impulse saw it, with its r at that point.
ImpulseResult EventBake::turning_impulse_on_still(const Body &b, const Contact &contact,
                                                  const std::vector<glm::dvec3> &points, double e,
                                                  double mu, double t, ImpulseBody &a) const {
    const glm::dvec3 n = contact.normal, c = b.path.at(t - b.t0);
    a = impulse_body(b, contact.point, t);
    const std::vector<glm::dvec3> offsets =
        contact_offsets(b, points.empty() ? std::vector<glm::dvec3>{contact.point} : points, t);
    std::vector<glm::dvec3> at;
    for (const glm::dvec3 &r : offsets) at.push_back(c + r);
    std::optional<SimultaneousImpulse> together;
    if (offsets.size() > 1)
        together = simultaneous_impulse(a, c, ImpulseBody{}, glm::dvec3(0.0), at, n, e);
    if (together) {
        a.r = together->centre - c;
        // Within rounding of straight below the centre of mass (a face landing flat: the
        // touching points' coordinates leave 1e-14 of their size), exactly below it, so that
        // it gets no spin from rounding.
        const glm::dvec3 across = a.r - glm::dot(a.r, n) * n;
        if (glm::length(across) <= 1e-12 * b.turning_reach) a.r = glm::dot(a.r, n) * n;
        return contact_impulse_of(a, ImpulseBody{}, n, together->normal, mu);
    }
    // The point that moves into it fastest.
    a.r = offsets[0];
    ImpulseBody probe = a;
    for (const glm::dvec3 &r_k : offsets) {
        probe.r = r_k;
        if (glm::dot(point_velocity_of(probe), n) < glm::dot(point_velocity_of(a), n)) a.r = r_k;
    }
    return contact_impulse(a, ImpulseBody{}, n, e, mu);
}

// The smallest bounce the Zeno rule follows, as a speed, for a body pressed along -n by g_n.
double EventBake::microcollision_speed(const Body &b, double g_n, double t) const {
    const double scale = std::max(1.0, glm::length(b.path.at(t - b.t0)));
    return g_n > 0.0 ? std::sqrt(2.0 * g_n * kZenoHeight * scale) : 0.0;
}

// A turning body meets static model o at `points` with normal n: the impulse of the pair's
// restitution and friction at the points' centre of pressure. The Zeno rule puts it on the face
// when its bounces there have become too small to follow and it does not turn (a box landing
// flat). True when it was put there.
bool EventBake::respond_turning_to_obstacle(int i, const Obstacle &o, const Contact &contact,
                                            const std::vector<glm::dvec3> &points, double t) {
    Body &b = bodies_[static_cast<size_t>(i)];
    const Material &mo = materials_[o.model];
    const double e = combined_restitution(b.material.restitution, mo.restitution),
                 mu = combined_friction(b.material.friction, mo.friction);
    const glm::dvec3 n = contact.normal, c = b.path.at(t - b.t0);
    ImpulseBody a;
    ImpulseResult r = turning_impulse_on_still(b, contact, points, e, mu, t, a);
    const double vn = glm::dot(r.va, n), g_n = -glm::dot(b.free_a, n),
                 scale = std::max(1.0, glm::length(c));
    // The speed of the highest bounce the Zeno rule still follows (zeno.hpp).
    const double v_min = microcollision_speed(b, g_n, t);
    // The Zeno rule, for a model that does not turn, or turns so slowly that no point of it
    // moves as fast as the bounces too small to follow (then it stops turning). settle_on puts
    // it there only if it stands balanced; otherwise it tips over by the microcollisions below.
    if (zeno_settles(vn, g_n, e, scale) && glm::length(r.wa) * b.turning_reach <= v_min) {
        restart(b, t, r.va, false);
        turn(b, t, glm::dvec3(0.0));
        if (settle_after_bounces(i, o, n, t)) {
            b.settles_at = zeno_accumulation(t, vn, g_n, e);
            return true;
        }
    }
    // Microcollisions (Mirtich's thesis, 1996, 4.4): a point that touches while the body
    // turns may be pressed back at once (a cube tipping over its corner), and its bounces
    // then come ever closer, with no closed form for their sum. So the touching point leaves
    // at least at v_min: each bounce at least 1e-9 of the coordinates' size high and 2 v_min
    // / g_n long (29 us at 1 m): the documented threshold of issue 18, until contacts that
    // last are solved (issue 19).
    ImpulseBody after = a;
    after.v = r.va;
    after.w = r.wa;
    if (glm::dot(point_velocity_of(after), n) < v_min) {
        // Standing on an edge, it tips over about it in closed form (bake_hinge.cpp) where it
        // can; otherwise by microcollisions.
        HingeSupport on;
        on.triangles = &o;
        on.obstacle = static_cast<int>(&o - obstacles_.data());
        if (try_hinge(i, on, n, a.v, a.w, t) || try_hinge_over_edge(i, on, points, a.v, a.w, t))
            return false;
        r = leave_at(after, n, v_min, mu);
    }
    restart(b, t, r.va, false);
    turn(b, t, r.wa);
    return false;
}

// A turning body b meets body o, which its support holds still (bake_rest.cpp, "resting on other
// models") or which stands without Dynamics, at `points` with normal n from o towards b: as
// against a static model, every touching point shares the impulse, and b leaves at least at the
// microcollision speed (a box knocked across the one it slept on slides over it by
// microcollisions, its face's corners taking them together), or tips over an edge of o that
// stands (bake_hinge.cpp). o takes nothing. It goes to sleep on o when it comes to rest there.
void EventBake::respond_turning_to_held(int i, int j, const Contact &contact,
                                        const std::vector<glm::dvec3> &points, double t) {
    Body &b = bodies_[static_cast<size_t>(i)];
    const Body &o = bodies_[static_cast<size_t>(j)];
    const double e = combined_restitution(b.material.restitution, o.material.restitution),
                 mu = combined_friction(b.material.friction, o.material.friction);
    const glm::dvec3 n = contact.normal;
    ImpulseBody a;
    ImpulseResult r = turning_impulse_on_still(b, contact, points, e, mu, t, a);
    const double v_min = microcollision_speed(b, -glm::dot(b.free_a, n), t);
    ImpulseBody after = a;
    after.v = r.va;
    after.w = r.wa;
    if (glm::dot(point_velocity_of(after), n) < v_min) {
        if (try_hinge_on_body(i, j, n, points, a.v, a.w, t)) return;
        r = leave_at(after, n, v_min, mu);
    }
    restart(b, t, r.va, false);
    turn(b, t, r.wa);
}

// Two bodies, one or both turning, meet with normal n (from o towards b): the impulse between
// them, ib and io as impulse_body() saw them before a keyed one was released (a keyed model
// is a wall of infinite mass moving as its keys say; one without Dynamics is too, and stops
// there, as the seed's do).
void EventBake::respond_turning_pair(Body &b, const ImpulseBody &ib, bool b_wall, Body &o,
                                     const ImpulseBody &io, bool o_wall, const glm::dvec3 &n,
                                     double t) {
    const double e = combined_restitution(b.material.restitution, o.material.restitution),
                 mu = combined_friction(b.material.friction, o.material.friction);
    ImpulseResult r = contact_impulse(ib, io, n, e, mu);
    // Microcollisions between bodies, as against static models (respond_turning_to_obstacle):
    // while their accelerations press them together, their touching points part at least at
    // the speed of the smallest bounce the Zeno rule follows.
    const double pressed = -glm::dot(acceleration(b) - acceleration(o), n);
    if (pressed > 0.0) {
        const double scale = std::max(1.0, glm::length(b.path.at(t - b.t0)));
        ImpulseBody after_b = ib, after_o = io;
        after_b.v = r.va;
        after_b.w = r.wa;
        after_o.v = r.vb;
        after_o.w = r.wb;
        const ImpulseResult parted =
            leave_at(after_b, after_o, n, std::sqrt(2.0 * pressed * kZenoHeight * scale));
        if (parted.normal > 0.0) {
            r.va = parted.va;
            r.wa = parted.wa;
            r.vb = parted.vb;
            r.wb = parted.wb;
        }
    }
    for (Body *x : {&b, &o}) {
        const bool first = x == &b;
        if (first ? b_wall : o_wall) continue; // released from its keys, moving as they did
        if (!x->dynamics) {
            restart(*x, t, glm::dvec3(0.0), true);
            continue;
        }
        restart(*x, t, first ? r.va : r.vb, false);
        if (x->spin.on) turn(*x, t, first ? r.wa : r.wb);
    }
}

} // namespace physics_custom::bake
