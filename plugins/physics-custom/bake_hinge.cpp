// The event-driven bake's tipping (physics.md, "Tipping"): a turning model that stands on an edge
// of a face of a static model, its centre of mass not over that edge, turns about it as an
// upside-down pendulum, in closed form (animator/pendulum.hpp), until a vertex lands on the face,
// or until the contact forces that motion needs would pull the edge down or exceed friction
// (then it turns freely, and microcollisions take it on); one lying with a face across an edge
// of a static model, its centre of mass beyond it, turns about that edge the same way
// (try_hinge_over_edge); and either on a body without Dynamics that stands (try_hinge_on_body).
// Relies on bake_response.cpp, which calls them where it would otherwise start microcollisions at
// an edge.
#include "event_bake_detail.hpp"

namespace physics_custom::bake {

namespace {

// The rotation of x by `angle` about the unit axis u (Rodrigues).
glm::dvec3 turned(const glm::dvec3 &x, const glm::dvec3 &u, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    return c * x + s * glm::cross(u, x) + (1.0 - c) * glm::dot(u, x) * u;
}

} // namespace

// Whether x, on the plane n . x = d, is on a triangle of the obstacle in that plane.
bool EventBake::on_flat_region(const Obstacle &o, const glm::dvec3 &n, double d,
                               const glm::dvec3 &x) const {
    const double slack = 1e-9 * std::max(1.0, glm::length(x));
    for (size_t k = 0; k < o.normals.size(); ++k) {
        if (!in_plane(o, k, n, d)) continue;
        const glm::dvec3 q =
            closest_point_on_triangle(x, o.corners[3 * k], o.corners[3 * k + 1], o.corners[3 * k + 2]);
        if (glm::length(q - x) <= slack) return true;
    }
    return false;
}

// Body i, a turning model touching obstacle o's face (normal n) at time t and leaving it too slowly
// to follow its bounces (bake_response.cpp's microcollisions), with velocity v and angular velocity
// w after the contact's impulse: when it stands on one edge of that face, level, its centre of mass
// over the edge's span, and the edge can hold it (the impulse that makes the edge's points still
// within the friction cone), it turns about that edge from here, its angular momentum about the
// edge kept (a plastic contact). True when it does.
bool EventBake::try_hinge(int i, const HingeSupport &on, const glm::dvec3 &n, const glm::dvec3 &v,
                          const glm::dvec3 &w, double t) {
    Body &b = bodies_[static_cast<size_t>(i)];
    if (!b.turning() || b.hinge || !b.dynamics || b.supported()) return false;
    const glm::dvec3 g = b.free_a;
    const double gl = glm::length(g);
    if (!(gl > 0.0) || !(glm::dot(g, n) < 0.0)) return false;
    const Obstacle &ob = *on.triangles;
    const glm::dvec3 c = b.path.at(t - b.t0);
    const glm::dquat q = b.spin.at(t);
    const glm::dmat3 R = glm::mat3_cast(q);
    const double size = std::max(1.0, 2.0 * b.turning_reach);
    std::vector<glm::dvec3> x;
    double low = kNever;
    for (const glm::dvec3 &tv : b.turning_vertices) {
        x.push_back(c + R * tv);
        low = std::min(low, glm::dot(n, x.back()));
    }
    // The face's plane: of the faces facing along n, the one through its lowest vertex.
    double d = kNever;
    for (size_t k = 0; k < ob.normals.size(); ++k)
        if (glm::dot(ob.normals[k], n) > 1.0 - 1e-9 && std::abs(ob.offsets[k] - low) <= 1e-6 * size &&
            (d == kNever || std::abs(ob.offsets[k] - low) < std::abs(d - low)))
            d = ob.offsets[k];
    if (d == kNever) return false;
    // Its feet (settle_on's: within 1e-6 of its size of the plane) on one line, at least 1e-6 of
    // its size long: an edge, not a corner or a face.
    std::vector<size_t> feet;
    for (size_t k = 0; k < x.size(); ++k)
        if (glm::dot(n, x[k]) - d <= kTipSlack * size) feet.push_back(k);
    if (feet.size() < 2) return false;
    const glm::dvec3 a = x[feet[0]];
    glm::dvec3 e = a;
    for (size_t k : feet)
        if (glm::length(x[k] - a) > glm::length(e - a)) e = x[k];
    const double length = glm::length(e - a);
    if (!(length > kTipSlack * size)) return false;
    const glm::dvec3 u = (e - a) / length;
    for (size_t k : feet) {
        const glm::dvec3 off = x[k] - a;
        if (glm::length(off - glm::dot(off, u) * u) > 1e-9 * size) return false; // on a face
        if (!on_flat_region(ob, n, d, x[k] - (glm::dot(n, x[k]) - d) * n)) return false;
    }
    // Level, so that gravity turns it about the edge alone; its centre over the edge's span.
    if (std::abs(glm::dot(u, g)) > 1e-9 * gl) return false;
    const double s = glm::dot(c - a, u);
    if (!(s > 1e-9 * length && s < (1.0 - 1e-9) * length)) return false;
    const glm::dvec3 P = a + s * u, r0 = c - P;
    const double rho = glm::length(r0);
    if (!(rho > 1e-9 * size)) return false;
    const double m = collision_mass(b);
    double psi0 = 0.0, mu = 0.0;
    auto pendulum = hinge_pendulum(b, ob, u, r0, n, v, w, t, psi0, mu);
    if (!pendulum) return false;
    auto h = new_hinge(b, on, P, n, R, c);
    // Nothing of the obstacle above the face's plane within its reach: the landing on the face is
    // then its first contact with the obstacle.
    for (const glm::dvec3 &corner : ob.shape->vertices)
        if (glm::dot(n, corner) - d > 1e-9 * size && glm::length(corner - P) <= h->reach * (1.0 + 1e-9))
            return false;
    // The landing: the first time a vertex off the edge meets the plane, on its circle about the
    // edge: height(delta) = H + B cos(delta) + C sin(delta) = 0 for a turn delta = psi - psi0.
    for (size_t k = 0; k < x.size(); ++k) {
        if (std::find(feet.begin(), feet.end(), k) != feet.end()) continue;
        const glm::dvec3 y = x[k] - P, across = y - glm::dot(y, u) * u;
        const double H = glm::dot(n, P) - d + glm::dot(y, u) * glm::dot(n, u),
                     B = glm::dot(n, across), C = glm::dot(n, glm::cross(u, across)),
                     span = std::hypot(B, C);
        if (!(span > 0.0) || std::abs(H) > span) continue;
        const double phase = std::atan2(C, B), half = std::acos(std::clamp(-H / span, -1.0, 1.0));
        for (double delta : {phase - half, phase + half})
            h->landing = std::min(h->landing, pendulum->first_time_at(psi0 + delta, t));
    }
    if (!(h->landing < kNever) || !(h->landing > t)) return false;
    const double turn_at_landing = pendulum->angle(h->landing) - psi0;
    for (size_t k = 0; k < x.size(); ++k) {
        const glm::dvec3 at = P + turned(x[k] - P, u, turn_at_landing);
        if (glm::dot(n, at) - d <= 1e-9 * size) {
            if (!on_flat_region(ob, n, d, at - (glm::dot(n, at) - d) * n)) return false;
            h->landing_points.push_back(at);
        }
    }
    // The contact's point: the one farthest from the edge, the fastest to land.
    auto off_edge = [&](const glm::dvec3 &p) { return glm::length(glm::cross(p - P, u)); };
    std::sort(h->landing_points.begin(), h->landing_points.end(),
              [&](const glm::dvec3 &x1, const glm::dvec3 &x2) { return off_edge(x1) > off_edge(x2); });
    // The contact force the motion needs, to the landing, along the face's normal.
    auto holds = [&](double time) {
        return edge_holds(*pendulum, time, u, r0, psi0, n, false, m, g, mu);
    };
    if (!holds(t)) return false;
    h->ends = first_failure(holds, t, h->landing);
    if (!(h->ends > t)) return false;
    begin_hinge(b, t, q, u, std::move(pendulum), std::move(h));
    return true;
}

// Body i, a turning model lying with a face across an edge of `on` (a box left overhanging a
// table), touching it at `points` on that edge (or on the table's face on its side), with velocity
// v and angular velocity w before the contact's impulse: when the edge is level and the model's
// centre of mass lies beyond it, over the span its face covers, and is not turning back, it turns
// about the edge from here, its angular momentum about the edge kept (a plastic contact), as the
// upside-down pendulum of try_hinge. The edge stays on its face's material line; the contact
// force its motion needs is taken along that face's normal, which turns with it. The rest of the
// table within its reach, below its top and behind the edge, cannot meet its face turning down
// about the edge before a quarter turn; a static model's triangles above the top or beyond the
// edge (the lower steps) are met as any turning model's contacts (Hinge::beyond). The hinge ends
// at such a contact, when the force fails (it slips or lifts off the edge) or at 80 degrees, and
// it turns freely from there. True when it does.
bool EventBake::try_hinge_over_edge(int i, const HingeSupport &on,
                                    const std::vector<glm::dvec3> &points, const glm::dvec3 &v,
                                    const glm::dvec3 &w, double t) {
    Body &b = bodies_[static_cast<size_t>(i)];
    if (!b.turning() || b.hinge || !b.dynamics || b.supported() || points.empty()) return false;
    const glm::dvec3 g = b.free_a;
    const double gl = glm::length(g);
    if (!(gl > 0.0)) return false;
    const Obstacle &ob = *on.triangles;
    const glm::dvec3 c = b.path.at(t - b.t0);
    const glm::dquat q = b.spin.at(t);
    const glm::dmat3 R = glm::mat3_cast(q);
    const double size = std::max(1.0, 2.0 * b.turning_reach), slack = 1e-9 * size;
    // An edge of the obstacle with a face of the obstacle on it facing the model (the table's top),
    // and the side the obstacle is on: the touching points on that edge, or on that face's plane
    // on its side (a box still lying flat on the table, overhanging), at least one on the edge.
    const MeshShape &shape = *ob.shape;
    auto on_segment = [&](const glm::dvec3 &x, const glm::dvec3 &p0, const glm::dvec3 &p1) {
        const glm::dvec3 d = p1 - p0;
        const double s = std::clamp(glm::dot(x - p0, d) / glm::dot(d, d), 0.0, 1.0);
        return glm::length(x - (p0 + s * d)) <= slack;
    };
    glm::dvec3 E0(0.0), top(0.0), out(0.0), u(0.0);
    double edge_length = 0.0;
    bool found = false;
    for (const auto &edge : shape.edges) {
        const glm::dvec3 &p0 = shape.vertices[edge[0]], &p1 = shape.vertices[edge[1]];
        if (!(glm::length(p1 - p0) > 0.0) ||
            !std::any_of(points.begin(), points.end(),
                         [&](const glm::dvec3 &p) { return on_segment(p, p0, p1); }))
            continue;
        for (size_t k = 0; k < shape.triangles.size(); ++k) {
            const auto &tri = shape.triangles[k];
            int shared = 0, third = -1;
            for (uint32_t x : tri) {
                if (x == edge[0] || x == edge[1])
                    ++shared;
                else
                    third = static_cast<int>(x);
            }
            const glm::dvec3 nk = shape.normals[k];
            if (shared != 2 || third < 0 || !(glm::dot(nk, c - p0) > 0.0) || !(glm::dot(nk, g) < 0.0))
                continue;
            if (found && glm::dot(nk, g) >= glm::dot(top, g)) continue; // the one facing up most
            const glm::dvec3 along = glm::normalize(p1 - p0);
            glm::dvec3 away = glm::normalize(glm::cross(along, nk));
            if (glm::dot(away, shape.vertices[static_cast<size_t>(third)] - p0) > 0.0) away = -away;
            if (!std::all_of(points.begin(), points.end(), [&](const glm::dvec3 &p) {
                    return on_segment(p, p0, p1) || (std::abs(glm::dot(nk, p - p0)) <= slack &&
                                                     glm::dot(away, p - p0) <= slack);
                }))
                continue;
            found = true;
            E0 = p0;
            edge_length = glm::length(p1 - p0);
            u = along;
            top = nk;
            out = away;
        }
    }
    if (!found) return false;
    // Level, so that gravity turns it about the edge alone; its centre of mass beyond the edge.
    if (std::abs(glm::dot(u, g)) > 1e-9 * gl) return false;
    const double sc = glm::dot(c - E0, u);
    const glm::dvec3 P = E0 + sc * u, r0 = c - P;
    const double rho = glm::length(r0);
    if (!(rho > slack) || !(glm::dot(r0, out) > slack)) return false;
    // Its face on the edge: the plane through the line that has all its vertices on the side of
    // its centre and touches another of them, the one nearest the table's top.
    std::vector<glm::dvec3> x;
    double reach = 0.0;
    for (const glm::dvec3 &tv : b.turning_vertices) {
        x.push_back(c + R * tv);
        reach = std::max(reach, glm::length(x.back() - P));
    }
    glm::dvec3 face(0.0);
    for (const glm::dvec3 &y : x) {
        glm::dvec3 m = glm::cross(u, y - P);
        if (!(glm::length(m) > slack)) continue; // on the line
        m = glm::normalize(m);
        if (glm::dot(m, r0) < 0.0) m = -m;
        bool all = true;
        for (const glm::dvec3 &z : x) all = all && glm::dot(m, z - P) >= -slack;
        if (all && glm::dot(m, top) > glm::dot(face, top)) face = m;
    }
    if (!(glm::dot(face, top) > 0.0)) return false;
    // Its centre of mass over the span of the edge its face lies on: where the line crosses the
    // face, its vertices within 1e-6 of its size of that plane (a tilt of rounding size across
    // the edge lifts one end of the line of contact, not the face off it), within the edge.
    std::vector<glm::dvec3> on_face;
    for (const glm::dvec3 &y : x)
        if (glm::dot(face, y - P) <= kTipSlack * size) on_face.push_back(y);
    const glm::dvec3 across = glm::cross(face, u);
    double from = kNever, to = -kNever;
    auto covers = [&](const glm::dvec3 &y) {
        from = std::min(from, glm::dot(y - E0, u));
        to = std::max(to, glm::dot(y - E0, u));
    };
    for (size_t j = 0; j < on_face.size(); ++j) {
        const double dj = glm::dot(across, on_face[j] - P);
        if (std::abs(dj) <= slack) covers(on_face[j]);
        for (size_t k = j + 1; k < on_face.size(); ++k) {
            const double dk = glm::dot(across, on_face[k] - P);
            if ((dj < -slack && dk > slack) || (dj > slack && dk < -slack))
                covers(on_face[j] + (on_face[k] - on_face[j]) * (dj / (dj - dk)));
        }
    }
    if (!(sc > std::max(from, 0.0) + slack && sc < std::min(to, edge_length) - slack)) return false;
    // The obstacle's triangles within its reach above the table's face or beyond the edge (the
    // lower steps beyond a step's nose): a static model's are its landing's, found as any turning
    // model's contacts (predict_obstacles); none may touch it at the edge. Nothing else of the
    // obstacle can meet its face turning down about the edge before a quarter turn.
    std::vector<uint32_t> beyond;
    for (size_t k = 0; k + 2 < ob.corners.size(); k += 3) {
        const glm::dvec3 near = closest_point_on_triangle(P, ob.corners[k], ob.corners[k + 1],
                                                          ob.corners[k + 2]);
        if (glm::length(near - P) > reach * (1.0 + 1e-9) + slack) continue;
        bool outside = false;
        for (size_t j = k; j < k + 3; ++j)
            outside = outside || glm::dot(top, ob.corners[j] - P) > slack ||
                      glm::dot(out, ob.corners[j] - P) > slack;
        if (!outside) continue;
        if (on.obstacle < 0 || glm::length(glm::cross(near - P, u)) <= kTipSlack * size)
            return false;
        const auto &corners = shape.triangles[k / 3];
        beyond.insert(beyond.end(), corners.begin(), corners.end());
    }
    // The pendulum about the edge, as try_hinge's.
    const double m = collision_mass(b);
    double psi0 = 0.0, mu = 0.0;
    auto pendulum = hinge_pendulum(b, ob, u, r0, face, v, w, t, psi0, mu);
    if (!pendulum) return false;
    // Away from the table: the turn that carries the centre of mass outwards, which gravity
    // speeds; not turning back.
    double psi_now = 0.0, rate0 = 0.0;
    pendulum->evaluate(t, psi_now, rate0);
    const double away = glm::dot(glm::cross(u, r0), out) > 0.0 ? 1.0 : -1.0;
    if (!(-std::sin(psi0) * away > 0.0) || rate0 * away < 0.0) return false;
    const double quarter = pendulum->first_time_at(psi0 + away * 80.0 * M_PI / 180.0, t);
    if (!(quarter > t && quarter < kNever)) return false;
    // The contact force the motion needs, along its face's normal, which turns with it.
    auto holds = [&](double time) {
        return edge_holds(*pendulum, time, u, r0, psi0, face, true, m, g, mu);
    };
    if (!holds(t)) return false;
    auto h = new_hinge(b, on, P, face, R, c);
    h->beyond = std::move(beyond);
    h->ends = std::min(quarter, first_failure(holds, t, quarter));
    if (!(h->ends > t)) return false;
    begin_hinge(b, t, q, u, std::move(pendulum), std::move(h));
    return true;
}

// Body i, a turning model, meets body j, which stands without Dynamics (a platform released from
// its keys: immovable), at `points` with normal n from j towards i, too slowly to follow its
// bounces: as against a static model (try_hinge, try_hinge_over_edge), it tips over an edge it
// stands on, on j's face, or over j's edge its face lies across, j's triangles placed as they
// stand. Until j's next key at most: its keys may move it from then. True when it does.
bool EventBake::try_hinge_on_body(int i, int j, const glm::dvec3 &n,
                                  const std::vector<glm::dvec3> &points, const glm::dvec3 &v,
                                  const glm::dvec3 &w, double t) {
    const Body &o = bodies_[static_cast<size_t>(j)];
    if (o.dynamics || o.sphere || o.keyed() || !immovable(o) || !(o.resume_at > t)) return false;
    Obstacle face = face_of(o, t);
    const Pose p = pose(o, t);
    face.shape = build_shape(o.model, ani(p.center), p.linear, glm::dvec3(0.0));
    HingeSupport on;
    on.triangles = &face;
    on.body = j;
    on.until = o.resume_at;
    return try_hinge(i, on, n, v, w, t) || try_hinge_over_edge(i, on, points, v, w, t);
}

// Body b turning about the line along u through its point at -r0 from its centre of mass, from t,
// with velocity v and angular velocity w before the contact (normal n) with static model ob that
// holds the line: the upside-down pendulum, psi'' = -w^2 sin psi with psi from straight down (b's
// acceleration) about u and w^2 = m g rho / I_line, starting at psi0 with the angular momentum
// about the line it has (a plastic contact). Null unless the line is a principal direction of its
// inertia (no wobble that would need a torque across it) and the impulse that makes the line
// still pushes, within the friction cone (mu, the pair's friction).
std::shared_ptr<const ani::Pendulum>
EventBake::hinge_pendulum(const Body &b, const Obstacle &ob, const glm::dvec3 &u,
                          const glm::dvec3 &r0, const glm::dvec3 &n, const glm::dvec3 &v,
                          const glm::dvec3 &w, double t, double &psi0, double &mu) const {
    const double m = collision_mass(b), rho = glm::length(r0), gl = glm::length(b.free_a);
    const glm::dmat3 I = b.spin.moments.x > 0.0 ? glm::inverse(b.spin.inverse_inertia(t))
                                                : glm::dmat3(1.0 / b.inv_inertia);
    const double Iu = glm::dot(u, I * u);
    if (glm::length(I * u - Iu * u) > 1e-9 * Iu) return nullptr;
    const double Ih = Iu + m * rho * rho;
    const double rate0 = glm::dot(u, I * w + m * glm::cross(r0, v)) / Ih;
    const Material &mo = materials_[ob.model];
    mu = combined_friction(b.material.friction, mo.friction);
    const glm::dvec3 J = m * (rate0 * glm::cross(u, r0) - v);
    const double Jn = glm::dot(J, n), tiny = 1e-12 * m * std::max(1.0, glm::length(v));
    if (Jn < -tiny || glm::length(J - Jn * n) > mu * Jn + tiny) return nullptr;
    const glm::dvec3 down = b.free_a / gl, side = glm::cross(u, down);
    psi0 = std::atan2(glm::dot(r0, side), glm::dot(r0, down));
    return std::make_shared<const ani::Pendulum>(m * gl * rho / Ih, psi0, rate0, t);
}

// A hinge of body b (at centre c, turned by R) about the line through P on `on`, n the contact's
// normal: its vertices and reach about P.
std::shared_ptr<Hinge> EventBake::new_hinge(const Body &b, const HingeSupport &on,
                                            const glm::dvec3 &P, const glm::dvec3 &n,
                                            const glm::dmat3 &R, const glm::dvec3 &c) {
    auto h = std::make_shared<Hinge>();
    h->support = on.obstacle;
    h->support_body = on.body;
    h->support_until = on.until;
    h->point = P;
    h->normal = n;
    h->pivot = b.pivot + glm::transpose(R) * (P - c);
    for (const glm::dvec3 &tv : b.turning_vertices) {
        h->vertices.push_back(tv - (h->pivot - b.pivot));
        h->reach = std::max(h->reach, glm::length(h->vertices.back()));
    }
    return h;
}

// Whether the contact at a hinge holds at `time`: the force the pendulum's motion needs,
// R = m (a - g) with a = psi'' u x r - psi'^2 r (r0 the centre of mass from the line at psi0),
// pushes along the contact's normal (n . R >= 0) and stays within the friction cone. n as at psi0,
// turned with the model when `normal_turns` (its own face on another's edge).
bool EventBake::edge_holds(const ani::Pendulum &pendulum, double time, const glm::dvec3 &u,
                           const glm::dvec3 &r0, double psi0, const glm::dvec3 &n0,
                           bool normal_turns, double m, const glm::dvec3 &g, double mu) {
    double psi, rate;
    pendulum.evaluate(time, psi, rate);
    const glm::dvec3 r = turned(r0, u, psi - psi0);
    const glm::dvec3 n = normal_turns ? turned(n0, u, psi - psi0) : n0;
    const glm::dvec3 accel = -pendulum.omega2() * std::sin(psi) * glm::cross(u, r) - rate * rate * r;
    const glm::dvec3 F = m * (accel - g);
    const double N = glm::dot(F, n), slack = 1e-12 * m * glm::length(g);
    return N >= -slack && glm::length(F - N * n) <= mu * N + slack;
}

// The end of the span from t in which `holds` holds, within (t, until] (kNever if it holds
// throughout): checked at 256 times and, where it fails, its first failure found by bisection
// (the contact force is a trigonometric polynomial of degree 2 in the angle: at most four sign
// changes over a turn).
double EventBake::first_failure(const std::function<bool(double)> &holds, double t, double until) {
    constexpr int kSamples = 256;
    double before = t;
    for (int k = 1; k <= kSamples; ++k) {
        const double at = t + (until - t) * k / kSamples;
        if (holds(at)) {
            before = at;
            continue;
        }
        double lo = before, hi = at;
        while (hi - lo > 1e-15 * std::max(1.0, std::abs(hi))) {
            const double mid = 0.5 * (lo + hi);
            if (mid <= lo || mid >= hi) break;
            (holds(mid) ? lo : hi) = mid;
        }
        return lo;
    }
    return kNever;
}

// From t body b turns about the line through h's point along u as the pendulum says: its path is
// that still point's, its turn the pendulum's from orientation q.
void EventBake::begin_hinge(Body &b, double t, const glm::dquat &q, const glm::dvec3 &u,
                            std::shared_ptr<const ani::Pendulum> pendulum,
                            std::shared_ptr<Hinge> h) {
    close_segment(b, t);
    emit_spin(b, t);
    b.t0 = t;
    b.path = Path{h->point, glm::dvec3(0.0), glm::dvec3(0.0)};
    b.motion = ANI_MOTION_FREE;
    b.settles_at = kNever;
    b.spin.hinge_on(t, q, u, std::move(pendulum));
    h->ends = std::min(h->ends, h->support_until); // a body under it may move from then
    b.hinge = std::move(h);
    ++b.version;
    ++count_.hinges;
}

// A tipping body turns freely from t on, where the hinge has put it: its centre of mass back on a
// parabola, with the velocity and angular velocity the hinge gives it then.
void EventBake::unhinge(Body &b, double t) {
    if (!b.hinge) return;
    const glm::dquat q = b.spin.at(t);
    const glm::dvec3 w = b.spin.rate(t);
    const glm::dvec3 arm = glm::mat3_cast(q) * (b.pivot - b.hinge->pivot); // hinge point to centre
    close_segment(b, t);
    emit_spin(b, t);
    b.t0 = t;
    b.path = Path{b.hinge->point + arm, glm::cross(w, arm), b.free_a};
    b.spin.start(t, q, w);
    b.hinge.reset();
    ++b.version;
}

// A tipping body's own next event: its landing on the face (of the static model, or of the body
// it stands on), or the end of the hinge.
void EventBake::predict_hinge(const Body &b, double now, Predicted &next) const {
    const Hinge &h = *b.hinge;
    if (h.landing <= h.ends) {
        if (!(h.landing < next.t)) return;
        Contact contact;
        contact.t = h.landing - now;
        contact.normal = h.normal;
        contact.point = h.landing_points.front();
        if (h.support_body >= 0) {
            const Body &o = bodies_[static_cast<size_t>(h.support_body)];
            next = predicted(h.landing, EventKind::kBody, h.support_body, o.version, contact);
            next.moving_in = true;
        } else {
            next = predicted(h.landing, EventKind::kObstacle, h.support, 0, contact);
        }
        next.points = h.landing_points;
    } else if (h.ends < next.t) {
        next = predicted(h.ends, EventKind::kHinge);
    }
}

} // namespace physics_custom::bake
