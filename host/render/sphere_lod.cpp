#include "render/sphere_lod.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>
#include <vector>

namespace animator {

namespace {

struct Face {
    std::uint32_t a, b, c; // indices into the hull's points, counter-clockwise seen from outside
    glm::dvec3 normal;     // outward, unit
    double offset;         // normal . a
    bool alive = true;
};

Face make_face(const std::vector<glm::dvec3> &p, std::uint32_t a, std::uint32_t b,
               std::uint32_t c) {
    Face f{a, b, c, glm::normalize(glm::cross(p[b] - p[a], p[c] - p[a])), 0.0};
    f.offset = glm::dot(f.normal, p[a]);
    return f;
}

// The convex hull of `p` (incremental: each point added removes the faces it sees and joins
// their horizon to itself), points within `tolerance` of a face's plane taken as on it (not
// added). Empty when the first four are not found apart.
std::vector<Face> convex_hull(const std::vector<glm::dvec3> &p, double tolerance) {
    const std::size_t n = p.size();
    if (n < 4) return {};
    // A first tetrahedron: the farthest point from the first, the farthest from their line, the
    // farthest from their plane.
    std::uint32_t i0 = 0, i1 = 0, i2 = 0, i3 = 0;
    double most = 0.0;
    for (std::uint32_t i = 1; i < n; ++i)
        if (glm::length(p[i] - p[i0]) > most) most = glm::length(p[i] - p[i0]), i1 = i;
    most = 0.0;
    for (std::uint32_t i = 0; i < n; ++i) {
        const double d = glm::length(glm::cross(p[i] - p[i0], glm::normalize(p[i1] - p[i0])));
        if (d > most) most = d, i2 = i;
    }
    const glm::dvec3 plane = glm::normalize(glm::cross(p[i1] - p[i0], p[i2] - p[i0]));
    most = 0.0;
    for (std::uint32_t i = 0; i < n; ++i) {
        const double d = std::abs(glm::dot(p[i] - p[i0], plane));
        if (d > most) most = d, i3 = i;
    }
    if (most <= tolerance) return {};
    if (glm::dot(p[i3] - p[i0], plane) > 0.0) std::swap(i1, i2); // i3 behind (i0, i1, i2)
    std::vector<Face> faces = {make_face(p, i0, i1, i2), make_face(p, i0, i3, i1),
                               make_face(p, i1, i3, i2), make_face(p, i2, i3, i0)};
    std::set<std::pair<std::uint32_t, std::uint32_t>> seen; // the visible faces' edges
    for (std::uint32_t i = 0; i < n; ++i) {
        if (i == i0 || i == i1 || i == i2 || i == i3) continue;
        seen.clear();
        const std::size_t before = faces.size();
        for (std::size_t k = 0; k < before; ++k) {
            Face &f = faces[k];
            if (!f.alive || glm::dot(f.normal, p[i]) - f.offset <= tolerance) continue;
            f.alive = false;
            seen.insert({f.a, f.b});
            seen.insert({f.b, f.c});
            seen.insert({f.c, f.a});
        }
        // The horizon: the edges of seen faces whose other side is not seen, each joined to i
        // in the seen face's turn (so the new face faces out).
        for (const auto &[u, v] : seen)
            if (!seen.count({v, u})) faces.push_back(make_face(p, u, v, i));
    }
    faces.erase(std::remove_if(faces.begin(), faces.end(), [](const Face &f) { return !f.alive; }),
                faces.end());
    return faces;
}

} // namespace

SphereLevel sphere_even_level(const Mesh &mesh, std::size_t vertices) {
    const glm::dvec3 centre = mesh.bound_center;
    const double radius = mesh.bound_radius;
    if (vertices < 4 || mesh.positions.empty() || !(radius > 0.0)) return {};
    // A Fibonacci lattice of `vertices` directions, spread more evenly by a few steps of Lloyd's
    // relaxation on the sphere: each moves to the mean of the circumcentres of the hull's
    // triangles around it, weighed by their areas. (The lattice's hull strays 20% farther than
    // the relaxed one's for as many triangles; after five steps it gains no more.)
    const double golden = M_PI * (3.0 - std::sqrt(5.0));
    std::vector<glm::dvec3> points;
    for (std::size_t i = 0; i < vertices; ++i) {
        const double y = 1.0 - (2.0 * static_cast<double>(i) + 1.0) / static_cast<double>(vertices);
        const double ring = std::sqrt(std::max(0.0, 1.0 - y * y));
        const double angle = golden * static_cast<double>(i);
        points.emplace_back(ring * std::cos(angle), y, ring * std::sin(angle));
    }
    // (The steps keep the first hull's triangles, their circumcentres moving with their corners:
    // the points move little, and a hull made anew at each step took 28 ms of sphere.obj's chain
    // where this takes 18, for levels whose errors are the same to four digits. The level is the
    // hull made after them.)
    const double tolerance = 1e-12;
    std::vector<Face> hull = convex_hull(points, tolerance);
    if (hull.empty()) return {};
    for (int step = 0; step < 5; ++step) {
        std::vector<glm::dvec3> sum(points.size(), glm::dvec3(0.0));
        for (const Face &f : hull) {
            const glm::dvec3 twice_area =
                glm::cross(points[f.b] - points[f.a], points[f.c] - points[f.a]);
            // Its circumcentre on the sphere (its plane's normal), weighed by its area.
            for (std::uint32_t k : {f.a, f.b, f.c}) sum[k] += 0.5 * twice_area;
        }
        for (std::size_t i = 0; i < points.size(); ++i)
            if (glm::length(sum[i]) > 0.0) points[i] = glm::normalize(sum[i]);
    }
    hull = convex_hull(points, tolerance);
    if (hull.empty()) return {};
    // Wound as the mesh: its triangles' normals by their corners' order point out of the sphere
    // (counter-clockwise seen from outside) or all in; its normals likewise. The hull's faces
    // sink into the sphere by up to `deepest` (of its radius) and the mesh's own by up to `own`:
    // the level is pushed out by half their difference, so that it strays as far out of the
    // mesh's surface as into it (for as many triangles, half as far as the hull itself).
    double outward = 0.0, normals_out = 0.0, deepest = 0.0, own = 0.0;
    for (std::size_t t = 0; t + 2 < mesh.triangles.size(); t += 3) {
        const glm::dvec3 a = mesh.positions[mesh.triangles[t]] - centre,
                         b = mesh.positions[mesh.triangles[t + 1]] - centre,
                         c = mesh.positions[mesh.triangles[t + 2]] - centre;
        const glm::dvec3 n = glm::cross(b - a, c - a);
        outward += glm::dot(n, a);
        if (glm::length(n) > 0.0)
            own = std::max(own, 1.0 - std::abs(glm::dot(glm::normalize(n), a)) / radius);
    }
    for (std::size_t i = 0; i < mesh.normals.size() && i < mesh.positions.size(); ++i)
        normals_out += glm::dot(mesh.normals[i], mesh.positions[i] - centre);
    for (const Face &f : hull) deepest = std::max(deepest, 1.0 - f.offset);
    const double scale = radius * (1.0 + 0.5 * std::max(deepest - own, 0.0));
    SphereLevel level;
    for (const glm::dvec3 &d : points) {
        level.positions.push_back(centre + scale * d);
        level.normals.push_back(normals_out < 0.0 ? -d : d);
    }
    level.triangles.reserve(hull.size() * 3);
    for (const Face &f : hull) {
        level.triangles.push_back(f.a);
        level.triangles.push_back(outward >= 0.0 ? f.b : f.c);
        level.triangles.push_back(outward >= 0.0 ? f.c : f.b);
    }
    return level;
}

} // namespace animator
