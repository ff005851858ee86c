#include "mesh_contact.hpp"

#include "polynomial.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <queue>
#include <stdexcept>
#include <tuple>

namespace physics_custom {

namespace {

constexpr uint32_t leaf_size = 4;
constexpr uint32_t no_edge = std::numeric_limits<uint32_t>::max();
constexpr double infinity = std::numeric_limits<double>::infinity();

// Sines below these make two directions the same. Coplanar triangles and a normal on the end of
// an edge's arc are judged loosely (a rotated mesh's flat faces differ by rounding); edges are
// parallel only when their crossing point could not be located at all.
constexpr double flat_sine = 1e-9;
constexpr double parallel_sine = 1e-12;
// Boxes are widened by this much of the scene's size so that touching counts despite rounding;
// features this close at t = 0 are touching.
constexpr double box_margin = 1e-12;
// Contacts this close to the earliest (relative to t_max) are simultaneous (see the header).
constexpr double simultaneous = 1e-12;

Box box_around(const glm::dvec3 &p, const glm::dvec3 &q) {
    return Box{glm::min(p, q), glm::max(p, q)};
}
Box merged(const Box &a, const Box &b) {
    return Box{glm::min(a.lo, b.lo), glm::max(a.hi, b.hi)};
}
Box widened(const Box &b, double m) {
    return Box{b.lo - m, b.hi + m};
}
// The box a box sweeps when displaced by every offset in `sweep` (the Minkowski sum).
Box swept_by(const Box &b, const Box &sweep) {
    return Box{b.lo + sweep.lo, b.hi + sweep.hi};
}
double size_of(const Box &b) {
    const glm::dvec3 e = b.hi - b.lo;
    return e.x + e.y + e.z;
}

// --- Building a shape ---------------------------------------------------------------------

// The directions from which an edge between triangles t1 and t2 can be touched (see EdgeReach):
// the arc from normal n1 to normal n2, as the two half-spaces n . (turn x n1) >= 0 and
// n . (n2 x turn) >= 0 (turn: the axis about which n1 turns to n2), for normals n perpendicular
// to the edge.
MeshShape::EdgeCone arc(const glm::dvec3 &n1, const glm::dvec3 &n2) {
    const glm::dvec3 turn = glm::normalize(glm::cross(n1, n2));
    return {MeshShape::EdgeReach::bounded, glm::cross(turn, n1), glm::cross(n2, turn)};
}

MeshShape::EdgeCone manifold_cone(const MeshShape &m, uint32_t lo, uint32_t hi, uint32_t t1,
                                  uint32_t t2) {
    using Reach = MeshShape::EdgeReach;
    const glm::dvec3 &n1 = m.normals[t1], &n2 = m.normals[t2];
    if (n1 == glm::dvec3(0.0) || n2 == glm::dvec3(0.0)) return {Reach::any, {}, {}};
    auto opposite = [&](uint32_t t) {
        const auto &tri = m.triangles[t];
        for (uint32_t v : tri)
            if (v != lo && v != hi) return m.vertices[v];
        return m.vertices[tri[0]];
    };
    const glm::dvec3 &p = m.vertices[lo];
    if (glm::length(glm::cross(n1, n2)) <= flat_sine) {
        if (glm::dot(n1, n2) > 0.0) return {Reach::none, {}, {}}; // coplanar: never an edge contact
        // Two triangles back to back (a sheet modelled as a closed body of no thickness): the
        // edge is reached from the half-plane beyond it.
        glm::dvec3 out = glm::normalize(glm::cross(m.vertices[hi] - p, n1));
        if (glm::dot(out, opposite(t1) - p) > 0.0) out = -out;
        return {Reach::bounded, out, glm::dvec3(0.0)};
    }
    // Convex when t2's far corner is behind t1's plane. A concave edge of a closed body cannot be
    // met by a crossing edge before its faces are; a sheet's valley is a ridge seen from below.
    if (glm::dot(n1, opposite(t2) - p) < 0.0) return arc(n1, n2);
    if (m.closed) return {Reach::none, {}, {}};
    return arc(-n1, -n2);
}

// A sheet's boundary edge: reached from the half-plane beyond it, n . out >= 0.
MeshShape::EdgeCone boundary_cone(const MeshShape &m, uint32_t lo, uint32_t hi, uint32_t t) {
    using Reach = MeshShape::EdgeReach;
    const glm::dvec3 &n = m.normals[t];
    if (n == glm::dvec3(0.0)) return {Reach::any, {}, {}};
    const glm::dvec3 &p = m.vertices[lo];
    glm::dvec3 out = glm::normalize(glm::cross(m.vertices[hi] - p, n));
    for (uint32_t v : m.triangles[t])
        if (v != lo && v != hi && glm::dot(out, m.vertices[v] - p) > 0.0) out = -out;
    return {Reach::bounded, out, glm::dvec3(0.0)};
}

// Whether the edge can be touched with the plane of contact's normal (pointing from the edge's
// mesh outwards) equal to the unit vector n; a normal on the end of the range counts.
bool reaches(const MeshShape::EdgeCone &cone, const glm::dvec3 &n) {
    switch (cone.reach) {
    case MeshShape::EdgeReach::none:
        return false;
    case MeshShape::EdgeReach::any:
        return true;
    case MeshShape::EdgeReach::bounded:
        return glm::dot(n, cone.a) >= -flat_sine && glm::dot(n, cone.b) >= -flat_sine;
    }
    return true;
}

// A flat hierarchy by median splits along the longest axis of the triangles' centroids.
void split(MeshShape &m, const std::vector<glm::dvec3> &centroids, uint32_t node, uint32_t begin,
           uint32_t end) {
    Box box = m.triangle_boxes[m.order[begin]];
    Box spread{centroids[m.order[begin]], centroids[m.order[begin]]};
    for (uint32_t i = begin; i < end; ++i) {
        box = merged(box, m.triangle_boxes[m.order[i]]);
        spread = merged(spread, Box{centroids[m.order[i]], centroids[m.order[i]]});
    }
    m.nodes[node].box = box;
    if (end - begin <= leaf_size) {
        m.nodes[node].first = begin;
        m.nodes[node].count = end - begin;
        return;
    }
    const glm::dvec3 extent = spread.hi - spread.lo;
    const int axis =
        extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(m.order.begin() + begin, m.order.begin() + mid, m.order.begin() + end,
                     [&](uint32_t a, uint32_t b) {
                         const double ca = centroids[a][axis], cb = centroids[b][axis];
                         return ca < cb || (ca == cb && a < b);
                     });
    const auto child = static_cast<uint32_t>(m.nodes.size());
    m.nodes.emplace_back();
    m.nodes.emplace_back();
    m.nodes[node].first = child;
    m.nodes[node].count = 0;
    split(m, centroids, child, begin, mid);
    split(m, centroids, child + 1, mid, end);
}

// --- Contact of two features ---------------------------------------------------------------

// One query, in B's frame: A's features are displaced by d(t) = pa.at(t) - pb.at(t).
struct Query {
    const MeshShape &a, &b;
    glm::dvec3 d0, d1, d2; // d(t) = d0 + d1 t + d2 t^2
    Path relative;         // the same as a path
    double t_max = 0.0;
    double margin = 0.0;
    Box sweep;                               // d over [0, t_max], widened by the margin
    glm::dvec3 center_a{0.0}, center_b{0.0}; // the meshes' box centers
    glm::dvec3 displacement(double t) const { return d0 + (d1 + d2 * t) * t; }
};

Query make_query(const MeshShape &a, const Path &pa, const MeshShape &b, const Path &pb,
                 double t_max) {
    const Path relative{pa.p - pb.p, pa.v - pb.v, pa.a - pb.a};
    const Box sweep = swept_box(relative, t_max);
    double scale = 0.0;
    for (const Box &box : {a.bounds(), b.bounds(), sweep})
        for (int i = 0; i < 3; ++i)
            scale = std::max({scale, std::abs(box.lo[i]), std::abs(box.hi[i])});
    const double margin = box_margin * scale;
    return Query{a,
                 b,
                 relative.p,
                 relative.v,
                 0.5 * relative.a,
                 relative,
                 t_max,
                 margin,
                 widened(sweep, margin),
                 0.5 * (a.bounds().lo + a.bounds().hi),
                 0.5 * (b.bounds().lo + b.bounds().hi)};
}

// An interval of times in [0, t_limit] holding every moment at which A's box, displaced by d(t),
// overlaps B's (first > last when there is none). Per axis, the offset d_i(t) must lie in a
// range; the moments it does form at most two intervals, bounded by 0, t_limit and the roots of
// d_i(t) = either end, and their hull is kept; the axes' hulls are intersected. Far tighter than
// the swept box when the motion runs diagonally. Rounding is covered by the boxes' margin and a
// little time on either side (1e-6 t_limit, far above the error of a root, even a double one).
std::pair<double, double> overlap_times(const Query &q, const Box &a, const Box &b,
                                        double t_limit) {
    double first = 0.0, last = t_limit;
    const double slack = 1e-6 * t_limit;
    for (int i = 0; i < 3; ++i) {
        const double lo = b.lo[i] - a.hi[i] - q.margin, hi = b.hi[i] - a.lo[i] + q.margin;
        const double p = q.d0[i], v = q.d1[i], h = q.d2[i];
        double times[7] = {0.0, t_limit};
        int n = 2;
        auto add = [&](double t) {
            if (t > 0.0 && t < t_limit) times[n++] = t;
        };
        if (h == 0.0) {
            if (v != 0.0) {
                add((lo - p) / v);
                add((hi - p) / v);
            }
        } else {
            add(-v / (2.0 * h)); // the extreme, in case a touching root is lost to rounding
            for (double end : {lo, hi}) {
                const double disc = v * v - 4.0 * h * (p - end);
                if (disc < 0.0) continue;
                const double root = -0.5 * (v + std::copysign(std::sqrt(disc), v));
                add(root / h);
                if (root != 0.0) add((p - end) / root);
            }
        }
        double from = infinity, to = -infinity;
        for (int k = 0; k < n; ++k) {
            const double t = times[k], offset = p + (v + h * t) * t;
            if (offset >= lo - q.margin && offset <= hi + q.margin) {
                from = std::min(from, t);
                to = std::max(to, t);
            }
        }
        first = std::max(first, from - slack);
        last = std::min(last, to + slack);
        if (first > last) break;
    }
    return {first, last};
}

// Whether a feature of A (inside box_a) and one of B (inside box_b) can meet within [0, t_max]:
// the swept boxes, then the times.
bool may_meet(const Query &q, const Box &box_a, const Box &box_b) {
    if (!swept_by(box_a, q.sweep).overlaps(box_b)) return false;
    const auto [first, last] = overlap_times(q, box_a, box_b, q.t_max);
    return first <= last;
}

// The first double in [lo, hi] at which f is no longer positive, given f(lo) > 0 >= f(hi) and a
// single crossing between: the closed-form root `guess` brackets it within a few doubles, and
// bisection of that bracket finds it to the last bit (as first_contact does over the whole span,
// at a fraction of the cost).
double crossing_near(const Quartic &f, double lo, double hi, double guess) {
    guess = std::clamp(guess, lo, hi);
    double a = lo, b = hi;
    const bool past = !(evaluate(f, guess) > 0.0);
    for (double step = std::max(std::abs(guess), 1.0) * 1e-15;; step *= 2.0) {
        const double probe = past ? guess - step : guess + step;
        if (past ? probe <= lo : probe >= hi) break;
        if ((evaluate(f, probe) > 0.0) == past) {
            (past ? a : b) = probe;
            break;
        }
    }
    (past ? b : a) = guess;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (a + b);
        if (mid <= a || mid >= b) break;
        (evaluate(f, mid) > 0.0 ? a : b) = mid;
    }
    return b;
}

// The time in [0, t_max] at which f = c0 + c1 t + c2 t^2 arrives at zero from above: f > 0 just
// before, or f within `touch` of zero at t = 0 (touching, up to the rounding of where the bodies
// are) and moving in (decreasing, or at rest and accelerating in: a resting contact). A quadratic
// arrives once at most. One touching or below zero at the start and not moving in (separating,
// sliding, or behind) must first become positive, which only a concave one does, after its
// maximum.
std::optional<double> arrival(double c0, double c1, double c2, double t_max, double touch) {
    const Quartic f = {c0, c1, c2, 0.0, 0.0};
    double from = 0.0;
    if (!(c0 > touch)) {
        if (c0 >= -touch && (c1 < 0.0 || (c1 == 0.0 && c2 < 0.0))) return 0.0;
        if (!(c2 < 0.0 && c1 > 0.0)) return std::nullopt;
        from = -c1 / (2.0 * c2);
        if (!(from < t_max) || !(evaluate(f, from) > 0.0)) return std::nullopt;
    }
    // Where f is lowest over [from, t_max] (the ends, or a convex one's bottom): positive there
    // means no contact, the common case. Otherwise f falls to zero once before `to`.
    double to = t_max;
    if (evaluate(f, t_max) > 0.0) {
        const double bottom = c2 > 0.0 ? -c1 / (2.0 * c2) : from;
        if (!(bottom > from && bottom < t_max) || evaluate(f, bottom) > 0.0) return std::nullopt;
        to = bottom;
    }
    // The closed-form root on the falling side: the smaller root of a convex f, the larger of a
    // concave one (q is the numerically stable half of the formula).
    auto closed_form = [&] {
        if (c2 == 0.0) return -c0 / c1; // falling, so c1 < 0
        const double disc = std::max(c1 * c1 - 4.0 * c2 * c0, 0.0);
        const double q = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
        const double r1 = q / c2, r2 = q != 0.0 ? c0 / q : r1;
        return c2 > 0.0 ? std::min(r1, r2) : std::max(r1, r2);
    };
    const double guess = closed_form();
    return crossing_near(f, from, to, std::isfinite(guess) ? guess : from);
}

// Whether g0 + g1 t + g2 t^2 comes within `touch` of zero in [0, t_max]: not of one sign, beyond
// it, at the ends and at its extreme (the points arrival() looks at, so it never rejects what
// arrival() finds).
bool reaches_zero(double g0, double g1, double g2, double t_max, double touch) {
    const Quartic g = {g0, g1, g2, 0.0, 0.0};
    const double end = evaluate(g, t_max);
    double lo = std::min(g0, end), hi = std::max(g0, end);
    if (g2 != 0.0) {
        const double top = -g1 / (2.0 * g2);
        if (top > 0.0 && top < t_max) {
            lo = std::min(lo, evaluate(g, top));
            hi = std::max(hi, evaluate(g, top));
        }
    }
    return lo <= touch && hi >= -touch;
}

// The side from which a two-sided face (or an edge pair that could be met from either side) is
// met first, given the signed distance g0 + g1 t + g2 t^2 of the feature: the side it is on at
// t = 0; when on the plane (within `touch`: a body that has just bounced off a floor sheet may be
// a rounding error below it), the side its body is on (`body`, the signed distance of the body's
// center), failing that the side it moves to. Zero when it stays in the plane.
double side_of(double g0, double body, double g1, double g2, double touch) {
    if (std::abs(g0) > touch) return g0 > 0.0 ? 1.0 : -1.0;
    for (double g : {body, g1, g2})
        if (g != 0.0) return g > 0.0 ? 1.0 : -1.0;
    return 0.0;
}

enum class Kind : uint8_t { vertex_face = 0, face_vertex = 1, edge_edge = 2 }; // the preference

struct Candidate {
    double t = 0.0;
    Kind kind = Kind::vertex_face;
    uint32_t feature_a = 0, feature_b = 0;
    glm::dvec3 normal{0.0}; // from B towards A

    // The preference among simultaneous contacts: a face normal first, then the earliest, then
    // the lowest features, so that the answer does not depend on the order of the tests.
    bool preferred_to(const Candidate &o) const {
        if (kind != o.kind) return kind < o.kind;
        if (t != o.t) return t < o.t;
        if (feature_a != o.feature_a) return feature_a < o.feature_a;
        return feature_b < o.feature_b;
    }
};

// The vertices of a contact's feature (a vertex, an edge's ends or a face's corners), in a
// small fixed array.
struct Corners {
    uint32_t index[3] = {0, 0, 0};
    int count = 0;
};

// Whether the bodies, touching at p (in B's frame) at time t through the features `fa` of A and
// `fb` of B, are also parted there by the plane of a face around either feature that the motion
// does not approach: then it is a touch in passing, not a collision. Both meshes must lie on
// their sides of the plane around the features (their vertices and the vertices next to them).
bool sliding_past(const Query &q, double t, const glm::dvec3 &p, const Corners &fa,
                  const Corners &fb) {
    const glm::dvec3 d = q.displacement(t), velocity = q.d1 + 2.0 * q.d2 * t;
    const double still = 1e-12 * glm::length(velocity);
    // Whether the mesh (moved by `shift`) lies on the side of the plane through p that `m`
    // points to (or away from, for `sign` -1), around the feature.
    auto beside = [&](const MeshShape &mesh, const Corners &f, const glm::dvec3 &shift,
                      const glm::dvec3 &m, double sign) {
        auto fits = [&](uint32_t w) {
            const glm::dvec3 along = (mesh.vertices[w] + shift) - p;
            return sign * glm::dot(m, along) >= -(flat_sine * glm::length(along) + q.margin);
        };
        for (int k = 0; k < f.count; ++k) {
            const uint32_t v = f.index[k];
            if (!fits(v)) return false;
            for (uint32_t i = mesh.neighbor_begin[v]; i < mesh.neighbor_begin[v + 1]; ++i)
                if (!fits(mesh.neighbors[i])) return false;
        }
        return true;
    };
    // m points from B towards A; the plane is a face's (of B, or of A reversed) through p.
    auto parts = [&](const glm::dvec3 &m, const glm::dvec3 &on_plane) {
        if (m == glm::dvec3(0.0) || std::abs(glm::dot(m, p - on_plane)) > q.margin) return false;
        const double closing = glm::dot(m, velocity);
        if (closing < -still || (closing <= still && glm::dot(m, 2.0 * q.d2) < 0.0)) return false;
        return beside(q.a, fa, d, m, 1.0) && beside(q.b, fb, glm::dvec3(0.0), m, -1.0);
    };
    for (int k = 0; k < fb.count; ++k) {
        const uint32_t v = fb.index[k];
        for (uint32_t i = q.b.fan_begin[v]; i < q.b.fan_begin[v + 1]; ++i) {
            const uint32_t tri = q.b.fan[i];
            if (parts(q.b.normals[tri], q.b.vertices[q.b.triangles[tri][0]])) return true;
        }
    }
    for (int k = 0; k < fa.count; ++k) {
        const uint32_t v = fa.index[k];
        for (uint32_t i = q.a.fan_begin[v]; i < q.a.fan_begin[v + 1]; ++i) {
            const uint32_t tri = q.a.fan[i];
            if (parts(-q.a.normals[tri], q.a.vertices[q.a.triangles[tri][0]] + d)) return true;
        }
    }
    return false;
}

// Vertex `v` of `mesh` against triangle `tri` of `face_mesh`: the vertex moves by sign d(t) in the
// face's frame (A's by +d, B's by -d). The time and the side of the face (+1 for its front) that
// the vertex meets.
std::optional<std::pair<double, double>> vertex_triangle(const Query &q, const MeshShape &mesh,
                                                         uint32_t v, const glm::dvec3 &center,
                                                         double sign, const MeshShape &face_mesh,
                                                         uint32_t tri) {
    const glm::dvec3 &x = mesh.vertices[v];
    const glm::dvec3 &n = face_mesh.normals[tri];
    if (n == glm::dvec3(0.0)) return std::nullopt;
    const auto &corners = face_mesh.triangles[tri];
    const glm::dvec3 &y0 = face_mesh.vertices[corners[0]];
    // The signed distance to the plane, n . (x + sign d(t) - y0), a quadratic.
    const double g0 = glm::dot(n, (x - y0) + sign * q.d0), g1 = sign * glm::dot(n, q.d1),
                 g2 = sign * glm::dot(n, q.d2);
    auto meet = [&](double side) -> std::optional<double> {
        // The vertex can only meet the face first if its mesh lies on the face's side of the
        // plane around it: every edge from it points away from the face (or along it). One that
        // points through the plane means the vertex is passing the face's rim (sliding off a
        // ledge, or a floor's vertex gliding under a box); the contact, if any, is another pair's.
        for (uint32_t i = mesh.neighbor_begin[v]; i < mesh.neighbor_begin[v + 1]; ++i) {
            const glm::dvec3 along = mesh.vertices[mesh.neighbors[i]] - x;
            if (side * glm::dot(n, along) < -flat_sine * glm::length(along)) return std::nullopt;
        }
        const auto t = arrival(side * g0, side * g1, side * g2, q.t_max, q.margin);
        if (!t) return std::nullopt;
        // The seed's inside test, inclusive: on the inner side of (or on) all three edges.
        const glm::dvec3 p = x + sign * q.displacement(*t);
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3 &c = face_mesh.vertices[corners[static_cast<size_t>(k)]];
            const glm::dvec3 &d = face_mesh.vertices[corners[static_cast<size_t>((k + 1) % 3)]];
            if (glm::dot(n, glm::cross(d - c, p - c)) < 0.0) return std::nullopt;
        }
        return t;
    };
    if (face_mesh.closed) {
        if (const auto t = meet(1.0)) return std::make_pair(*t, 1.0);
        return std::nullopt;
    }
    // A two-sided face: first from the side the vertex starts on; then, if it passed the plane
    // beside the triangle, from the other side on its way back (never at 0: that is leaving).
    const double side = side_of(g0, glm::dot(n, (center - y0) + sign * q.d0), g1, g2, q.margin);
    if (side == 0.0) return std::nullopt;
    if (const auto t = meet(side)) return std::make_pair(*t, side);
    if (const auto t = meet(-side); t && *t > 0.0) return std::make_pair(*t, -side);
    return std::nullopt;
}

std::optional<Candidate> vertex_face(const Query &q, uint32_t vertex, uint32_t tri) {
    const glm::dvec3 &x = q.a.vertices[vertex];
    if (!may_meet(q, Box{x, x}, q.b.triangle_boxes[tri])) return std::nullopt;
    const auto hit = vertex_triangle(q, q.a, vertex, q.center_a, 1.0, q.b, tri);
    if (!hit) return std::nullopt;
    const auto &corners = q.b.triangles[tri];
    if (sliding_past(q, hit->first, x + q.displacement(hit->first), Corners{{vertex, 0, 0}, 1},
                     Corners{{corners[0], corners[1], corners[2]}, 3}))
        return std::nullopt;
    return Candidate{hit->first, Kind::vertex_face, vertex, tri, hit->second * q.b.normals[tri]};
}

std::optional<Candidate> face_vertex(const Query &q, uint32_t tri, uint32_t vertex) {
    const glm::dvec3 &y = q.b.vertices[vertex];
    if (!may_meet(q, q.a.triangle_boxes[tri], Box{y, y})) return std::nullopt;
    // B's vertex meets A's face from the face's side `side`, so B is on that side of A and the
    // normal from B towards A is the opposite.
    const auto hit = vertex_triangle(q, q.b, vertex, q.center_b, -1.0, q.a, tri);
    if (!hit) return std::nullopt;
    const auto &corners = q.a.triangles[tri];
    if (sliding_past(q, hit->first, y, Corners{{corners[0], corners[1], corners[2]}, 3},
                     Corners{{vertex, 0, 0}, 1}))
        return std::nullopt;
    return Candidate{hit->first, Kind::face_vertex, tri, vertex, -hit->second * q.a.normals[tri]};
}

// Where the lines a0 + s ea and b0 + u eb (c = ea x eb, w = a0 - b0) cross: s and u.
std::pair<double, double> crossing(const glm::dvec3 &ea, const glm::dvec3 &eb, const glm::dvec3 &c,
                                   const glm::dvec3 &w) {
    const double cc = glm::dot(c, c);
    return {glm::dot(glm::cross(eb, w), c) / cc, glm::dot(glm::cross(ea, w), c) / cc};
}

std::optional<Candidate> edge_edge(const Query &q, uint32_t edge_a, uint32_t edge_b) {
    const MeshShape::EdgeCone &cone_a = q.a.edge_cones[edge_a], &cone_b = q.b.edge_cones[edge_b];
    if (cone_a.reach == MeshShape::EdgeReach::none || cone_b.reach == MeshShape::EdgeReach::none)
        return std::nullopt;
    if (!may_meet(q, q.a.edge_boxes[edge_a], q.b.edge_boxes[edge_b])) return std::nullopt;
    const auto &ia = q.a.edges[edge_a], &ib = q.b.edges[edge_b];
    const glm::dvec3 &a0 = q.a.vertices[ia[0]], &b0 = q.b.vertices[ib[0]];
    const glm::dvec3 ea = q.a.vertices[ia[1]] - a0, eb = q.b.vertices[ib[1]] - b0;
    const glm::dvec3 c = glm::cross(ea, eb);
    const double cc = glm::dot(c, c);
    if (!(cc > parallel_sine * parallel_sine * glm::dot(ea, ea) * glm::dot(eb, eb)))
        return std::nullopt;
    // The signed distance between the lines along c, c . (a0 + d(t) - b0), a quadratic: it must
    // reach zero for the edges to meet (the common rejection, before the cones).
    const double g0 = glm::dot(c, (a0 - b0) + q.d0), g1 = glm::dot(c, q.d1), g2 = glm::dot(c, q.d2);
    const double length = std::sqrt(cc), touch = q.margin * length; // g is a distance times |c|
    if (!reaches_zero(g0, g1, g2, q.t_max, touch)) return std::nullopt;
    // The orientations (n pointing from B towards A) that let both edges be touched.
    const glm::dvec3 n = c / length;
    auto possible = [&](double s) { return reaches(cone_b, s * n) && reaches(cone_a, -s * n); };
    const bool plus = possible(1.0), minus = possible(-1.0);
    if (!plus && !minus) return std::nullopt;
    auto meet = [&](double side) -> std::optional<Candidate> {
        const auto t = arrival(side * g0, side * g1, side * g2, q.t_max, touch);
        if (!t) return std::nullopt;
        const auto [s, u] = crossing(ea, eb, c, (a0 - b0) + q.displacement(*t));
        if (!(s >= 0.0 && s <= 1.0 && u >= 0.0 && u <= 1.0)) return std::nullopt;
        if (sliding_past(q, *t, b0 + u * eb, Corners{{ia[0], ia[1], 0}, 2},
                         Corners{{ib[0], ib[1], 0}, 2}))
            return std::nullopt;
        return Candidate{*t, Kind::edge_edge, edge_a, edge_b, side * n};
    };
    if (plus != minus) return meet(plus ? 1.0 : -1.0);
    // Either side (edges of sheets, or of non-manifold meshes): as for a two-sided face, first
    // from the side A's edge starts on, then from the other on its way back.
    const double side = side_of(g0, glm::dot(c, (q.center_a + q.d0) - q.center_b), g1, g2, touch);
    if (side == 0.0) return std::nullopt;
    if (auto first = meet(side)) return first;
    if (auto back = meet(-side); back && back->t > 0.0) return back;
    return std::nullopt;
}

// The contacts that can still be the answer: those within the simultaneous window of the
// earliest found so far.
class Earliest {
  public:
    explicit Earliest(double window) : window_(window) {}

    void offer(const std::optional<Candidate> &c) {
        if (!c || c->t > limit()) return;
        if (found_.empty() || c->t < earliest_) {
            earliest_ = c->t;
            found_.erase(
                std::remove_if(found_.begin(), found_.end(),
                               [&](const Candidate &o) { return o.t > earliest_ + window_; }),
                found_.end());
        }
        found_.push_back(*c);
    }
    // No contact later than this can change the answer.
    double limit() const { return found_.empty() ? infinity : earliest_ + window_; }
    double earliest() const { return earliest_; }
    const Candidate *best() const {
        const Candidate *best = nullptr;
        for (const Candidate &c : found_)
            if (!best || c.preferred_to(*best)) best = &c;
        return best;
    }

  private:
    double window_;
    double earliest_ = infinity;
    std::vector<Candidate> found_;
};

std::optional<Contact> answer(const Query &q, const Path &pa, const Path &pb,
                              const Earliest &found) {
    const Candidate *best = found.best();
    if (!best) return std::nullopt;
    Contact contact;
    contact.t = found.earliest();
    contact.normal = best->normal;
    const double t = contact.t;
    switch (best->kind) {
    case Kind::vertex_face:
        contact.point = pa.at(t) + q.a.vertices[best->feature_a];
        break;
    case Kind::face_vertex:
        contact.point = pb.at(t) + q.b.vertices[best->feature_b];
        break;
    case Kind::edge_edge: {
        const auto &ia = q.a.edges[best->feature_a], &ib = q.b.edges[best->feature_b];
        const glm::dvec3 &a0 = q.a.vertices[ia[0]], &b0 = q.b.vertices[ib[0]];
        const glm::dvec3 ea = q.a.vertices[ia[1]] - a0, eb = q.b.vertices[ib[1]] - b0;
        const double u = std::clamp(
            crossing(ea, eb, glm::cross(ea, eb), (a0 - b0) + q.displacement(t)).second, 0.0, 1.0);
        contact.point = pb.at(t) + b0 + u * eb;
        break;
    }
    }
    return contact;
}

} // namespace

MeshShape MeshShape::build(std::vector<glm::dvec3> vertices,
                           std::vector<std::array<uint32_t, 3>> triangles) {
    MeshShape m;
    m.vertices = std::move(vertices);
    m.triangles = std::move(triangles);
    const auto nt = static_cast<uint32_t>(m.triangles.size());
    for (const auto &tri : m.triangles)
        for (uint32_t v : tri)
            if (v >= m.vertices.size())
                throw std::invalid_argument("mesh: a triangle's vertex index is out of range");

    // The unique edges, from the triangles' sides sorted by their endpoints.
    struct Side {
        uint32_t lo, hi, triangle, k;
        bool forward; // the triangle runs from lo to hi
    };
    std::vector<Side> sides;
    sides.reserve(3 * static_cast<size_t>(nt));
    for (uint32_t t = 0; t < nt; ++t)
        for (uint32_t k = 0; k < 3; ++k) {
            const uint32_t p = m.triangles[t][k], q = m.triangles[t][(k + 1) % 3];
            if (p != q) sides.push_back({std::min(p, q), std::max(p, q), t, k, p < q});
        }
    std::sort(sides.begin(), sides.end(), [](const Side &x, const Side &y) {
        return std::tie(x.lo, x.hi, x.triangle, x.k) < std::tie(y.lo, y.hi, y.triangle, y.k);
    });
    std::vector<std::array<uint32_t, 3>> triangle_edges(nt, {no_edge, no_edge, no_edge});
    std::vector<std::pair<size_t, size_t>> groups; // each edge's run of sides
    for (size_t i = 0; i < sides.size();) {
        size_t j = i;
        while (j < sides.size() && sides[j].lo == sides[i].lo && sides[j].hi == sides[i].hi) ++j;
        const auto edge = static_cast<uint32_t>(m.edges.size());
        m.edges.push_back({sides[i].lo, sides[i].hi});
        for (size_t k = i; k < j; ++k) triangle_edges[sides[k].triangle][sides[k].k] = edge;
        groups.emplace_back(i, j);
        i = j;
    }
    auto manifold = [&](const std::pair<size_t, size_t> &g) {
        return g.second - g.first == 2 && sides[g.first].forward != sides[g.first + 1].forward;
    };
    m.closed = nt > 0 && std::all_of(groups.begin(), groups.end(), manifold);
    m.normals.resize(nt);
    m.triangle_boxes.resize(nt);
    std::vector<glm::dvec3> centroids(nt);
    for (uint32_t t = 0; t < nt; ++t) {
        const glm::dvec3 &p0 = m.vertices[m.triangles[t][0]], &p1 = m.vertices[m.triangles[t][1]],
                         &p2 = m.vertices[m.triangles[t][2]];
        const glm::dvec3 n = glm::cross(p1 - p0, p2 - p0);
        const double length = glm::length(n);
        m.normals[t] = length > 0.0 ? n / length : glm::dvec3(0.0);
        m.triangle_boxes[t] = merged(box_around(p0, p1), Box{p2, p2});
        centroids[t] = (p0 + p1 + p2) / 3.0;
    }

    m.edge_cones.resize(m.edges.size());
    m.edge_boxes.resize(m.edges.size());
    for (size_t e = 0; e < m.edges.size(); ++e) {
        const auto [i, j] = groups[e];
        const uint32_t lo = m.edges[e][0], hi = m.edges[e][1];
        if (manifold(groups[e]))
            m.edge_cones[e] = manifold_cone(m, lo, hi, sides[i].triangle, sides[i + 1].triangle);
        else if (j - i == 1)
            m.edge_cones[e] = boundary_cone(m, lo, hi, sides[i].triangle);
        m.edge_boxes[e] = box_around(m.vertices[lo], m.vertices[hi]);
    }

    // Each vertex's neighbours along edges.
    m.neighbor_begin.assign(m.vertices.size() + 1, 0);
    for (const auto &e : m.edges) {
        ++m.neighbor_begin[e[0] + 1];
        ++m.neighbor_begin[e[1] + 1];
    }
    std::partial_sum(m.neighbor_begin.begin(), m.neighbor_begin.end(), m.neighbor_begin.begin());
    m.neighbors.resize(2 * m.edges.size());
    std::vector<uint32_t> filled(m.neighbor_begin.begin(), m.neighbor_begin.end() - 1);
    for (const auto &e : m.edges) {
        m.neighbors[filled[e[0]]++] = e[1];
        m.neighbors[filled[e[1]]++] = e[0];
    }

    m.fan_begin.assign(m.vertices.size() + 1, 0);
    for (const auto &t : m.triangles)
        for (uint32_t v : t) ++m.fan_begin[v + 1];
    std::partial_sum(m.fan_begin.begin(), m.fan_begin.end(), m.fan_begin.begin());
    m.fan.resize(3 * static_cast<size_t>(nt));
    filled.assign(m.fan_begin.begin(), m.fan_begin.end() - 1);
    for (uint32_t t = 0; t < nt; ++t)
        for (uint32_t v : m.triangles[t]) m.fan[filled[v]++] = t;

    if (nt == 0) return m;
    m.order.resize(nt);
    std::iota(m.order.begin(), m.order.end(), 0u);
    m.nodes.reserve(2 * (size_t{nt} / leaf_size + 1));
    m.nodes.emplace_back();
    split(m, centroids, 0, 0, nt);

    // Each vertex and edge goes to the first leaf that references it.
    std::vector<bool> vertex_taken(m.vertices.size(), false), edge_taken(m.edges.size(), false);
    for (Node &node : m.nodes) {
        if (!node.leaf()) continue;
        node.vertex_begin = static_cast<uint32_t>(m.owned_vertices.size());
        node.edge_begin = static_cast<uint32_t>(m.owned_edges.size());
        for (uint32_t i = node.first; i < node.first + node.count; ++i) {
            const uint32_t t = m.order[i];
            for (uint32_t k = 0; k < 3; ++k) {
                const uint32_t v = m.triangles[t][k], e = triangle_edges[t][k];
                if (!vertex_taken[v]) {
                    vertex_taken[v] = true;
                    m.owned_vertices.push_back(v);
                }
                if (e != no_edge && !edge_taken[e]) {
                    edge_taken[e] = true;
                    m.owned_edges.push_back(e);
                }
            }
        }
        node.vertex_end = static_cast<uint32_t>(m.owned_vertices.size());
        node.edge_end = static_cast<uint32_t>(m.owned_edges.size());
    }
    return m;
}

Box MeshShape::bounds() const {
    return nodes.empty() ? Box{} : nodes[0].box;
}

std::optional<Contact> mesh_mesh(const MeshShape &a, const Path &pa, const MeshShape &b,
                                 const Path &pb, double t_max, PairStats *stats) {
    if (stats) *stats = PairStats{};
    if (!(t_max >= 0.0) || a.nodes.empty() || b.nodes.empty()) return std::nullopt;
    const Query q = make_query(a, pa, b, pb, t_max);
    Earliest found(simultaneous * t_max);
    PairStats counted;

    // The sweep over [0, limit], narrowed as contacts are found.
    double limit = t_max;
    Box sweep = q.sweep;
    auto overlapping = [&](uint32_t na, uint32_t nb) {
        return swept_by(a.nodes[na].box, sweep).overlaps(b.nodes[nb].box);
    };
    // When the boxes can overlap: the first moment orders the visits.
    auto meeting = [&](uint32_t na, uint32_t nb) {
        const auto [first, last] = overlap_times(q, a.nodes[na].box, b.nodes[nb].box, limit);
        return first <= last ? std::optional<double>(first) : std::nullopt;
    };

    // Best first: the node pairs whose boxes can meet earliest are opened first, so that the
    // limit shrinks early.
    struct Visit {
        double key;
        uint32_t na, nb;
        bool operator>(const Visit &o) const {
            return std::tie(key, na, nb) > std::tie(o.key, o.na, o.nb);
        }
    };
    std::priority_queue<Visit, std::vector<Visit>, std::greater<>> queue;
    auto push = [&](uint32_t na, uint32_t nb) {
        if (!overlapping(na, nb)) return;
        if (const auto first = meeting(na, nb)) queue.push({*first, na, nb});
    };
    push(0, 0);
    while (!queue.empty()) {
        const Visit visit = queue.top();
        queue.pop();
        if (visit.key > limit || !overlapping(visit.na, visit.nb)) continue; // the limit shrank
        ++counted.nodes_visited;
        const MeshShape::Node &na = a.nodes[visit.na], &nb = b.nodes[visit.nb];
        if (na.leaf() && nb.leaf()) {
            for (uint32_t i = na.vertex_begin; i < na.vertex_end; ++i)
                for (uint32_t j = nb.first; j < nb.first + nb.count; ++j)
                    found.offer(vertex_face(q, a.owned_vertices[i], b.order[j]));
            for (uint32_t i = na.first; i < na.first + na.count; ++i)
                for (uint32_t j = nb.vertex_begin; j < nb.vertex_end; ++j)
                    found.offer(face_vertex(q, a.order[i], b.owned_vertices[j]));
            for (uint32_t i = na.edge_begin; i < na.edge_end; ++i)
                for (uint32_t j = nb.edge_begin; j < nb.edge_end; ++j)
                    found.offer(edge_edge(q, a.owned_edges[i], b.owned_edges[j]));
            counted.primitive_tests +=
                uint64_t{na.vertex_end - na.vertex_begin} * nb.count +
                uint64_t{na.count} * (nb.vertex_end - nb.vertex_begin) +
                uint64_t{na.edge_end - na.edge_begin} * (nb.edge_end - nb.edge_begin);
            if (found.limit() < limit) {
                limit = found.limit();
                sweep = widened(swept_box(q.relative, limit), q.margin);
            }
            continue;
        }
        // Open the larger node (or the one that is not a leaf).
        if (!na.leaf() && (nb.leaf() || size_of(na.box) >= size_of(nb.box))) {
            push(na.first, visit.nb);
            push(na.first + 1, visit.nb);
        } else {
            push(visit.na, nb.first);
            push(visit.na, nb.first + 1);
        }
    }
    if (stats) *stats = counted;
    return answer(q, pa, pb, found);
}

std::optional<Contact> mesh_mesh_brute(const MeshShape &a, const Path &pa, const MeshShape &b,
                                       const Path &pb, double t_max, PairStats *stats) {
    if (stats) *stats = PairStats{};
    if (!(t_max >= 0.0) || a.nodes.empty() || b.nodes.empty()) return std::nullopt;
    const Query q = make_query(a, pa, b, pb, t_max);
    Earliest found(simultaneous * t_max);
    const auto ta = static_cast<uint32_t>(a.triangles.size()),
               tb = static_cast<uint32_t>(b.triangles.size());
    const auto ea = static_cast<uint32_t>(a.edges.size()),
               eb = static_cast<uint32_t>(b.edges.size());
    for (uint32_t v : a.owned_vertices)
        for (uint32_t t = 0; t < tb; ++t) found.offer(vertex_face(q, v, t));
    for (uint32_t t = 0; t < ta; ++t)
        for (uint32_t v : b.owned_vertices) found.offer(face_vertex(q, t, v));
    for (uint32_t i = 0; i < ea; ++i)
        for (uint32_t j = 0; j < eb; ++j) found.offer(edge_edge(q, i, j));
    if (stats)
        stats->primitive_tests = uint64_t{a.owned_vertices.size()} * tb +
                                 uint64_t{ta} * b.owned_vertices.size() + uint64_t{ea} * eb;
    return answer(q, pa, pb, found);
}

} // namespace physics_custom
