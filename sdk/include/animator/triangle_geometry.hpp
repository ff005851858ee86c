// animator SDK, optional C++ helper (header only, glm): the point of a triangle nearest to a
// point, shared by the backend that measures distances to meshes (physics.custom) and the host's
// levels of detail (the distance from a simplified mesh to its original).
#pragma once

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace ani {

// The point of the triangle a, b, c nearest to q (Ericson, Real-Time Collision Detection
// 5.1.5): by the Voronoi regions of its corners, then of its edges, then its face.
inline glm::dvec3 closest_point_on_triangle(const glm::dvec3 &q, const glm::dvec3 &a, const glm::dvec3 &b,
                                            const glm::dvec3 &c) {
    const glm::dvec3 ab = b - a, ac = c - a, aq = q - a;
    const double d1 = glm::dot(ab, aq), d2 = glm::dot(ac, aq);
    if (d1 <= 0.0 && d2 <= 0.0) return a;
    const glm::dvec3 bq = q - b;
    const double d3 = glm::dot(ab, bq), d4 = glm::dot(ac, bq);
    if (d3 >= 0.0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + ab * (d1 / (d1 - d3));
    const glm::dvec3 cq = q - c;
    const double d5 = glm::dot(ab, cq), d6 = glm::dot(ac, cq);
    if (d6 >= 0.0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + ac * (d2 / (d2 - d6));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
        return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    const double denom = 1.0 / (va + vb + vc);
    return a + ab * (vb * denom) + ac * (vc * denom);
}

} // namespace ani
