// The event-driven bake's carriers (physics.md, "Riding a keyed platform"): a model resting or
// sliding on a face of another body that translates at a constant velocity u without turning:
// a keyed platform between two of its keys (linear keys, the default interpolation), or one
// standing still after its keys (without Dynamics or gravity, nothing moves it then). The carrier's
// frame is inertial while u holds, so every closed form of the rest manager holds in it
// (bake_rest.cpp works with the velocity relative to the support), and in the world the rider's
// path is that plus u t: still a free motion segment. Where u changes (the carrier's next key), the
// rider's velocity relative to it jumps, and friction is aimed again against the new one.
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
std::optional<EventBake::Carried> EventBake::carried_motion(int j, double t) {
    const Body &c = bodies_[static_cast<size_t>(j)];
    if (c.sphere || !c.active) return std::nullopt;
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
        const ani_model_state s = keyed_state(*scene_, c.model, t + 0.2 * k * (end - t), &v);
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
    if (!b.active || b.keyed() || b.supported() || b.motion == ANI_MOTION_REST ||
        !(b.sphere || b.shape || (b.turning() && b.spin.w == glm::dvec3(0.0))))
        return false;
    const glm::dvec3 c = b.path.at(t - b.t0);
    const double reach = b.sphere ? b.radius : body_size(b);
    for (size_t j = 0; j < bodies_.size(); ++j) {
        const Body &o = bodies_[j];
        const int other = static_cast<int>(j);
        if (other == i || o.sphere || !o.active || is_ignored(i, other)) continue;
        const Pose po = pose(o, t);
        if (glm::length(c - po.center) > 1.01 * (reach + o.reach * frobenius(po.linear))) continue;
        const Obstacle ob = face_of(o, t);
        const std::vector<glm::dvec3> faces = standing_faces(i, ob, po.velocity, t);
        if (faces.empty()) continue;
        std::optional<Carried> motion = carried_motion(other, t);
        if (!(motion && carries_along(motion->velocity, faces.front()))) {
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

// Keyed body j cannot carry body i on its face (its keys accelerate it, turn it, or move it across
// that face: not yet, physics.md), which would sink into it: j is released from its keys, as at a
// collision, and said so. Without Dynamics it then stands still, and carries i.
bool EventBake::let_go(int j, int i, double t) {
    if (!bodies_[static_cast<size_t>(j)].keyed()) return false;
    log_warning("model '" +
                std::string(name_of(scene_->models[bodies_[static_cast<size_t>(i)].model])) +
                "' stands on keyed model '" +
                name_of(scene_->models[bodies_[static_cast<size_t>(j)].model]) +
                "' at t = " + short_number(t) +
                " s, whose keys cannot carry it (physics.custom carries a model only on a "
                "platform that its keys translate at a constant velocity along the face, as "
                "linear keys do): the platform is released from its keys, as at a collision");
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
    if (b.turning() || !b.dynamics || b.supported() || b.keyed()) return false;
    const std::optional<Carried> motion = carried_motion(y, t);
    if (!motion) return false;
    const glm::dvec3 u = motion->velocity, v = b.path.velocity(t - b.t0), v_rel = v - u;
    const double vn = glm::dot(v_rel, n), g_n = -glm::dot(b.free_a, n);
    const Material mo = material_of(*scene_->models[bodies_[static_cast<size_t>(y)].model].desc);
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
        if (!(motion && carries_along(motion->velocity, b.support_n)) && let_go(b.carrier, i, t))
            motion = carried_motion(b.carrier, t);
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

// Body j has been handled: the bodies it carries follow what it does now.
void EventBake::carry_on(int j, double t) {
    if (riders_ == 0) return;
    for (size_t k = 0; k < bodies_.size(); ++k) {
        Body &r = bodies_[k];
        if (r.carrier != j || r.carrier_version == bodies_[static_cast<size_t>(j)].version)
            continue;
        recarry(static_cast<int>(k), t);
        predict(static_cast<int>(k), t);
    }
}

} // namespace physics_custom::bake
