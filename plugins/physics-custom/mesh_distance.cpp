#include "mesh_distance.hpp"

#include "time_of_impact.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace physics_custom {

// The closest points of segments p1q1 and p2q2 (Ericson, Real-Time Collision Detection 5.1.9).
void closest_on_segments(const glm::dvec3 &p1, const glm::dvec3 &q1, const glm::dvec3 &p2,
                         const glm::dvec3 &q2, glm::dvec3 &c1, glm::dvec3 &c2) {
    const glm::dvec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
    const double a = glm::dot(d1, d1), e = glm::dot(d2, d2), f = glm::dot(d2, r);
    double s = 0.0, t = 0.0;
    if (a <= 0.0 && e > 0.0) {
        t = std::clamp(f / e, 0.0, 1.0);
    } else if (a > 0.0) {
        const double c = glm::dot(d1, r);
        if (e <= 0.0) {
            s = std::clamp(-c / a, 0.0, 1.0);
        } else {
            const double b = glm::dot(d1, d2), denom = a * e - b * b;
            s = denom > 0.0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
            t = (b * s + f) / e;
            if (t < 0.0) {
                t = 0.0;
                s = std::clamp(-c / a, 0.0, 1.0);
            } else if (t > 1.0) {
                t = 1.0;
                s = std::clamp((b - c) / a, 0.0, 1.0);
            }
        }
    }
    c1 = p1 + d1 * s;
    c2 = p2 + d2 * t;
}

// The distance between two meshes' surfaces, the nearest points, and the normal there from
// b towards a: every vertex of each against every triangle of the other, every edge against
// every edge. At a touch the nearest points coincide, so the normal comes from the features:
// the face's normal for a vertex nearest to a face, the edges' cross product for two edges.
double mesh_distance(const PlacedMesh &a, const PlacedMesh &b, glm::dvec3 &on_a, glm::dvec3 &on_b,
                     glm::dvec3 &normal) {
    double best = std::numeric_limits<double>::infinity();
    glm::dvec3 feature_normal(0.0); // unoriented
    auto offer = [&](const glm::dvec3 &x, const glm::dvec3 &y, const glm::dvec3 &n) {
        const double d = glm::length(x - y);
        if (d < best) {
            best = d;
            on_a = x;
            on_b = y;
            feature_normal = n;
        }
    };
    for (int side = 0; side < 2; ++side) {
        const PlacedMesh &p = side == 0 ? a : b, &q = side == 0 ? b : a;
        for (const glm::dvec3 &v : p.vertices)
            for (size_t k = 0; k < q.triangle_count; ++k) {
                const uint32_t *t = q.triangles + 3 * k;
                const glm::dvec3 &q0 = q.vertices[t[0]], &q1 = q.vertices[t[1]],
                                 &q2 = q.vertices[t[2]];
                const glm::dvec3 c = closest_point_on_triangle(v, q0, q1, q2);
                const glm::dvec3 face = glm::cross(q1 - q0, q2 - q0);
                if (side == 0)
                    offer(v, c, face);
                else
                    offer(c, v, face);
            }
    }
    for (size_t i = 0; i < a.edge_count; ++i)
        for (size_t j = 0; j < b.edge_count; ++j) {
            glm::dvec3 x, y;
            const glm::dvec3 &a0 = a.vertices[a.edges[i][0]], &a1 = a.vertices[a.edges[i][1]];
            const glm::dvec3 &b0 = b.vertices[b.edges[j][0]], &b1 = b.vertices[b.edges[j][1]];
            closest_on_segments(a0, a1, b0, b1, x, y);
            offer(x, y, glm::cross(a1 - a0, b1 - b0));
        }
    // Apart: the direction between the nearest points (the gradient of the distance). Touching:
    // the touching features' normal, oriented from b towards a by the centers.
    const glm::dvec3 apart = on_a - on_b, centers = a.center - b.center;
    const double size = glm::length(centers) + 1.0;
    if (glm::length(apart) > 1e-9 * size) {
        normal = glm::normalize(apart);
        return best;
    }
    glm::dvec3 n =
        glm::length(feature_normal) > 0.0 ? glm::normalize(feature_normal) : glm::dvec3(0.0);
    if (n == glm::dvec3(0.0))
        n = glm::length(centers) > 0.0 ? glm::normalize(centers) : glm::dvec3(0, 1, 0);
    const double side = glm::dot(n, centers);
    normal = side < 0.0 ? -n : n;
    return best;
}

std::vector<std::array<uint32_t, 2>> edges_of(const uint32_t *triangles,
                                              std::size_t triangle_count) {
    std::vector<std::array<uint32_t, 2>> edges;
    edges.reserve(3 * triangle_count);
    for (std::size_t k = 0; k < triangle_count; ++k)
        for (std::size_t e = 0; e < 3; ++e) {
            uint32_t a = triangles[3 * k + e], b = triangles[3 * k + (e + 1) % 3];
            if (b < a) std::swap(a, b);
            edges.push_back({a, b});
        }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    return edges;
}

namespace {

struct Bounds {
    glm::dvec3 lo{std::numeric_limits<double>::infinity()},
        hi{-std::numeric_limits<double>::infinity()};
    void add(const glm::dvec3 &p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    bool overlaps(const Bounds &o) const {
        return lo.x <= o.hi.x && o.lo.x <= hi.x && lo.y <= o.hi.y && o.lo.y <= hi.y &&
               lo.z <= o.hi.z && o.lo.z <= hi.z;
    }
};

// Whether segment ae passes through the inside of triangle c0 c1 c2 (see surfaces_cross).
bool segment_crosses(const glm::dvec3 &a, const glm::dvec3 &e, const glm::dvec3 &c0,
                     const glm::dvec3 &c1, const glm::dvec3 &c2, double tol) {
    const glm::dvec3 n = glm::cross(c1 - c0, c2 - c0);
    if (!(glm::length(n) > 0.0)) return false;
    const glm::dvec3 u = glm::normalize(n);
    const double da = glm::dot(u, a - c0), db = glm::dot(u, e - c0);
    if (!((da > tol && db < -tol) || (da < -tol && db > tol))) return false;
    const glm::dvec3 q = a + (e - a) * (da / (da - db));
    const glm::dvec3 c[3] = {c0, c1, c2};
    for (int i = 0; i < 3; ++i) {
        const glm::dvec3 side = c[(i + 1) % 3] - c[i];
        if (!(glm::dot(glm::cross(side, q - c[i]), u) > tol * glm::length(side))) return false;
    }
    return true;
}

// The edges of `from` through the triangles of `to`, looking only where both can be.
bool edges_cross(const PlacedMesh &from, const PlacedMesh &to, const Bounds &common, double tol) {
    std::vector<std::size_t> near;
    std::vector<Bounds> boxes;
    for (std::size_t f = 0; f < to.triangle_count; ++f) {
        Bounds box;
        for (int c = 0; c < 3; ++c) box.add(to.vertices[to.triangles[3 * f + c]]);
        if (!box.overlaps(common)) continue;
        near.push_back(f);
        boxes.push_back(box);
    }
    for (std::size_t k = 0; k < from.edge_count; ++k) {
        const glm::dvec3 &a = from.vertices[from.edges[k][0]], &e = from.vertices[from.edges[k][1]];
        Bounds edge;
        edge.add(a);
        edge.add(e);
        if (!edge.overlaps(common)) continue;
        for (std::size_t n = 0; n < near.size(); ++n) {
            const uint32_t *tri = to.triangles + 3 * near[n];
            if (edge.overlaps(boxes[n]) &&
                segment_crosses(a, e, to.vertices[tri[0]], to.vertices[tri[1]], to.vertices[tri[2]],
                                tol))
                return true;
        }
    }
    return false;
}

} // namespace

bool surfaces_cross(const PlacedMesh &a, const PlacedMesh &b, double tol) {
    Bounds box_a, box_b;
    for (const glm::dvec3 &v : a.vertices) box_a.add(v);
    for (const glm::dvec3 &v : b.vertices) box_b.add(v);
    Bounds common;
    common.lo = glm::max(box_a.lo, box_b.lo) - glm::dvec3(tol);
    common.hi = glm::min(box_a.hi, box_b.hi) + glm::dvec3(tol);
    if (common.lo.x > common.hi.x || common.lo.y > common.hi.y || common.lo.z > common.hi.z)
        return false;
    return edges_cross(a, b, common, tol) || edges_cross(b, a, common, tol);
}

} // namespace physics_custom
