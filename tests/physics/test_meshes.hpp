// Meshes built in code for the mesh narrow phase's tests and for the benchmark (bench/mesh.cpp):
// an icosahedron subdivided towards the unit sphere, a tessellated floor, and the winding that
// makes every triangle face out.
#pragma once

#include "mesh_contact.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace physics_custom::test_meshes {

using Vertices = std::vector<glm::dvec3>;
using Triangles = std::vector<std::array<uint32_t, 3>>;

// Turns every triangle counter-clockwise seen from outside, for a mesh that is star-shaped
// around `inside`.
inline Triangles facing_out(const Vertices &v, Triangles tris, const glm::dvec3 &inside = glm::dvec3(0.0)) {
    for (auto &t : tris) {
        const glm::dvec3 n = glm::cross(v[t[1]] - v[t[0]], v[t[2]] - v[t[0]]);
        if (glm::dot(n, (v[t[0]] + v[t[1]] + v[t[2]]) / 3.0 - inside) < 0.0) std::swap(t[1], t[2]);
    }
    return tris;
}

// An icosahedron's faces subdivided `level` times (20 * 4^level triangles), every vertex on the
// unit sphere. The winding is left as it comes: pass the result through facing_out.
inline std::pair<Vertices, Triangles> subdivided_icosahedron(int level) {
    const double p = (1.0 + std::sqrt(5.0)) / 2.0;
    Vertices v = {{-1, p, 0},  {1, p, 0},  {-1, -p, 0}, {1, -p, 0}, {0, -1, p},  {0, 1, p},
                  {0, -1, -p}, {0, 1, -p}, {p, 0, -1},  {p, 0, 1},  {-p, 0, -1}, {-p, 0, 1}};
    Triangles t = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                   {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                   {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                   {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    for (auto &x : v) x = glm::normalize(x);
    for (int l = 0; l < level; ++l) {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> middle;
        auto mid = [&](uint32_t a, uint32_t b) {
            const auto key = std::minmax(a, b);
            const auto found = middle.find(key);
            if (found != middle.end()) return found->second;
            v.push_back(glm::normalize(v[a] + v[b]));
            return middle[key] = static_cast<uint32_t>(v.size() - 1);
        };
        Triangles next;
        for (const auto &f : t) {
            const uint32_t ab = mid(f[0], f[1]), bc = mid(f[1], f[2]), ca = mid(f[2], f[0]);
            next.push_back({f[0], ab, ca});
            next.push_back({f[1], bc, ab});
            next.push_back({f[2], ca, bc});
            next.push_back({ab, bc, ca});
        }
        t = std::move(next);
    }
    return {std::move(v), std::move(t)};
}

// A square of side 2 s in the plane y = 0, facing +Y, in n x n cells of two triangles each (an
// open mesh: a floor).
inline MeshShape floor_square(double s, int n = 1) {
    Vertices v;
    Triangles t;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) v.emplace_back(-s + 2.0 * s * i / n, 0.0, -s + 2.0 * s * j / n);
    auto at = [&](int i, int j) { return static_cast<uint32_t>(i * (n + 1) + j); };
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            // (i, j) -> (i, j + 1) -> (i + 1, j + 1) runs counter-clockwise seen from above.
            t.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1)});
            t.push_back({at(i, j), at(i + 1, j + 1), at(i + 1, j)});
        }
    return MeshShape::build(v, t);
}

} // namespace physics_custom::test_meshes
