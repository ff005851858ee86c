// The event-driven bake's rest manager (physics.md, "Where the code is"): a body put on the flat
// part of a static model (resting or sliding), where it leaves that support, and what a contact
// does to it. Relies on zeno.hpp for the Zeno rule and bake_prediction.cpp for the gaps.
#include "event_bake_detail.hpp"

namespace physics_custom::bake {

// ---- resting and sliding on static models ---------------------------------------------

// Whether triangle k of the obstacle lies in the plane n . x = d (to rounding).
bool EventBake::in_plane(const Obstacle &o, size_t k, const glm::dvec3 &n, double d) {
    return glm::dot(o.normals[k], n) > 1.0 - 1e-9 &&
           std::abs(o.offsets[k] - d) <= 1e-9 * (1.0 + std::abs(d));
}

bool EventBake::in_support_plane(const Body &b, const Obstacle &o, size_t k) {
    return in_plane(o, k, b.support_n, b.support_d);
}

// A free sphere touching the face of a static model, not moving into or out of it, with its
// acceleration not pulling it away, rests or slides on it: the face holds it up (the part of
// its acceleration into the face is cancelled) until it slides off the flat region the face
// belongs to. Without this a ball placed on a floor under gravity would meet the floor with
// zero speed at every instant.
bool EventBake::try_settle(int i, double t) {
    Body &b = bodies_[static_cast<size_t>(i)];
    if (!b.free_sphere() || b.supported() || b.motion == ANI_MOTION_REST) return false;
    const glm::dvec3 c = b.path.at(t - b.t0);
    const double tol = touching(b);
    for (size_t o = 0; o < obstacles_.size(); ++o) {
        const Obstacle &ob = obstacles_[o];
        if (glm::length(c - ob.center) > b.radius + ob.radius + tol) continue;
        if (b.ignored_obstacles > 0 && is_ignored(i, -1 - static_cast<int>(o))) continue;
        Holder holder;
        holder.obstacle = static_cast<int>(o);
        // (Its radius is less while it overlaps the obstacle.)
        if (settle_sphere_on(i, ob, holder, radius_against(i, static_cast<int>(o)), t)) return true;
    }
    return try_ride(i, t);
}

// The same on the faces `ob` of what holds it (a static model, or a carrier: try_ride), against
// which it moves at its velocity less the holder's, with radius r there.
bool EventBake::settle_sphere_on(int i, const Obstacle &ob, const Holder &holder, double r,
                                 double t) {
    Body &b = bodies_[static_cast<size_t>(i)];
    const glm::dvec3 c = b.path.at(t - b.t0), v = b.path.velocity(t - b.t0),
                     v_rel = v - holder.velocity;
    const double tol = touching(b);
    Box near{c - glm::dvec3(r + tol), c + glm::dvec3(r + tol)};
    for (size_t k = 0; k < ob.boxes.size(); ++k) {
        const glm::dvec3 n = ob.normals[k];
        if (n == glm::dvec3(0.0) || !near.overlaps(ob.boxes[k])) continue;
        const double h = glm::dot(n, c) - ob.offsets[k]; // height of the center above the face
        if (std::abs(h - r) > tol) continue;
        const glm::dvec3 q = closest_point_on_triangle(c, ob.corners[3 * k], ob.corners[3 * k + 1],
                                                       ob.corners[3 * k + 2]);
        if (glm::length((c - q) - h * n) > tol)
            continue;                              // nearest to an edge or a corner, not the face
        if (glm::dot(b.free_a, n) > 0.0) continue; // pulled away from it
        if (std::abs(glm::dot(v_rel, n)) > 1e-9 * std::max(1.0, glm::length(v_rel)))
            continue;                                     // bouncing
        if (!carries_along(holder.velocity, n)) continue; // a carrier moving across its face
        Body held = b;
        held.t0 = t;
        held.path =
            Path{c - (h - r) * n, v - glm::dot(v_rel, n) * n, b.free_a - glm::dot(b.free_a, n) * n};
        held_by(held, holder, t);
        held.support_n = n;
        held.support_d = ob.offsets[k];
        held.support_edges = support_boundary(ob, held);
        held.support_feet = {-r * n};
        if (leaves_support(held, t, 1e-9 * std::max(1.0, std::abs(t))))
            continue; // on the rim of the flat region, on its way off
        put_on(i, std::move(held), ob, n, t);
        return true;
    }
    return false;
}

// A free model that is not a sphere, meeting a face of a static model with no speed along its
// normal and pulled into it, rests or slides on the flat region of that face's plane.
bool EventBake::settle_on(int i, int o, const glm::dvec3 &n, double t) {
    Holder holder;
    holder.obstacle = o;
    return settle_on_face(i, obstacles_[static_cast<size_t>(o)], holder, n, t);
}

// The same on the faces `ob` of what holds it: a static model, or a carrier (try_ride), against
// which it moves at its velocity less the holder's.
bool EventBake::settle_on_face(int i, const Obstacle &ob, const Holder &holder, const glm::dvec3 &n,
                               double t) {
    Body &b = bodies_[static_cast<size_t>(i)];
    // (A turning model settles only while it does not turn.)
    if (!(b.shape || (b.turning() && b.spin.w == glm::dvec3(0.0))) || b.supported() || b.driven() ||
        b.motion == ANI_MOTION_REST || !(glm::dot(b.free_a, n) < 0.0))
        return false;
    const glm::dvec3 c = b.path.at(t - b.t0), v = b.path.velocity(t - b.t0);
    // Where its tests against the obstacle place it: moved out by its depth while it
    // overlaps it (held at that depth).
    const glm::dvec3 placed_c = holder.obstacle >= 0 ? c + shift_against(i, holder.obstacle) : c;
    // The face: one of the obstacle's, in the plane through the contact with normal n.
    int face = -1;
    for (size_t k = 0; k < ob.normals.size() && face < 0; ++k)
        if (glm::dot(ob.normals[k], n) > 1.0 - 1e-9) face = static_cast<int>(k);
    if (face < 0) return false;
    Body held = b;
    held_by(held, holder, t);
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
    // A model that turns stands there only balanced, its centre of mass over its feet along
    // gravity (support_polygon.hpp); otherwise it tips over (respond_turning_to_obstacle's
    // microcollisions). Its feet for that are the vertices within kTipSlack of its size of the
    // plane: a face tilted by less than that many radians stands on all its corners. (Those
    // within 1e-9 alone would leave a face landing flat on two corners, rounding lifting the
    // other two, to tip over by nothing at all in microcollisions without end.) One that does
    // not turn stays as its keys left it, on an edge or a corner.
    if (b.turning()) {
        std::vector<glm::dvec3> stand;
        for (const glm::dvec3 &corner : corners)
            if (std::abs(glm::dot(n, placed_c + corner) - held.support_d) <= kTipSlack * size)
                stand.push_back(corner);
        if (!over_feet(glm::dvec3(0.0), stand, b.free_a, 1e-9 * size)) return false;
        // It stays on while its centre of mass is over the flat region: past the rim it tips
        // over it (a box sliding off a step's nose), not when its last corner leaves.
        held.support_feet = {-(glm::dot(n, placed_c) - held.support_d) * n};
    }
    held.t0 = t;
    held.path = Path{c, v - glm::dot(v, n) * n, b.free_a - glm::dot(b.free_a, n) * n};
    if (leaves_support(held, t, 1e-9 * std::max(1.0, std::abs(t)))) return false;
    put_on(i, std::move(held), ob, n, t);
    return true;
}

// A copy of a body, `held`, held up from t by what `holder` says.
void EventBake::held_by(Body &held, const Holder &holder, double t) const {
    held.support = holder.obstacle;
    held.carrier = holder.carrier;
    held.support_v = holder.velocity;
    held.support_t = t;
    held.carrier_until = holder.until;
    if (holder.carrier >= 0)
        held.carrier_version = bodies_[static_cast<size_t>(holder.carrier)].version;
}

// Body i becomes `held` (itself, put on the face of `ob` with normal n at t): its motion so far
// reported, friction there from now.
void EventBake::put_on(int i, Body held, const Obstacle &ob, const glm::dvec3 &n, double t) {
    Body &b = bodies_[static_cast<size_t>(i)];
    close_segment(b, t);
    held.motion = ANI_MOTION_FREE;
    ++held.version;
    b = std::move(held);
    if (b.carrier >= 0) ++riders_;
    hold_on(b, materials_[ob.model], n);
}

// The edges that bound the flat region of an obstacle in a body's support plane: those of
// its triangles in that plane that only one of them has, with their outward normal.
std::vector<std::array<glm::dvec3, 3>> EventBake::support_boundary(const Obstacle &o,
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
        while (same < edges.size() && edges[same].a == edges[k].a && edges[same].b == edges[k].b)
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
// [now, now + limit]: a sphere's touching point, a turning model's centre of mass (seen along
// the normal), or every corner of a model that cannot turn (it tips over nothing: it is held
// until it is wholly past the rim).
std::optional<double> EventBake::leaves_support(const Body &b, double now, double limit) const {
    // Relative to the support, whose edges were at support_edges at support_t.
    Path c = from_now(b, now);
    c.p -= b.support_v * (now - b.support_t);
    c.v -= b.support_v;
    std::optional<double> last;
    for (const glm::dvec3 &foot : b.support_feet) {
        const Path p{c.p + foot, c.v, c.a};
        std::optional<double> first;
        for (const auto &[ea, eb, m] : b.support_edges) {
            const auto s =
                upward_root(glm::dot(m, p.p - ea), glm::dot(m, p.v), 0.5 * glm::dot(m, p.a), limit);
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

void EventBake::predict_leave(int i, double now, double limit, Predicted &next) {
    if (auto s = leaves_support(bodies_[static_cast<size_t>(i)], now, limit);
        s && now + *s < next.t)
        next = predicted(now + *s, EventKind::kLeave);
}

// Nothing holds it up any more: its own acceleration again.
void EventBake::unsupport(Body &b, double t) {
    if (!b.supported()) return;
    const glm::dvec3 v = b.path.velocity(t - b.t0);
    close_segment(b, t);
    b.path = Path{b.path.at(t - b.t0), v, b.free_a};
    b.t0 = t;
    b.support = -1;
    if (b.carrier >= 0) --riders_;
    b.carrier = -1;
    b.carrier_until = kNever;
    b.support_v = glm::dvec3(0.0);
    b.rub = 0.0;
    b.reaim_at = kNever;
    b.rolling = false;
    if (b.spin.on && b.spin.alpha != glm::dvec3(0.0)) restart_spin(b, t); // no friction turns it
    b.support_edges.clear();
    b.support_feet.clear();
    b.settles_at = kNever;
    ++b.version;
}

// After a contact: a body knocked off its support loses it; one that comes to slide on a
// face gains one.
void EventBake::after_contact(int i, double t) {
    Body &b = bodies_[static_cast<size_t>(i)];
    if (b.on_body >= 0 && !b.still()) { // knocked off the body it slept on: its own
        b.on_body = -1;                 // acceleration again (asleep, it had none)
        --sleepers_;
        if (b.t0 != t) rebase(b, t);
        b.path.a = b.free_a;
        ++b.version;
    }
    if (b.supported()) {
        const glm::dvec3 v = b.path.velocity(t - b.t0) - b.support_v;
        if (std::abs(glm::dot(v, b.support_n)) > 1e-9 * std::max(1.0, glm::length(v)))
            unsupport(b, t);
        else { // its new velocity and spin on the support, from here
            if (b.t0 != t) rebase(b, t);
            aim_friction(b);
        }
    }
    try_settle(i, t);
}

// The lowest of `points` (world space) along n, when it lies in the plane n . x = d of
// triangle p0 p1 p2 and over the triangle, within slack: where a model with those vertices
// stands on that face.
std::optional<glm::dvec3> EventBake::standing_point(const std::vector<glm::dvec3> &points,
                                                    const glm::dvec3 &p0, const glm::dvec3 &p1,
                                                    const glm::dvec3 &p2, const glm::dvec3 &n,
                                                    double d, double slack) {
    glm::dvec3 lowest = points.front();
    for (const glm::dvec3 &p : points)
        if (glm::dot(n, p) < glm::dot(n, lowest)) lowest = p;
    if (std::abs(glm::dot(n, lowest) - d) > slack ||
        glm::length(closest_point_on_triangle(lowest, p0, p1, p2) - lowest) > slack)
        return std::nullopt;
    return lowest;
}

// A free model that is not a sphere, placed on a face of a static model (touching its plane with
// its lowest vertices over the face, not moving into or out of it, pulled into it) and not
// turning, rests or slides there from the start: settle_on, as if it had landed there.
bool EventBake::try_settle_mesh(int i, double t) {
    Body &b = bodies_[static_cast<size_t>(i)];
    if (b.sphere || !b.active || b.driven() || b.supported() || b.motion == ANI_MOTION_REST ||
        !(b.shape || (b.turning() && b.spin.w == glm::dvec3(0.0))))
        return false;
    const glm::dvec3 c = b.path.at(t - b.t0);
    const double reach = body_size(b), slack = 1e-9 * std::max(1.0, 2.0 * reach);
    for (size_t o = 0; o < obstacles_.size(); ++o) {
        const Obstacle &ob = obstacles_[o];
        const int key = -1 - static_cast<int>(o);
        if (glm::length(c - ob.center) > reach + ob.radius + slack || is_ignored(i, key) ||
            is_overlapped(i, key))
            continue;
        for (const glm::dvec3 &n : standing_faces(i, ob, glm::dvec3(0.0), t))
            if (settle_on(i, static_cast<int>(o), n, t)) return true;
    }
    return try_ride(i, t);
}

// The normals of the faces of `ob` (what holds it up, moving at v_other) that body i stands on at
// t, each once: pulled into the face, not moving into or out of it, and touching it with its
// lowest point over the face (a sphere: its centre a radius above the face's plane, over it).
std::vector<glm::dvec3> EventBake::standing_faces(int i, const Obstacle &ob,
                                                  const glm::dvec3 &v_other, double t) const {
    const Body &b = bodies_[static_cast<size_t>(i)];
    const glm::dvec3 c = b.path.at(t - b.t0), v_rel = b.path.velocity(t - b.t0) - v_other;
    std::vector<glm::dvec3> corners;
    double slack = touching(b);
    if (!b.sphere) {
        corners = placed_vertices(b, t);
        for (glm::dvec3 &r : corners) r += c; // in world space
        slack = 1e-9 * std::max(1.0, 2.0 * body_size(b));
    }
    std::vector<glm::dvec3> faces;
    for (size_t k = 0; k < ob.normals.size(); ++k) {
        const glm::dvec3 n = ob.normals[k];
        if (n == glm::dvec3(0.0) || !(glm::dot(b.free_a, n) < 0.0) ||
            std::abs(glm::dot(v_rel, n)) > 1e-9 * std::max(1.0, glm::length(v_rel)))
            continue;
        const glm::dvec3 &p0 = ob.corners[3 * k], &p1 = ob.corners[3 * k + 1],
                         &p2 = ob.corners[3 * k + 2];
        const bool stands =
            b.sphere
                ? std::abs(glm::dot(n, c) - ob.offsets[k] - b.radius) <= slack &&
                      glm::length(closest_point_on_triangle(c, p0, p1, p2) - c) <= b.radius + slack
                : standing_point(corners, p0, p1, p2, n, ob.offsets[k], slack).has_value();
        if (stands && std::none_of(faces.begin(), faces.end(), [&](const glm::dvec3 &m) {
                return glm::dot(m, n) > 1.0 - 1e-9;
            }))
            faces.push_back(n);
    }
    return faces;
}

// ---- sliding, skidding and rolling with Coulomb friction ---------------------------------

// A body put on the support o with normal n: friction there acts with at most mu g_n per unit
// mass, the pair's mu (the higher of the two) times the part of its acceleration into the face,
// and its path on the face starts with that (aim_friction).
void EventBake::hold_on(Body &b, const Material &support, const glm::dvec3 &n) {
    const double mu = combined_friction(b.material.friction, support.friction);
    b.rub = mu * std::max(0.0, -glm::dot(b.free_a, n));
    aim_friction(b);
}

// The motion on the support from b.t0, where its path starts (physics.md, "Sliding, skidding and
// rolling"). Its own acceleration along the face is a_t; friction F, at most rub, acts against
// the slip of the touching point: the velocity of the centre for a model that does not turn, or
// u = v - r w x n for a ball that rotates.
//  - Slipping: F = -rub u/|u|. A model that does not turn slides on a parabola until v = 0; a
//    ball skids, F turning it at alpha = -(5 / 2r) n x F, until u = 0 (predict_friction). Exact
//    while a_t is along u (a level face, or straight down or up a slope); across a slope u turns
//    as it goes, and so does F: pieces over which u turns by at most kAimTurn, each with F along
//    u at its middle (physics.md gives the error).
//  - Not slipping: a model that does not turn stays still while |a_t| <= rub (static friction),
//    else slides down along a_t at |a_t| - rub. A ball rolls: F = -(2/7) a_t keeps u = 0 while
//    that is at most rub (it rolls down a slope at 5/7 a_t), else it skids along a_t.
void EventBake::aim_friction(Body &b, bool rolls) {
    constexpr double kAimTurn = 1e-3; // radians
    // (On a carrier: its velocity relative to the carrier, whose frame is inertial.)
    const glm::dvec3 v_rel = b.path.v - b.support_v;
    const glm::dvec3 n = b.support_n, a_t = b.free_a - glm::dot(b.free_a, n) * n,
                     v = v_rel - glm::dot(v_rel, n) * n;
    const bool ball = b.sphere && b.spin.on;
    const double r = b.radius;
    b.reaim_at = kNever;
    b.rolling = false;
    if (ball && (b.spin.t0 != b.t0 || b.spin.alpha != glm::dvec3(0.0)))
        restart_spin(b, b.t0); // its turn so far; from here, the rate friction gives it
    glm::dvec3 f(0.0);         // friction's acceleration
    if (b.rub > 0.0) {
        const double pull = glm::length(a_t);
        const glm::dvec3 w = ball ? b.spin.w : glm::dvec3(0.0);
        const glm::dvec3 u = ball ? v - r * glm::cross(w, n) : v;
        const double slip = glm::length(u);
        bool holds =
            ball ? slip <= 1e-12 * std::max(1.0, glm::length(v) + r * glm::length(w)) : slip == 0.0;
        // The slip's direction, and the part of a_t across it that turns it.
        const glm::dvec3 along = slip > 0.0 ? u / slip : glm::dvec3(0.0),
                         across = a_t - glm::dot(a_t, along) * along;
        // A slip that turns so fast that its next piece would not move the clock is what
        // rounding left of a slip that has ended (a model sent across a slope, stopping): it
        // holds from here (a model that does not turn stops).
        if (!holds && !rolls && glm::length(across) > 1e-12 * pull &&
            b.t0 + kAimTurn * slip / glm::length(across) == b.t0) {
            holds = true;
            if (!ball) b.path.v = b.support_v;
        }
        if (rolls || holds) {
            // (Static friction needs (2/7) |a_t| for a ball to roll, all of |a_t| for a model
            // that does not turn to stay.)
            const double need = ball ? (2.0 / 7.0) * pull : pull;
            if (need <= b.rub)
                f = ball ? -(2.0 / 7.0) * a_t : -a_t;
            else
                f = -(b.rub / pull) * a_t;
            if (ball) { // exactly no slip: the spin about the normal and the rolling rate
                b.spin.w = glm::dot(w, n) * n + glm::cross(n, v) / r;
                b.rolling = need <= b.rub;
            }
        } else {
            // The slip's rate: a_t + f for the centre, and 5/2 f more for a ball's turn.
            if (glm::length(across) <= 1e-12 * pull) {
                f = -b.rub * along;
            } else {
                // The slip at the piece's middle, with friction along the slip now, then again
                // with friction along that: its direction to second order in the turn.
                const double h = kAimTurn * slip / glm::length(across);
                const double gain = ball ? 3.5 : 1.0; // the slip's rate is a_t + gain f
                f = -b.rub * glm::normalize(u + 0.5 * h * (a_t - gain * b.rub * along));
                f = -b.rub * glm::normalize(u + 0.5 * h * (a_t + gain * f));
                b.reaim_at = b.t0 + h;
            }
        }
        if (ball) b.spin.alpha = -(2.5 / r) * glm::cross(n, f);
    }
    b.path.a = a_t + f;
}

// When friction changes on the support: the slip ends (a model that does not turn stops, a ball
// starts rolling) where it reaches 0 along a line against it, or friction is aimed again.
void EventBake::predict_friction(int i, double now, double &limit, Predicted &next) const {
    const Body &b = bodies_[static_cast<size_t>(i)];
    if (!b.supported() || b.rub == 0.0 || b.rolling) return;
    const Path p = from_now(b, now);
    glm::dvec3 u = p.v - b.support_v, rate = p.a;
    if (b.sphere && b.spin.on) {
        u -= b.radius * glm::cross(b.spin.rate(now), b.support_n);
        rate -= b.radius * glm::cross(b.spin.alpha, b.support_n);
    }
    double s = kNever;
    int stops = 0;
    if (const double along = glm::dot(u, rate); along < 0.0) {
        s = -along / glm::dot(rate, rate);
        stops = 1;
    }
    if (b.reaim_at - now < s) {
        s = std::max(0.0, b.reaim_at - now);
        stops = 0;
    }
    if (s <= limit) {
        limit = s;
        next = predicted(now + s, EventKind::kFriction, stops);
    }
}

// The event: the slip ends exactly here (a model that does not turn is at rest, and static
// friction may then hold it; a ball rolls), or it goes on with friction aimed along it now.
void EventBake::friction_changes(Body &b, double now, bool stops) {
    const glm::dvec3 p = b.path.at(now - b.t0), v = b.path.velocity(now - b.t0);
    const bool ball = b.sphere && b.spin.on;
    close_segment(b, now);
    b.t0 = now;
    b.path = Path{p, stops && !ball ? b.support_v : v, b.path.a};
    aim_friction(b, stops && ball);
    ++b.version;
}

// ---- resting on other models ----------------------------------------------------------

// Body x, turning, meets body y, which rests (still on a static model or on another resting
// body) or stands without Dynamics (immovable), at `point` with normal n from y towards x, while
// its acceleration presses it into y: when it comes so slowly that the bounces left are too small
// to follow (the Zeno rule's threshold, whatever its restitution) and it turns no faster, and
// friction can hold it there, it goes to sleep on y: still, at no cost, until y moves
// (wake_riders). y takes nothing from it: the bodies under it rest on their own supports, which
// carry it.
bool EventBake::sleep_on_body(int x, int y, const glm::dvec3 &n, const glm::dvec3 &point,
                              double t) {
    Body &b = bodies_[static_cast<size_t>(x)];
    const Body &under = bodies_[static_cast<size_t>(y)];
    if (!(b.turning() || b.free_sphere()) || b.driven() || !b.dynamics || b.supported() ||
        b.on_body >= 0 || !immovable(under))
        return false;
    const double g_n = -glm::dot(b.free_a, n);
    if (!(g_n > 0.0)) return false;
    const glm::dvec3 c = b.path.at(t - b.t0);
    const double scale = std::max(1.0, glm::length(c));
    const double v_min = std::sqrt(2.0 * g_n * kZenoHeight * scale);
    const double approach = std::max(0.0, -glm::dot(point_velocity(b, point, t), n));
    // (Nor while it slides across y: a box knocked over the one it slept on.)
    const glm::dvec3 v = b.path.velocity(t - b.t0);
    const double slide = glm::length(v - glm::dot(v, n) * n);
    if (approach * approach / (2.0 * g_n) > kZenoHeight * scale || slide > v_min ||
        glm::length(b.spin.rate(t)) * (b.sphere ? b.radius : b.turning_reach) > v_min)
        return false;
    const double mu = combined_friction(b.material.friction, under.material.friction);
    if (glm::length(b.free_a + g_n * n) > mu * g_n) return false; // it would slide
    if (!b.sphere && !balanced_on(b, under, n, point, t)) return false; // it tips over y's edge
    close_segment(b, t);
    b.path = Path{c, glm::dvec3(0.0), glm::dvec3(0.0)};
    b.t0 = t;
    if (b.spin.on) turn(b, t, glm::dvec3(0.0));
    b.on_body = y;
    b.support_n = n; // (it has no support of its own: support stays -1)
    b.settles_at = kNever;
    ++b.version;
    ++sleepers_;
    return true;
}

// Whether body b, touching body y at `point` with normal n (from y towards b), stands balanced
// on it: its centre of mass over the part of the plane where its vertices and y's meet (each
// set's vertices within kTipSlack of its size of that plane; support_polygon.hpp), seen along
// its acceleration. Both convex, the line meets their intersection when it meets each. A box
// left overhanging a platform's edge tips over it (by microcollisions) instead of sleeping.
bool EventBake::balanced_on(const Body &b, const Body &y, const glm::dvec3 &n,
                            const glm::dvec3 &point, double t) const {
    const double size = std::max(1.0, 2.0 * body_size(b)), d = glm::dot(n, point);
    const glm::dvec3 c = b.path.at(t - b.t0); // a turning body's path is its centre of mass's
    auto feet = [&](const Body &x) {
        std::vector<glm::dvec3> in_plane;
        for (const glm::dvec3 &p : placed(x, pose(x, t)).vertices)
            if (std::abs(glm::dot(n, p) - d) <= kTipSlack * size) in_plane.push_back(p - c);
        return in_plane;
    };
    return over_feet(glm::dvec3(0.0), feet(b), b.free_a, 1e-9 * size) &&
           over_feet(glm::dvec3(0.0), feet(y), b.free_a, 1e-9 * size);
}

// A blow along `push` on resting body b is taken by what holds it up when it presses b into its
// support and friction there can hold its part across (the stack's contact problem solved as one:
// the support's normal and friction forces together cancel it). A blow from the side, or one
// slanting more than the friction cone allows (a ball striking a frictionless stack's edge),
// moves b, which then meets its support as any other body does.
bool EventBake::held_by_support(const Body &b, const glm::dvec3 &push) const {
    // Still on a static model or a resting body, still on a carrier (moving with it), or stuck to
    // a platform that accelerates: what holds it up is of infinite mass, or rests on one.
    const bool on_carrier = b.carrier >= 0 && b.mode == Body::Mode::kFree &&
                            b.path.a == glm::dvec3(0.0) && b.path.v == b.support_v &&
                            (!b.turning() || b.spin.w == glm::dvec3(0.0));
    if (!resting(b) && !on_carrier && !b.carried()) return false;
    const double into = -glm::dot(push, b.support_n);
    if (!(into > 0.0)) return false;
    const double across = glm::length(push + into * b.support_n);
    const int holder = b.on_body >= 0 ? b.on_body : b.carried() ? b.carried_by : b.carrier;
    const double mu =
        holder >= 0 ? combined_friction(b.material.friction,
                                        bodies_[static_cast<size_t>(holder)].material.friction)
                    : combined_friction(
                          b.material.friction,
                          materials_[obstacles_[static_cast<size_t>(b.support)].model].friction);
    // (A push straight into it, to rounding, is held by any support.)
    return across <= mu * into + 1e-12;
}

// At the start of the bake: a turning model placed at rest on a resting one (a stack, built
// from the floor up) sleeps on it from the start, as one put on a face does (try_settle_mesh),
// instead of falling into it by nothing and being followed through ever smaller bounces.
void EventBake::settle_stacks(double t) {
    for (bool changed = true; changed;) {
        changed = false;
        for (size_t x = 0; x < bodies_.size(); ++x) {
            const Body &b = bodies_[x];
            if (!b.active || !b.turning() || b.driven() || resting(b) ||
                b.path.velocity(t - b.t0) != glm::dvec3(0.0) || b.spin.rate(t) != glm::dvec3(0.0))
                continue;
            const double slack = 1e-9 * std::max(1.0, 2.0 * body_size(b));
            const std::vector<glm::dvec3> corners = placed(b, pose(b, t)).vertices;
            for (size_t y = 0; y < bodies_.size() && !changed; ++y) {
                const Body &under = bodies_[y];
                if (y == x || !under.active || under.sphere || !immovable(under)) continue;
                // The faces of y facing up against x's acceleration whose plane x's lowest
                // vertex lies in, over the face: x stands on that face (the normal a touching
                // pair's closest features would leave undecided).
                const PlacedMesh m = placed(under, pose(under, t));
                for (size_t k = 0; k < m.triangle_count && !changed; ++k) {
                    const glm::dvec3 &p0 = m.vertices[m.triangles[3 * k]],
                                     &p1 = m.vertices[m.triangles[3 * k + 1]],
                                     &p2 = m.vertices[m.triangles[3 * k + 2]];
                    glm::dvec3 n = glm::cross(p1 - p0, p2 - p0);
                    if (glm::length(n) == 0.0) continue;
                    n = glm::normalize(n);
                    if (glm::dot(n, p0 - m.center) < 0.0) n = -n; // outward
                    if (!(glm::dot(b.free_a, n) < 0.0)) continue;
                    const auto lowest =
                        standing_point(corners, p0, p1, p2, n, glm::dot(n, p0), slack);
                    if (!lowest) continue;
                    changed =
                        sleep_on_body(static_cast<int>(x), static_cast<int>(y), n, *lowest, t);
                }
            }
        }
    }
}

// Body j has moved: the bodies asleep on it wake, at rest where they are, under their own
// acceleration, and so do the ones asleep on them.
void EventBake::wake_riders(int j, double t) {
    if (sleepers_ == 0 || immovable(bodies_[static_cast<size_t>(j)])) return;
    count_.scanned += bodies_.size();
    for (size_t k = 0; k < bodies_.size(); ++k) {
        Body &r = bodies_[k];
        if (r.on_body != j) continue;
        r.on_body = -1;
        --sleepers_;
        close_segment(r, t);
        r.path = Path{r.path.at(t - r.t0), glm::dvec3(0.0), r.free_a};
        r.t0 = t;
        ++r.version;
        wake_riders(static_cast<int>(k), t);
        predict(static_cast<int>(k), t);
    }
}

} // namespace physics_custom::bake
