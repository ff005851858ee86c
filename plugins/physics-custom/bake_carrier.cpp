// The event-driven bake's carriers (physics.md, "Riding a keyed platform"): a model resting or
// sliding on a face of another body that translates at a constant velocity u without turning:
// a keyed platform between two of its keys (linear keys, the default interpolation), or one
// standing still after its keys (without Dynamics or gravity, nothing moves it then). The carrier's
// frame is inertial while u holds, so every closed form of the rest manager holds in it
// (bake_rest.cpp works with the velocity relative to the support), and in the world the rider's
// path is that plus u t: still a free motion segment. Where u changes (the carrier's next key), the
// rider's velocity relative to it jumps, and friction is aimed again against the new one. A keyed
// platform that accelerates carries a model stuck to it instead (the last section: "sticking").
#include "event_bake_detail.hpp"

namespace physics_custom::bake {

// Whether body j translates at a constant velocity from t on, without turning or changing its
// scale, and until when.
//  - Keyed: over the span to its next key. Its keys' velocity is the same at four times inside
//    the span, and so are its angles and scale: for an interpolation at most cubic (the
//    seed's linear and smooth ones) that makes the velocity constant over the span (a quadratic
//    equal at three points), and the angles and scale too (a cubic equal at four points).
//    Where its keys end now: it stands still from here, without Dynamics or gravity.
//  - Free, without Dynamics or gravity: it stands still (its velocity 0; released from its keys
//    by a contact, until it resumes them).
std::optional<EventBake::Carried> EventBake::carried_motion(int j, double t) const {
    const Body &c = bodies_[static_cast<size_t>(j)];
    if (c.sphere || !c.active || c.carried()) return std::nullopt;
    // (A model with Dynamics or gravity is moved by what it carries, once free of its keys.)
    const ani_model_desc &d = *scene_->models[c.model].desc;
    const bool stands = !d.dynamics && !d.gravity;
    if (!c.keyed()) {
        if (!stands) return std::nullopt;
        return Carried{c.path.velocity(t - c.t0), c.resume_at};
    }
    const double end = std::min(next_key(c.model, t), c.keys_end);
    if (!(end > t)) { // its keys end now: free from here, it stands still
        if (!stands) return std::nullopt;
        return Carried{glm::dvec3(0.0), kNever};
    }
    glm::dvec3 u(0.0);
    ani_model_state first{};
    for (int k = 1; k <= 4; ++k) {
        glm::dvec3 v;
        const ani_model_state s = keyed(c.model, t + 0.2 * k * (end - t), &v);
        auto same = [](const ani_vec3 &a, const ani_vec3 &b) {
            return a.x == b.x && a.y == b.y && a.z == b.z;
        };
        if (k == 1) {
            u = v;
            first = s;
        } else if (glm::length(v - u) > 1e-12 * std::max(1.0, glm::length(u)) ||
                   !same(s.angles, first.angles) || !same(s.scale, first.scale)) {
            return std::nullopt;
        }
    }
    return Carried{u, end};
}

// Body b's triangles as placed at t, as an obstacle's (to stand on one of its faces).
Obstacle EventBake::face_of(const Body &b, double t) const {
    const PlacedMesh m = placed(b, pose(b, t));
    Obstacle o;
    o.model = b.model;
    for (size_t k = 0; k < 3 * m.triangle_count; ++k)
        o.corners.push_back(m.vertices[m.triangles[k]]);
    finish_obstacle(o);
    return o;
}

// A free model placed on a face of a carrier (touching its plane with its lowest point over the
// face, not moving into or out of it relative to the carrier, pulled into it, the carrier moving
// along the face) rests, slides or rolls on it from here, as try_settle and try_settle_mesh put
// one on a static model.
bool EventBake::try_ride(int i, double t) {
    Body &b = bodies_[static_cast<size_t>(i)];
    if (!b.active || b.driven() || b.supported() || b.motion == ANI_MOTION_REST ||
        !(b.sphere || b.shape || (b.turning() && b.spin.w == glm::dvec3(0.0))))
        return false;
    const glm::dvec3 c = b.path.at(t - b.t0);
    const double reach = b.sphere ? b.radius : body_size(b);
    count_.scanned += mesh_bodies_.size();
    for (const int other : mesh_bodies_) {
        const Body &o = bodies_[static_cast<size_t>(other)];
        if (other == i || !o.active || is_ignored(i, other)) continue;
        const Pose po = pose(o, t);
        if (glm::length(c - po.center) > 1.01 * (reach + o.reach * frobenius(po.linear))) continue;
        const Obstacle ob = face_of(o, t);
        const std::vector<glm::dvec3> faces = standing_faces(i, ob, po.velocity, t);
        if (faces.empty()) continue;
        std::optional<Carried> motion = carried_motion(other, t);
        if (!(motion && carries_along(motion->velocity, faces.front()))) {
            if (stick(i, other, faces.front(), t)) return true;
            if (!let_go(other, i, t)) continue;
            motion = carried_motion(other, t);
            if (!(motion && carries_along(motion->velocity, faces.front()))) continue;
        }
        Holder holder;
        holder.carrier = other;
        holder.velocity = motion->velocity;
        holder.until = motion->until;
        if (ride_on(i, ob, holder, t)) return true;
    }
    return false;
}

// Whether a carrier moving at u keeps to the plane of its face with normal n.
bool EventBake::carries_along(const glm::dvec3 &u, const glm::dvec3 &n) {
    return std::abs(glm::dot(u, n)) <= 1e-12 * std::max(1.0, glm::length(u));
}

// Keyed body j cannot carry body i on its face (its keys turn it, or accelerate it more than i
// can follow, or i slides on it while they accelerate it: not yet, physics.md), and i would sink
// into it: j is released from its keys, as at a collision, and said so. Without Dynamics it then
// stands still, and carries i.
bool EventBake::let_go(int j, int i, double t) {
    if (!bodies_[static_cast<size_t>(j)].keyed()) return false;
    log_warning("model '" +
                std::string(name_of(scene_->models[bodies_[static_cast<size_t>(i)].model])) +
                "' stands on keyed model '" +
                name_of(scene_->models[bodies_[static_cast<size_t>(j)].model]) +
                "' at t = " + short_number(t) +
                " s, whose keys cannot carry it (physics.custom carries a model only on a "
                "platform that its keys translate without turning it, at a constant velocity "
                "along the face, or with an acceleration that friction and gravity let the model "
                "follow from rest): the platform is released from its keys, as at a collision");
    release(j, t);
    predict(j, t);
    return true;
}

// Body i on one of the faces `ob` of the carrier in `holder`, if it stands on one.
bool EventBake::ride_on(int i, const Obstacle &ob, const Holder &holder, double t) {
    Body &b = bodies_[static_cast<size_t>(i)];
    if (b.sphere) {
        double r = b.radius; // less while it overlaps the carrier (touching at that depth)
        if (const OverlapRecord *rec = overlap_of(i, holder.carrier);
            rec && rec->kind == OverlapRecord::Kind::kContactDistance)
            r = std::min(r, rec->contact);
        return settle_sphere_on(i, ob, holder, r, t);
    }
    if (is_overlapped(i, holder.carrier)) return false;
    for (const glm::dvec3 &n : standing_faces(i, ob, holder.velocity, t))
        if (carries_along(holder.velocity, n) && settle_on_face(i, ob, holder, n, t)) return true;
    return false;
}

// Body x has just bounced off body y with normal n (from y towards x): when y is a carrier and
// the bounces left are too small to follow, the Zeno rule puts x on y's face, as
// respond_to_obstacle does on a static model, in y's frame (inertial while y's velocity holds).
bool EventBake::settle_on_carrier(int x, int y, const glm::dvec3 &n, double t) {
    Body &b = bodies_[static_cast<size_t>(x)];
    if (b.turning() || !b.dynamics || b.supported() || b.driven()) return false;
    const std::optional<Carried> motion = carried_motion(y, t);
    if (!motion) return false;
    const glm::dvec3 u = motion->velocity, v = b.path.velocity(t - b.t0), v_rel = v - u;
    const double vn = glm::dot(v_rel, n), g_n = -glm::dot(b.free_a, n);
    const Material &mo = materials_[bodies_[static_cast<size_t>(y)].model];
    const double e = combined_restitution(b.material.restitution, mo.restitution);
    if (!carries_along(u, n) ||
        !zeno_settles(vn, g_n, e, std::max(1.0, glm::length(b.path.at(t - b.t0)))))
        return false;
    restart(b, t, v_rel - vn * n + u, false); // on the face, at its speed along it
    Holder holder;
    holder.carrier = y;
    holder.velocity = u;
    holder.until = motion->until;
    if (!ride_on(x, face_of(bodies_[static_cast<size_t>(y)], t), holder, t)) {
        restart(b, t, v, false);
        return false;
    }
    b.settles_at = zeno_accumulation(t, vn, g_n, e);
    return true;
}

// Rider i at t, where its carrier's motion may change: on the same face from here, with friction
// against its velocity relative to the carrier's new one; or on its own (it leaves its support)
// where the carrier no longer moves at a constant velocity along the face, or is no longer under
// it (a carrier that resumes its keys is placed where they say).
void EventBake::recarry(int i, double t) {
    Body &b = bodies_[static_cast<size_t>(i)];
    if (b.carrier < 0) return;
    const Body &o = bodies_[static_cast<size_t>(b.carrier)];
    const Obstacle ob = face_of(o, t);
    const glm::dvec3 c = b.path.at(t - b.t0);
    const bool under =
        std::any_of(b.support_feet.begin(), b.support_feet.end(), [&](const glm::dvec3 &foot) {
            return on_flat_region(ob, b.support_n, b.support_d, c + foot);
        });
    std::optional<Carried> motion;
    if (under) {
        motion = carried_motion(b.carrier, t);
        if (!(motion && carries_along(motion->velocity, b.support_n))) {
            if (stick(i, b.carrier, b.support_n, t)) return;
            if (let_go(b.carrier, i, t)) motion = carried_motion(b.carrier, t);
        }
    }
    if (!(motion && carries_along(motion->velocity, b.support_n))) {
        unsupport(b, t);
        return;
    }
    rebase(b, t);
    b.support_v = motion->velocity;
    b.support_t = t;
    b.carrier_until = motion->until;
    b.carrier_version = o.version;
    b.support_edges = support_boundary(ob, b);
    aim_friction(b);
}

// Body j has been handled: the bodies it carries follow what it does now (one stuck to it is
// dropped where it is, and finds what holds it from there).
void EventBake::carry_on(int j, double t) {
    if (riders_ == 0) return;
    count_.scanned += bodies_.size();
    for (size_t k = 0; k < bodies_.size(); ++k) {
        Body &r = bodies_[k];
        if ((r.carrier != j && r.carried_by != j) ||
            r.carrier_version == bodies_[static_cast<size_t>(j)].version)
            continue;
        if (r.carried())
            carry_again(static_cast<int>(k), t);
        else
            recarry(static_cast<int>(k), t);
        predict(static_cast<int>(k), t);
    }
}

// Carried body i at the end of its span (its carrier's next key), or where its carrier changed
// course: free from here, it is carried again, rides, or rests where it is, as it would be put
// there (try_settle_mesh).
void EventBake::carry_again(int i, double t) {
    drop(i, t);
    try_settle_mesh(i, t);
}

// ---- sticking to a platform that accelerates ------------------------------------------------
//
// A keyed platform whose keys accelerate it (smooth keys, an elevator easing in and out) carries
// a model standing on it without slipping while friction can give the model the platform's
// acceleration: the model then moves exactly as the platform does, its pose the platform's plus a
// fixed offset, which is no polynomial of its own. It is reported as carried segments (ABI 1.8),
// which the host evaluates from the platform's keys. The platform may not turn or scale
// meanwhile (then its keys let it go, as before).

// Whether body b, on the face with normal n of keyed body j and moving with it, stays there from
// t to `end` (j's next key): the force per unit mass its contact must give it, f = a_j - free_a
// (a_j from j's keys' velocity at two times 2e-6 of the span apart), presses it into the face
// (f . n > 0), within the friction cone (|f - (f . n) n| <= mu f . n), and, for a model that
// turns, its line through the centre of mass meets its feet (it does not tip). Checked at 33
// times of the span, both ends among them. For keys at most cubic, a_j is linear in time and the
// cone convex, so the ends alone decide: the times between are a margin for other interpolators.
bool EventBake::sticks(const Body &b, int j, const glm::dvec3 &n, double t, double end) const {
    const Body &c = bodies_[static_cast<size_t>(j)];
    const double mu = combined_friction(b.material.friction, c.material.friction);
    const double span = end - t, h = 1e-6 * span;
    // Its feet, relative to its centre, when it turns: the vertices within kTipSlack of its size
    // of the lowest along n.
    std::vector<glm::dvec3> feet;
    const double size = std::max(1.0, 2.0 * body_size(b));
    if (b.turning()) {
        const std::vector<glm::dvec3> corners = placed_vertices(b, t);
        double lowest = kNever;
        for (const glm::dvec3 &r : corners) lowest = std::min(lowest, glm::dot(n, r));
        for (const glm::dvec3 &r : corners)
            if (glm::dot(n, r) - lowest <= kTipSlack * size) feet.push_back(r);
    }
    constexpr int kSamples = 32;
    for (int k = 0; k <= kSamples; ++k) {
        // (At `end` itself the keys give the velocity of the span after: this span's is read
        // just before it.)
        const double tau = t + span * k / kSamples;
        const double t1 = std::clamp(tau - h, t, end - 3.0 * h), t2 = t1 + 2.0 * h;
        glm::dvec3 v1, v2;
        keyed(c.model, t1, &v1);
        keyed(c.model, t2, &v2);
        const glm::dvec3 f = (v2 - v1) / (t2 - t1) - b.free_a;
        const double fn = glm::dot(f, n);
        if (!(fn > 1e-9 * glm::length(b.free_a))) return false;
        if (glm::length(f - fn * n) > mu * fn) return false;
        if (b.turning() && !over_feet(glm::dvec3(0.0), feet, -f, 1e-9 * size)) return false;
    }
    return true;
}

// Body i stands on the face with normal n of keyed body j at t, moving with it: when j's keys
// accelerate it without turning or scaling it until its next key, and i sticks there all the
// while (sticks), i is carried by j from here. Not for a ball (it would roll), one that turns,
// or a host that takes no carried segments.
bool EventBake::stick(int i, int j, const glm::dvec3 &n, double t) {
    Body &b = bodies_[static_cast<size_t>(i)];
    const Body &c = bodies_[static_cast<size_t>(j)];
    if (!sink_->carried || b.sphere || b.driven() || b.hinge || !b.dynamics || !c.keyed() ||
        c.sphere || (b.turning() && b.spin.w != glm::dvec3(0.0)))
        return false;
    const double end = std::min(next_key(c.model, t), c.keys_end);
    if (!(end > t)) return false;
    if (!keys_hold_pose(c.model, t, end)) return false;
    const Pose pc = pose(c, t), pb = pose(b, t);
    const glm::dvec3 v = b.path.velocity(t - b.t0);
    if (glm::length(v - pc.velocity) > 1e-9 * std::max(1.0, glm::length(pc.velocity))) return false;
    if (!sticks(b, j, n, t, end)) return false;
    // Its motion so far reported, it moves with j from here.
    if (b.supported()) unsupport(b, t);
    close_segment(b, t);
    b.carried_spin = b.spin.on;
    if (b.spin.on) {
        emit_spin(b, t);
        b.spin.start(t, b.spin.at(t), glm::dvec3(0.0));
        b.spin.on = false;
    }
    b.mode = Body::Mode::kCarried;
    b.carried_by = j;
    b.carrier_version = c.version;
    b.carried_from = t;
    b.carried_until = std::min(end, b.resume_at);
    b.carried_offset = pb.center - pc.center;
    b.carried_linear = pb.linear;
    b.support_n = n; // the face it stands on (held_by_support)
    b.settles_at = kNever;
    ++riders_;
    ++b.version;
    return true;
}

// Reports body b's carried segment from when it was carried (or from this slice's start) to t:
// the motion segment ANI_MOTION_CARRIED and the carried segment, its offset and orientation in
// its carrier's frame (which its keys turn by the same angles all the while).
void EventBake::emit_carried(const Body &b, double t) {
    const double from = std::max(b.carried_from, t_begin_);
    if (!(t > from)) return;
    ani_motion_segment s{};
    s.model = b.model;
    s.motion = ANI_MOTION_CARRIED;
    s.t0 = from;
    s.t1 = t;
    emit(s);
    const Body &c = bodies_[static_cast<size_t>(b.carried_by)];
    const glm::dquat carrier = orientation_of_angles(vec(keyed(c.model, from, nullptr).angles));
    const glm::dquat own = b.carried_spin
                               ? b.spin.at(from)
                               : orientation_of_angles(vec(keyed(b.model, from, nullptr).angles));
    const glm::dvec3 offset = glm::conjugate(carrier) * b.carried_offset;
    const glm::dquat relative = glm::normalize(glm::conjugate(carrier) * own);
    ani_carried_segment seg{};
    seg.model = b.model;
    seg.carrier = c.model;
    seg.t0 = from;
    seg.t1 = t;
    seg.offset = ani(offset);
    seg.relative = ani_quat{relative.w, relative.x, relative.y, relative.z};
    if (!std::isfinite(offset.x + offset.y + offset.z + relative.w + relative.x + relative.y +
                       relative.z))
        throw ani::Failure(ANI_ERR_FAILED, std::string("model '") +
                                               name_of(scene_->models[b.model]) +
                                               "' would be carried to a value that is not finite");
    sink_->carried(sink_->context, &seg);
}

// Carried body i leaves its carrier's motion at t (the span ends, something hits it, or the
// carrier was released): free from there, where the carrier has taken it and at its velocity,
// turning again (at rest) if it turned before.
void EventBake::drop(int i, double t) {
    Body &b = bodies_[static_cast<size_t>(i)];
    if (!b.carried()) return;
    const Pose p = pose(b, t);
    emit_carried(b, t);
    b.mode = Body::Mode::kFree;
    b.carried_by = -1;
    b.carried_until = kNever;
    --riders_;
    b.t0 = t;
    // (Its path is its centre of mass's when it turns about one.)
    const glm::dvec3 arm = b.carried_spin ? b.spin.at(t) * b.pivot : glm::dvec3(0.0);
    b.path = Path{p.center + arm, p.velocity, b.free_a};
    b.motion = ANI_MOTION_FREE;
    if (b.carried_spin) {
        b.spin.on = true;
        b.spin.start(t, b.spin.at(t), glm::dvec3(0.0));
    }
    b.carried_spin = false;
    ++b.version;
}

} // namespace physics_custom::bake
