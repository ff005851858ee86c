#include "turning_contact.hpp"

#include "mesh_distance.hpp"
#include "time_of_impact.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace physics_custom {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

double radius_of(const TurningMesh &mesh) {
    double r = 0.0;
    for (std::size_t i = 0; i < mesh.vertex_count; ++i)
        r = std::max(r, glm::length(mesh.vertices[i]));
    return r;
}

// The first s > 0 at which the closing bound D(s) = beta s + alpha s^2 / 2 reaches the gap g > 0
// (infinite if it never does): the smaller positive root, in the form without cancellation.
double first_reach(double g, double beta, double alpha) {
    if (beta > 0.0) {
        const double disc = beta * beta + 2.0 * alpha * g;
        if (disc < 0.0) return kInf;
        return 2.0 * g / (beta + std::sqrt(disc));
    }
    if (alpha > 0.0) {
        const double disc = beta * beta + 2.0 * alpha * g;
        return (-beta + std::sqrt(disc)) / alpha;
    }
    return kInf;
}

// The plane's gap: min over vertices of n . x_i(t) - d, and the vertex that attains it.
double plane_gap(const TurningMesh &mesh, const TurningPath &path, const StaticPlane &plane,
                 double t, std::size_t &lowest) {
    double best = kInf;
    const glm::dvec3 c = path.center(t);
    const glm::dquat q = path.orientation(t);
    for (std::size_t i = 0; i < mesh.vertex_count; ++i) {
        const double h = glm::dot(plane.n, c + q * mesh.vertices[i]) - plane.d;
        if (h < best) {
            best = h;
            lowest = i;
        }
    }
    return best;
}

// A bound of how far the plane's gap can close from t within s: every point's height changes at
// -n . c'(t + s) - n . (w x r), and n . (w x r) = r . (n x w) >= -|n x w| r_max, so it closes by
// at most D(s) = (u0 + rho) s + alpha s^2 / 2 with u0 = -n . c'(t), alpha = -n . a (Mirtich's
// directional bound, integrated over the step rather than taken at its worst).
double plane_step(const TurningPath &path, const StaticPlane &plane, double rho, double t,
                  double g) {
    const double u0 = -glm::dot(plane.n, path.velocity(t));
    const double alpha = -glm::dot(plane.n, path.a);
    return first_reach(g, u0 + rho, alpha);
}

// A mesh's vertices at t: world positions, velocities, and distances from the centre of mass.
struct Moving {
    std::vector<glm::dvec3> x, v;
    std::vector<double> r;
};

void place_moving(const TurningMesh &mesh, const TurningPath &path, double t, Moving &out) {
    out.x.resize(mesh.vertex_count);
    out.v.resize(mesh.vertex_count);
    out.r.resize(mesh.vertex_count);
    const glm::dvec3 c = path.center(t), cv = path.velocity(t);
    const glm::dquat q = path.orientation(t);
    const glm::dvec3 spin = path.angular_velocity(t);
    for (std::size_t i = 0; i < mesh.vertex_count; ++i) {
        const glm::dvec3 r = q * mesh.vertices[i];
        out.x[i] = c + r;
        out.v[i] = cv + glm::cross(spin, r);
        out.r[i] = glm::length(mesh.vertices[i]);
    }
}

// The second-order (Taylor model) bound of Zhang et al.: a point's height n . x(t + s) has
// derivative n . x' now and second derivative n . a + (n x w) . (w x r) >= n . a - |n x w| |w| |r|
// everywhere, so it stays above h + h' s + m s^2 / 2; the first root of that lower bound is safe.
double taylor_reach(double h, double rate, double m) {
    if (!(h > 0.0)) return 0.0;
    return first_reach(h, -rate, -m);
}

// The plane's safe step from the Taylor bound of every vertex.
double plane_taylor_step(const TurningMesh &mesh, const TurningPath &path, const StaticPlane &plane,
                         double t) {
    Moving m;
    place_moving(mesh, path, t, m);
    const double turn = path.turn_curving(plane.n);
    const double na = glm::dot(plane.n, path.a);
    double step = kInf;
    for (std::size_t i = 0; i < mesh.vertex_count; ++i)
        step = std::min(step, taylor_reach(glm::dot(plane.n, m.x[i]) - plane.d,
                                           glm::dot(plane.n, m.v[i]), na - turn * m.r[i]));
    return step;
}

// Of the unit directions c / |c| and -c / |c|, the one along which `apart` (how far two shapes
// are apart along a unit direction) is largest, kept in best when larger than widest. A zero c
// offers nothing.
template <class Apart>
void offer_direction(const glm::dvec3 &c, const Apart &apart, double &widest, glm::dvec3 &best) {
    const double len = glm::length(c);
    if (!(len > 0.0)) return;
    for (double sign : {1.0, -1.0}) {
        const glm::dvec3 m = c * (sign / len);
        const double d = apart(m);
        if (d > widest) {
            widest = d;
            best = m;
        }
    }
}

// The bounds of a path's turn over all time: |w| <= spin, |w'| <= spin_rate.
void turn_bounds(const TurningPath &path, double &spin, double &spin_rate) {
    spin = path.turn ? path.w_bound : glm::length(path.w);
    spin_rate = path.turn ? path.w_rate_bound : 0.0;
}

// The safe step from a plane that turns with one body, F: through its point x0 (a corner of
// F's triangle) with unit normal n now, F's triangle on its side n . (x - x0) <= 0 (the caller
// makes sure: the plane of F's face, or through an edge of F's triangle and across an edge of
// the other's, F's third corner below it), and turning with F that triangle stays there. While
// every corner of the other triangle o (of O on path po) stays above it, they do not touch.
// That follows a contact about which F turns (a cube's face or edge tipping over a step's nose,
// the other's edge touching it inside), where a fixed direction closes at F's far corners
// however slowly the touching points meet (Mirtich's bound and the fixed-direction Taylor bound
// crawl there).
//
// For a corner y of o, h(t) = n(t) . (y(t) - x0(t)) has h' = (w x n) . p + n . p' and
// |h''| <= (|w'| + |w|^2) |p| + 2 |w| |p'| + |p''|, p = y - x0; over a window of length S,
// |p''| <= P2 (the centres' relative acceleration and each turn's (|w'| + |w|^2) r),
// |p'| <= |p'(t)| + P2 S and |p| <= |p(t)| + |p'(t)| S + P2 S^2 / 2. The first root of
// h + h' s - M s^2 / 2 within S is safe; a few windows are tried, the best kept.
double turning_plane_step(const Moving &F, uint32_t x0_index, const TurningPath &pf,
                          const glm::dvec3 &n, const Moving &O, const uint32_t *o,
                          const TurningPath &po, double t) {
    const glm::dvec3 x0 = F.x[x0_index];
    for (int j = 0; j < 3; ++j)
        if (!(glm::dot(n, O.x[o[j]] - x0) > 0.0)) return 0.0; // it does not separate them now
    double wf = 0.0, wf_rate = 0.0, wo = 0.0, wo_rate = 0.0;
    turn_bounds(pf, wf, wf_rate);
    turn_bounds(po, wo, wo_rate);
    const glm::dvec3 turning_n = glm::cross(pf.angular_velocity(t), n);
    const double centres = glm::length(pf.a - po.a);
    double best = 0.0;
    for (double window : {1e-5, 1e-3, 1e-1}) {
        double step = window;
        for (int j = 0; j < 3 && step > 0.0; ++j) {
            const glm::dvec3 p = O.x[o[j]] - x0, dp = O.v[o[j]] - F.v[x0_index];
            const double h = glm::dot(n, p);
            const double rate = glm::dot(turning_n, p) + glm::dot(n, dp);
            const double p2 =
                centres + (wf_rate + wf * wf) * F.r[x0_index] + (wo_rate + wo * wo) * O.r[o[j]];
            const double p1 = glm::length(dp) + p2 * window;
            const double p0 =
                glm::length(p) + glm::length(dp) * window + 0.5 * p2 * window * window;
            const double m = (wf_rate + wf * wf) * p0 + 2.0 * wf * p1 + p2;
            step = std::min(step, taylor_reach(h, rate, -m));
        }
        best = std::max(best, step);
    }
    return best;
}

// turning_plane_step from the plane of F's triangle f, turned towards o.
double turning_face_step(const Moving &F, const uint32_t *f, const TurningPath &pf, const Moving &O,
                         const uint32_t *o, const TurningPath &po, double t) {
    const glm::dvec3 x0 = F.x[f[0]];
    const glm::dvec3 n = glm::cross(F.x[f[1]] - x0, F.x[f[2]] - x0);
    const double len = glm::length(n);
    if (!(len > 0.0)) return 0.0;
    const double side = glm::dot(n, O.x[o[0]] - x0) > 0.0 ? 1.0 : -1.0;
    return turning_plane_step(F, f[0], pf, n * (side / len), O, o, po, t);
}

// The safe step of one triangle of a against one of b (conservative advancement on convex
// pieces, as C2A does on a polygon soup). Nearest points pa, pb at distance d apart, n from pb
// to pa: the plane through them with normal n separates the two triangles (both convex), and the
// gap between them is at least min over vertex pairs of n . (x_i - z_j), each of which is bounded
// below both by the first-order directional bound (Mirtich) and by the Taylor bound; the larger
// of the two safe steps is safe. Both use the gap between the triangles' slabs along n measured
// from their vertices, not d: that holds for any direction n, so a direction spoilt by rounding
// when d is tiny gives a small step, never a step past the contact. `gap` receives d, `normal`
// the direction used (from b towards a).
double pair_step(const Moving &A, const uint32_t *ta, const TurningPath &pa_path, const Moving &B,
                 const uint32_t *tb, const TurningPath &pb_path, double t, double &gap,
                 glm::dvec3 *normal) {
    const glm::dvec3 a[3] = {A.x[ta[0]], A.x[ta[1]], A.x[ta[2]]};
    const glm::dvec3 b[3] = {B.x[tb[0]], B.x[tb[1]], B.x[tb[2]]};
    double d = kInf;
    glm::dvec3 on_a(0.0), on_b(0.0);
    glm::dvec3 edge_cross(0.0);
    auto offer = [&](const glm::dvec3 &x, const glm::dvec3 &y, const glm::dvec3 &cross) {
        const double len = glm::length(x - y);
        if (len < d) {
            d = len;
            on_a = x;
            on_b = y;
            edge_cross = cross;
        }
    };
    for (int i = 0; i < 3; ++i) {
        offer(a[i], closest_point_on_triangle(a[i], b[0], b[1], b[2]), glm::dvec3(0.0));
        offer(closest_point_on_triangle(b[i], a[0], a[1], a[2]), b[i], glm::dvec3(0.0));
        for (int j = 0; j < 3; ++j) {
            glm::dvec3 x, y;
            closest_on_segments(a[i], a[(i + 1) % 3], b[j], b[(j + 1) % 3], x, y);
            offer(x, y, glm::cross(a[(i + 1) % 3] - a[i], b[(j + 1) % 3] - b[j]));
        }
    }
    gap = d;
    // The direction: of the line between the nearest points, the two faces' normals and the
    // nearest edges' cross product (either sign), the one whose slabs are furthest apart. Near a
    // touch the line between the points is lost to rounding, the features' normals are not.
    auto slab_along = [&](const glm::dvec3 &m) {
        double least = kInf;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) least = std::min(least, glm::dot(m, a[i] - b[j]));
        return least;
    };
    const glm::dvec3 candidates[4] = {on_a - on_b, glm::cross(a[1] - a[0], a[2] - a[0]),
                                      glm::cross(b[1] - b[0], b[2] - b[0]), edge_cross};
    glm::dvec3 n(0.0);
    double slab = -kInf;
    for (const glm::dvec3 &c : candidates) offer_direction(c, slab_along, slab, n);
    if (normal) *normal = n;
    if (!(d > 0.0) || !(slab > 0.0)) return 0.0;
    const double turn_a = pa_path.turn_across(n), turn_b = pb_path.turn_across(n);
    const double spin_a = pa_path.turn_curving(n), spin_b = pb_path.turn_curving(n);
    const double na = glm::dot(n, pa_path.a - pb_path.a);
    double ra = 0.0, rb = 0.0, second = kInf;
    for (int i = 0; i < 3; ++i) {
        ra = std::max(ra, A.r[ta[i]]);
        rb = std::max(rb, B.r[tb[i]]);
        for (int j = 0; j < 3; ++j)
            second = std::min(second, taylor_reach(glm::dot(n, a[i] - b[j]),
                                                   glm::dot(n, A.v[ta[i]] - B.v[tb[j]]),
                                                   na - spin_a * A.r[ta[i]] - spin_b * B.r[tb[j]]));
    }
    const double closing = -glm::dot(n, pa_path.velocity(t) - pb_path.velocity(t));
    const double first = first_reach(slab, closing + turn_a * ra + turn_b * rb, -na);
    // Planes that turn with either body that turns: the plane of its face, and the plane across
    // n through its corner nearest the other (n as it is now, then turning with that body). Only
    // where the fixed direction's steps are short (they crawl near a contact a body turns about;
    // elsewhere they are long and the planes would only cost time).
    double step = std::max(first, second);
    if (step >= 1e-4) return step;
    double wa = 0.0, wa_rate = 0.0, wb = 0.0, wb_rate = 0.0;
    turn_bounds(pa_path, wa, wa_rate);
    turn_bounds(pb_path, wb, wb_rate);
    uint32_t lowest_a = ta[0], highest_b = tb[0];
    for (int i = 1; i < 3; ++i) {
        if (glm::dot(n, A.x[ta[i]]) < glm::dot(n, A.x[lowest_a])) lowest_a = ta[i];
        if (glm::dot(n, B.x[tb[i]]) > glm::dot(n, B.x[highest_b])) highest_b = tb[i];
    }
    if (wa > 0.0 || wa_rate > 0.0)
        step = std::max({step, turning_face_step(A, ta, pa_path, B, tb, pb_path, t),
                         turning_plane_step(A, lowest_a, pa_path, -n, B, tb, pb_path, t)});
    if (wb > 0.0 || wb_rate > 0.0)
        step = std::max({step, turning_face_step(B, tb, pb_path, A, ta, pa_path, t),
                         turning_plane_step(B, highest_b, pb_path, n, A, ta, pa_path, t)});
    return step;
}

struct Nearest {
    double distance = kInf;
    glm::dvec3 on_a{0.0}, on_b{0.0}, feature_normal{0.0};
    TurningContact::Kind kind = TurningContact::kNone;
};

// Each triangle's box, and each edge's, placed at `v`.
std::vector<Box> triangle_boxes(const TurningMesh &m, const std::vector<glm::dvec3> &v) {
    std::vector<Box> out(m.triangle_count);
    for (std::size_t k = 0; k < m.triangle_count; ++k) {
        const uint32_t *t = m.triangles + 3 * k;
        out[k] = Box{glm::min(v[t[0]], glm::min(v[t[1]], v[t[2]])),
                     glm::max(v[t[0]], glm::max(v[t[1]], v[t[2]]))};
    }
    return out;
}

std::vector<Box> edge_boxes(const TurningMesh &m, const std::vector<glm::dvec3> &v) {
    std::vector<Box> out(m.edge_count);
    for (std::size_t k = 0; k < m.edge_count; ++k) {
        const glm::dvec3 &p = v[m.edges[k][0]], &q = v[m.edges[k][1]];
        out[k] = Box{glm::min(p, q), glm::max(p, q)};
    }
    return out;
}

// Every vertex of each against every triangle of the other and every edge against every edge;
// `near` receives the vertex-face and edge-edge points within `slack` of the nearest. A pair
// whose boxes are farther apart than the nearest can be, plus `slack`, is skipped: it can be
// neither (`reach`: one pair's distance, the vertex and triangle whose boxes are nearest, an
// upper bound of the nearest; the order of the rest is kept, so ties resolve as before). A
// cube on a staircase measured every pair twice at each contact: half the bake's time.
Nearest nearest_features(const TurningMesh &ma, const std::vector<glm::dvec3> &va,
                         const TurningMesh &mb, const std::vector<glm::dvec3> &vb, double slack,
                         std::vector<std::pair<double, glm::dvec3>> *near) {
    Nearest best;
    auto offer = [&](const glm::dvec3 &x, const glm::dvec3 &y, const glm::dvec3 &n,
                     TurningContact::Kind kind) {
        const double d = glm::length(x - y);
        if (near) near->push_back({d, 0.5 * (x + y)});
        // Where a face lies on a face, edges crossing in the common plane tie with the vertices
        // on the faces: the vertex-face kind is kept unless an edge pair is nearer by more than
        // rounding.
        const double margin =
            kind == TurningContact::kEdgeEdge && best.kind == TurningContact::kVertexFace
                ? 64.0 * std::numeric_limits<double>::epsilon() *
                      (1.0 + glm::length(x) + glm::length(y))
                : 0.0;
        if (d < best.distance - margin) {
            best.distance = d;
            best.on_a = x;
            best.on_b = y;
            best.feature_normal = n;
            best.kind = kind;
        }
    };
    const std::vector<Box> boxes_a = triangle_boxes(ma, va), boxes_b = triangle_boxes(mb, vb);
    double reach = kInf, size = 0.0;
    {
        double lowest = kInf;
        const glm::dvec3 *point = nullptr;
        const uint32_t *triangle = nullptr;
        const std::vector<glm::dvec3> *corners = nullptr;
        for (int side = 0; side < 2; ++side) {
            const TurningMesh &mq = side == 0 ? mb : ma;
            const std::vector<glm::dvec3> &vp = side == 0 ? va : vb, &vq = side == 0 ? vb : va;
            const std::vector<Box> &boxes = side == 0 ? boxes_b : boxes_a;
            for (std::size_t k = 0; k < mq.triangle_count; ++k)
                for (const glm::dvec3 &x : vp) {
                    const double d = boxes[k].distance(Box{x, x});
                    if (d < lowest) {
                        lowest = d;
                        point = &x;
                        triangle = mq.triangles + 3 * k;
                        corners = &vq;
                    }
                }
        }
        if (point)
            reach = glm::length(*point - closest_point_on_triangle(*point, (*corners)[triangle[0]],
                                                                   (*corners)[triangle[1]],
                                                                   (*corners)[triangle[2]]));
    }
    for (const std::vector<glm::dvec3> *v : {&va, &vb})
        for (const glm::dvec3 &x : *v) size = std::max(size, glm::length(x));
    // Beyond this no pair can be the nearest or within `slack` of it (with room for rounding).
    const double cut = reach + slack + 1e-9 * (1.0 + size);
    for (int side = 0; side < 2; ++side) {
        const TurningMesh &mp = side == 0 ? ma : mb, &mq = side == 0 ? mb : ma;
        const std::vector<glm::dvec3> &vp = side == 0 ? va : vb, &vq = side == 0 ? vb : va;
        const std::vector<Box> &boxes = side == 0 ? boxes_b : boxes_a;
        for (std::size_t k = 0; k < mq.triangle_count; ++k) {
            const uint32_t *tri = mq.triangles + 3 * k;
            const glm::dvec3 &q0 = vq[tri[0]], &q1 = vq[tri[1]], &q2 = vq[tri[2]];
            const glm::dvec3 face = glm::cross(q1 - q0, q2 - q0);
            for (std::size_t i = 0; i < mp.vertex_count; ++i) {
                if (boxes[k].distance(Box{vp[i], vp[i]}) > cut) continue;
                const glm::dvec3 c = closest_point_on_triangle(vp[i], q0, q1, q2);
                if (side == 0)
                    offer(vp[i], c, face, TurningContact::kVertexFace);
                else
                    offer(c, vp[i], face, TurningContact::kVertexFace);
            }
        }
    }
    const std::vector<Box> edges_a = edge_boxes(ma, va), edges_b = edge_boxes(mb, vb);
    for (std::size_t i = 0; i < ma.edge_count; ++i)
        for (std::size_t j = 0; j < mb.edge_count; ++j) {
            if (edges_a[i].distance(edges_b[j]) > cut) continue;
            const glm::dvec3 &a0 = va[ma.edges[i][0]], &a1 = va[ma.edges[i][1]];
            const glm::dvec3 &b0 = vb[mb.edges[j][0]], &b1 = vb[mb.edges[j][1]];
            glm::dvec3 x, y;
            closest_on_segments(a0, a1, b0, b1, x, y);
            // An edge-edge pair whose nearest point is an edge's end is a vertex's contact,
            // already offered against the face; keep the kind of the feature that touches.
            offer(x, y, glm::cross(a1 - a0, b1 - b0), TurningContact::kEdgeEdge);
        }
    if (near) {
        const double limit = best.distance + slack;
        std::vector<std::pair<double, glm::dvec3>> kept;
        for (const auto &p : *near) {
            if (p.first > limit) continue;
            bool seen = false;
            for (const auto &k : kept) seen = seen || glm::length(k.second - p.second) <= slack;
            if (!seen) kept.push_back(p);
        }
        *near = std::move(kept);
    }
    return best;
}

bool finite(const glm::dvec3 &v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool mesh_is_finite(const TurningMesh &mesh) {
    for (std::size_t i = 0; i < mesh.vertex_count; ++i)
        if (!finite(mesh.vertices[i])) return false;
    return true;
}

bool window_is_finite(double t0, double t1) {
    return std::isfinite(t0) && std::isfinite(t1);
}

bool plane_is_finite(const StaticPlane &plane) {
    return finite(plane.n) && std::isfinite(plane.d) && glm::length(plane.n) > 0.0;
}

} // namespace

bool turning_path_is_finite(const TurningPath &path) {
    if (path.turn && !(path.turn_rate && std::isfinite(path.w_bound) && path.w_bound >= 0.0 &&
                       std::isfinite(path.w_rate_bound) && path.w_rate_bound >= 0.0))
        return false;
    return finite(path.c0) && finite(path.v) && finite(path.a) && finite(path.w) &&
           std::isfinite(path.q0.w) && std::isfinite(path.q0.x) && std::isfinite(path.q0.y) &&
           std::isfinite(path.q0.z);
}

glm::dquat TurningPath::orientation(double t) const {
    if (turn) return turn(t);
    const double rate = glm::length(w);
    if (!(rate > 0.0)) return q0;
    return glm::angleAxis(rate * t, w / rate) * q0;
}

double TurningPath::turn_across(const glm::dvec3 &n) const {
    return turn ? w_bound : glm::length(glm::cross(n, w));
}

double TurningPath::turn_curving(const glm::dvec3 &n) const {
    return turn ? w_bound * w_bound + w_rate_bound : glm::length(glm::cross(n, w)) * glm::length(w);
}

glm::dvec3 TurningPath::place(const glm::dvec3 &p, double t) const {
    return center(t) + orientation(t) * p;
}

// The plane with a unit normal (the bounds take |n| = 1).
StaticPlane unit_plane(const StaticPlane &plane) {
    const double len = glm::length(plane.n);
    return {plane.n / len, plane.d / len};
}

TurningContact turning_plane_contact(const TurningMesh &mesh, const TurningPath &path,
                                     const StaticPlane &given, double t0, double t1,
                                     const TurningContactSettings &settings, double contact_slack) {
    TurningContact out;
    if (!window_is_finite(t0, t1) || !turning_path_is_finite(path) || !mesh_is_finite(mesh) ||
        !plane_is_finite(given)) {
        out.kind = TurningContact::kInvalid;
        return out;
    }
    const StaticPlane plane = unit_plane(given);
    const double rho = path.turn_across(plane.n) * radius_of(mesh);
    double t = t0;
    std::size_t lowest = 0;
    double g = plane_gap(mesh, path, plane, t, lowest);
    for (;;) {
        if (!(g > 0.0)) break;
        const double s =
            std::max(plane_step(path, plane, rho, t, g), plane_taylor_step(mesh, path, plane, t));
        if (s < settings.time_tolerance || t + s == t) break; // within tolerance of touching
        if (t + s > t1) {
            out.t = t1;
            out.gap = g;
            return out; // kNone
        }
        if (out.steps >= settings.max_steps) {
            out.kind = TurningContact::kUndecided;
            out.t = t;
            out.gap = g;
            return out;
        }
        t += s;
        ++out.steps;
        g = plane_gap(mesh, path, plane, t, lowest);
    }
    out.kind = TurningContact::kVertexFace;
    out.t = t;
    out.gap = g;
    out.normal = plane.n;
    const glm::dvec3 x = path.place(mesh.vertices[lowest], t);
    out.point = x - plane.n * (0.5 * g);
    for (std::size_t i = 0; i < mesh.vertex_count; ++i) {
        const glm::dvec3 y = path.place(mesh.vertices[i], t);
        const double h = glm::dot(plane.n, y) - plane.d;
        if (h <= g + contact_slack) out.points.push_back(y - plane.n * (0.5 * h));
    }
    return out;
}

TurningContact turning_mesh_contact(const TurningMesh &a, const TurningPath &path_a,
                                    const TurningMesh &b, const TurningPath &path_b, double t0,
                                    double t1, const TurningContactSettings &settings,
                                    double contact_slack) {
    TurningContact out;
    if (!window_is_finite(t0, t1) || !turning_path_is_finite(path_a) ||
        !turning_path_is_finite(path_b) || !mesh_is_finite(a) || !mesh_is_finite(b)) {
        out.kind = TurningContact::kInvalid;
        return out;
    }
    // Each pair of triangles is known apart until `due` (its last safe step's end): a step
    // measures again only the pairs due by then, the rest keep their bounds (each holds from the
    // time it was taken: the paths are the same), so a pair that stays far is not measured at
    // every step of one that closes. Within the time tolerance of due counts as due, so that a
    // step shorter than the tolerance is always a fresh one: a contact, whose direction is that
    // of the nearest pair measured then (the pair that closed, not one leaving a contact).
    const std::size_t pairs = a.triangle_count * b.triangle_count;
    std::vector<double> due(pairs, t0);
    Moving ma, mb;
    glm::dvec3 pair_normal(0.0);
    double t = t0;
    for (;;) {
        place_moving(a, path_a, t, ma);
        place_moving(b, path_b, t, mb);
        double g = kInf, s = kInf, fresh = kInf;
        for (std::size_t i = 0; i < a.triangle_count; ++i)
            for (std::size_t j = 0; j < b.triangle_count; ++j) {
                double &until = due[i * b.triangle_count + j];
                if (!settings.measure_every_pair && until - t > settings.time_tolerance) {
                    s = std::min(s, until - t);
                    continue;
                }
                double d = kInf;
                glm::dvec3 n(0.0);
                const double step = pair_step(ma, a.triangles + 3 * i, path_a, mb,
                                              b.triangles + 3 * j, path_b, t, d, &n);
                ++out.pair_tests;
                until = t + step;
                fresh = std::min(fresh, step);
                if (d < g) {
                    g = d;
                    pair_normal = n;
                }
            }
        s = std::min(s, fresh);
        out.gap = g;
        if (!(g > 0.0)) break;
        if (fresh < settings.time_tolerance || t + fresh == t) break;
        if (t + s > t1) {
            out.t = t1;
            return out; // kNone
        }
        // At most the work of max_steps plain steps (each step measures at least one pair).
        if (out.pair_tests >= static_cast<std::size_t>(settings.max_steps) * pairs) {
            out.kind = TurningContact::kUndecided;
            out.t = t;
            return out;
        }
        t += s;
        ++out.steps;
    }
    std::vector<glm::dvec3> va = ma.x, vb = mb.x;
    std::vector<std::pair<double, glm::dvec3>> near;
    const Nearest nearest = nearest_features(a, va, b, vb, contact_slack, &near);
    out.t = t;
    out.kind = nearest.kind;
    out.point = 0.5 * (nearest.on_a + nearest.on_b);
    // The direction that separates the nearest triangles best: the face's normal for a vertex on
    // a face, the edges' cross product for two edges, oriented from b towards a.
    // Where the faces lie in one plane at a touch, rounding alone picks the side; the bodies
    // are then closing, a moving towards b, so the normal is the side a comes from.
    glm::dvec3 n = pair_normal;
    const glm::dvec3 at = out.point;
    const glm::dvec3 closing =
        path_a.velocity(t) + glm::cross(path_a.angular_velocity(t), at - path_a.center(t)) -
        path_b.velocity(t) - glm::cross(path_b.angular_velocity(t), at - path_b.center(t));
    if (out.gap <= 1e-9 && glm::dot(n, closing) > 0.0) n = -n;
    out.normal = n;
    for (const auto &p : near) out.points.push_back(p.second);
    return out;
}

glm::dvec3 separating_face_normal(const TurningMesh &a, const TurningPath &path_a,
                                  const TurningMesh &b, const TurningPath &path_b, double t,
                                  double slack, const glm::dvec3 &fallback) {
    std::vector<glm::dvec3> va(a.vertex_count), vb(b.vertex_count);
    for (std::size_t i = 0; i < a.vertex_count; ++i) va[i] = path_a.place(a.vertices[i], t);
    for (std::size_t i = 0; i < b.vertex_count; ++i) vb[i] = path_b.place(b.vertices[i], t);
    // How far apart they are along unit n (from b towards a): a's lowest less b's highest.
    auto apart = [&](const glm::dvec3 &n) {
        double low = kInf, high = -kInf;
        for (const glm::dvec3 &x : va) low = std::min(low, glm::dot(n, x));
        for (const glm::dvec3 &x : vb) high = std::max(high, glm::dot(n, x));
        return low - high;
    };
    glm::dvec3 best = fallback;
    double widest = -slack;
    for (int side = 0; side < 2; ++side) {
        const TurningMesh &m = side == 0 ? a : b;
        const std::vector<glm::dvec3> &v = side == 0 ? va : vb;
        for (std::size_t k = 0; k < m.triangle_count; ++k) {
            const uint32_t *tri = m.triangles + 3 * k;
            offer_direction(glm::cross(v[tri[1]] - v[tri[0]], v[tri[2]] - v[tri[0]]), apart, widest,
                            best);
        }
    }
    return best;
}

double turning_plane_root(const TurningMesh &mesh, const TurningPath &path,
                          const StaticPlane &given, double t_lo, double t1, std::size_t *vertex) {
    if (!window_is_finite(t_lo, t1) || !turning_path_is_finite(path) || !mesh_is_finite(mesh) ||
        !plane_is_finite(given))
        return std::numeric_limits<double>::quiet_NaN();
    const StaticPlane plane = unit_plane(given);
    const double rho = path.turn_across(plane.n) * radius_of(mesh);
    auto height = [&](std::size_t i, double t, double *rate) {
        const glm::dvec3 r = path.orientation(t) * mesh.vertices[i];
        if (rate)
            *rate = glm::dot(plane.n, path.velocity(t) + glm::cross(path.angular_velocity(t), r));
        return glm::dot(plane.n, path.center(t) + r) - plane.d;
    };
    // Bracket: advance the lower end only by safe (conservative) steps; try the Newton step of
    // the lowest vertex as the upper end.
    double lo = t_lo, hi = kInf;
    std::size_t i = 0;
    double g = plane_gap(mesh, path, plane, lo, i);
    for (int k = 0; k < 10000 && hi == kInf; ++k) {
        if (!(g > 0.0)) {
            if (vertex) *vertex = i;
            return lo;
        }
        double rate = 0.0;
        height(i, lo, &rate);
        const double safe =
            std::max(plane_step(path, plane, rho, lo, g), plane_taylor_step(mesh, path, plane, lo));
        if (rate < 0.0) {
            // The Newton step, pushed a little past: its end must be below the plane.
            const double guess = std::max(safe, g / -rate) * (1.0 + 1e-6) + 1e-15;
            std::size_t j = 0;
            if (lo + guess <= t1 && !(plane_gap(mesh, path, plane, lo + guess, j) > 0.0)) {
                hi = lo + guess;
                break;
            }
        }
        if (!(safe < kInf) || lo + safe > t1) return t1 + 1.0;
        const double next = lo + std::max(safe, std::nextafter(lo, kInf) - lo);
        lo = next;
        g = plane_gap(mesh, path, plane, lo, i);
    }
    if (hi == kInf) return t1 + 1.0;
    // Safeguarded Newton (Numerical Recipes' rtsafe) on the lowest vertex's height: a Newton
    // step from the last point when it stays inside the bracket and shrinks it, else bisection.
    double x = hi;
    for (int k = 0; k < 200 && std::nextafter(lo, kInf) < hi; ++k) {
        std::size_t j = 0;
        const double hx = plane_gap(mesh, path, plane, x, j);
        if (hx == 0.0) {
            lo = x;
            break;
        }
        if (hx > 0.0)
            lo = x;
        else
            hi = x;
        double rate = 0.0;
        height(j, x, &rate);
        double next = rate != 0.0 ? x - hx / rate : kInf;
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (next == x) next = 0.5 * (lo + hi);
        x = next;
        i = j;
    }
    if (vertex) *vertex = i;
    return lo;
}

} // namespace physics_custom
