// The event-driven bake's overlaps (physics.md, "Where the code is"): pairs found inside each
// other when they start to collide, treated as touching at that depth until they are apart, and
// the pairs left alone meanwhile. Relies on overlap_memory.hpp and bake_prediction.cpp's gaps.
#include "event_bake_detail.hpp"

namespace physics_custom::bake {

// ---- pairs that overlap when they start to collide (physics.md) -------------------------

// Finds the pairs with body i that overlap at t (at the start, when i becomes free inside
// another, or when its keys take it back inside one) and treats each as touching.
void EventBake::find_overlaps(int i, double t) {
    for (size_t o = 0; o < obstacles_.size(); ++o) {
        const int other = -1 - static_cast<int>(o);
        if (is_overlapped(i, other) || is_ignored(i, other)) continue;
        if (auto seen = overlap_with_obstacle(bodies_[static_cast<size_t>(i)], obstacles_[o], t))
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
std::optional<EventBake::Seen> EventBake::overlap_with_obstacle(const Body &b, const Obstacle &o,
                                                                double t) const {
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
void EventBake::meet_overlap(int i, int other, const Seen &seen, double t) {
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
    const bool keyed = b.driven() || (o && o->driven());
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
            collide_bodies(i, other, seen.contact, {}, t);
            if (predicted_.size() == bodies_.size()) predict(other, t);
        } else {
            collide_obstacle(i, obstacles_[static_cast<size_t>(-1 - other)], seen.contact, {}, t);
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

void EventBake::treat_as_touching(int i, int other, const OverlapRecord &record) {
    if (record.kind == OverlapRecord::Kind::kIgnored) {
        ignore(i, other, record.since);
        return;
    }
    if (overlaps_.emplace(pair_key(i, other), record).second && other < 0)
        ++bodies_[static_cast<size_t>(i)].overlapped_obstacles;
}

// `normal` points from the other towards body i.
void EventBake::report_overlap(int i, int other, double t, double depth, const glm::dvec3 &normal) {
    const uint32_t a = bodies_[static_cast<size_t>(i)].model, b = model_of(other);
    if (memory_.reported_before(a, b, t) || !reported_.insert(pair_key(i, other)).second) return;
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

std::string EventBake::short_number(double x) {
    std::ostringstream out;
    out << std::setprecision(4) << (std::abs(x) < 1e-12 ? 0.0 : x);
    return out.str();
}

uint32_t EventBake::model_of(int other) const {
    return other >= 0 ? bodies_[static_cast<size_t>(other)].model
                      : obstacles_[static_cast<size_t>(-1 - other)].model;
}

bool EventBake::is_overlapped(int a, int b) const {
    return !overlaps_.empty() && overlaps_.count(pair_key(a, b));
}

const OverlapRecord *EventBake::overlap_of(int a, int b) const {
    if (overlaps_.empty()) return nullptr;
    const auto it = overlaps_.find(pair_key(a, b));
    return it == overlaps_.end() ? nullptr : &it->second;
}

// The radius a free sphere touches obstacle o with: its own, or less while it overlaps it.
double EventBake::radius_against(int i, int o) const {
    const Body &b = bodies_[static_cast<size_t>(i)];
    if (b.overlapped_obstacles == 0) return b.radius;
    const OverlapRecord *r = overlap_of(i, -1 - o);
    return r && r->kind == OverlapRecord::Kind::kContactDistance ? std::min(b.radius, r->contact)
                                                                 : b.radius;
}

// How far a mesh body is moved for its tests against obstacle o while it overlaps it.
glm::dvec3 EventBake::shift_against(int i, int o) const {
    const OverlapRecord *r =
        bodies_[static_cast<size_t>(i)].overlapped_obstacles > 0 ? overlap_of(i, -1 - o) : nullptr;
    return r && r->kind == OverlapRecord::Kind::kShift ? r->shift : glm::dvec3(0.0);
}

// Two free spheres that overlapped touch at the distance they had: their radii, scaled.
void EventBake::radii_against(int i, int j, double &ri, double &rj) const {
    const OverlapRecord *r = overlap_of(i, j);
    if (!r || r->kind != OverlapRecord::Kind::kContactDistance) return;
    const double scale = std::min(1.0, r->contact / (ri + rj));
    ri *= scale;
    rj *= scale;
}

// Whether a body that overlapped obstacle o is apart from it now (then the pair is as any).
bool EventBake::apart_after_overlap(int i, int o, double t) const {
    const Body &b = bodies_[static_cast<size_t>(i)];
    const OverlapRecord *r = overlap_of(i, -1 - o);
    if (!r || r->kind != OverlapRecord::Kind::kShift || !b.shape)
        return apart_from_obstacle(b, obstacles_[static_cast<size_t>(o)], t);
    return !overlap_with_obstacle(b, obstacles_[static_cast<size_t>(o)], t);
}

void EventBake::unoverlap(int i, int other, double t) {
    if (!overlaps_.erase(pair_key(i, other))) return;
    if (other < 0) --bodies_[static_cast<size_t>(i)].overlapped_obstacles;
    memory_.close(bodies_[static_cast<size_t>(i)].model, model_of(other), t);
}

std::pair<int, int> EventBake::pair_key(int a, int b) {
    return b >= 0 && b < a ? std::make_pair(b, a) : std::make_pair(a, b);
}

// Leaves the pair alone until they are apart (overlapping keyed models, or a grazing contact).
void EventBake::ignore(int i, int other, double t) {
    if (!ignored_.insert(pair_key(i, other)).second) return;
    if (other < 0) {
        Body &b = bodies_[static_cast<size_t>(i)];
        ++b.ignored_obstacles;
        if (!b.sphere) b.grazed_until = t + recheck_after(b, t);
    }
}

void EventBake::unignore(int i, int other, double t) {
    if (ignored_.erase(pair_key(i, other))) {
        if (other < 0) --bodies_[static_cast<size_t>(i)].ignored_obstacles;
        memory_.close(bodies_[static_cast<size_t>(i)].model, model_of(other), t);
    }
}

void EventBake::forget_ignored(int i, double t) {
    std::vector<std::pair<int, int>> mine;
    for (const auto &key : ignored_)
        if (key.first == i || key.second == i) mine.push_back(key);
    for (const auto &[a, b] : mine) unignore(i, a == i ? b : a, t);
}

bool EventBake::is_ignored(int a, int b) const {
    return !ignored_.empty() && ignored_.count(pair_key(a, b));
}

} // namespace physics_custom::bake
