#include "animator/mesh_topology.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <map>
#include <utility>
#include <vector>

namespace ani {

namespace {

// The signed volume the triangles enclose (the divergence theorem over each triangle, x part:
// the first of Eberly's volume integrals, "Polyhedral Mass Properties (Revisited)"), with the
// vertices taken relative to their mean, so that a mesh far from the origin keeps its digits.
double enclosed_volume(const ani_mesh_view &mesh) {
    double mean[3] = {0.0, 0.0, 0.0};
    for (uint32_t i = 0; i < mesh.vertex_count; ++i)
        for (int c = 0; c < 3; ++c) mean[c] += mesh.positions[3 * std::size_t(i) + c];
    if (mesh.vertex_count)
        for (double &m : mean) m /= double(mesh.vertex_count);
    double sum = 0.0;
    for (uint32_t t = 0; t < mesh.triangle_count; ++t) {
        double p[3][3];
        for (int k = 0; k < 3; ++k)
            for (int c = 0; c < 3; ++c)
                p[k][c] = mesh.positions[3 * std::size_t(mesh.triangles[3 * std::size_t(t) + k]) + c] - mean[c];
        // x of (p1 - p0) x (p2 - p0), times p0.x + p1.x + p2.x
        const double e1[3] = {p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
        const double e2[3] = {p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
        const double dx = e1[1] * e2[2] - e1[2] * e2[1];
        sum += dx * (p[0][0] + p[1][0] + p[2][0]);
    }
    return sum / 6.0;
}

} // namespace

bool is_closed(const ani_mesh_view &mesh, std::string *why) {
    auto fail = [&](std::string text) {
        if (why) *why = std::move(text);
        return false;
    };
    if (mesh.triangle_count == 0) return fail("it has no triangles");
    // Meshes split a vertex where its normals or UVs differ (a cube's corner is three vertices
    // at one position): the surface is closed when the triangles close over the positions, so
    // each vertex is taken as the first vertex at its position.
    std::map<std::array<double, 3>, uint32_t> first_at;
    std::vector<uint32_t> welded(mesh.vertex_count);
    for (uint32_t i = 0; i < mesh.vertex_count; ++i) {
        const double *p = mesh.positions + 3 * std::size_t(i);
        welded[i] = first_at.emplace(std::array<double, 3>{p[0], p[1], p[2]}, i).first->second;
    }
    // Each undirected edge (lower index first) with the triangles that use it and whether they
    // run along it from the lower index to the higher.
    std::map<std::pair<uint32_t, uint32_t>, std::vector<std::pair<uint32_t, bool>>> edges;
    for (uint32_t t = 0; t < mesh.triangle_count; ++t) {
        const uint32_t *named = mesh.triangles + 3 * std::size_t(t);
        for (int k = 0; k < 3; ++k)
            if (named[k] >= mesh.vertex_count)
                return fail("triangle " + std::to_string(t) + " names vertex " +
                            std::to_string(named[k]) + " of " + std::to_string(mesh.vertex_count));
        const uint32_t v[3] = {welded[named[0]], welded[named[1]], welded[named[2]]};
        if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0])
            return fail("triangle " + std::to_string(t) + " is degenerate");
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = v[k], b = v[(k + 1) % 3];
            edges[{std::min(a, b), std::max(a, b)}].push_back({t, a < b});
        }
    }
    for (const auto &[edge, users] : edges) {
        const std::string name = std::to_string(edge.first) + "-" + std::to_string(edge.second);
        if (users.size() != 2)
            return fail("edge " + name + " is used by " + std::to_string(users.size()) +
                        (users.size() == 1 ? " triangle" : " triangles"));
        if (users[0].second == users[1].second)
            return fail("edge " + name + " runs the same way in triangles " +
                        std::to_string(users[0].first) + " and " + std::to_string(users[1].first));
    }
    const double volume = enclosed_volume(mesh);
    if (!(volume > 0.0))
        return fail("its triangles face inward or enclose no volume (volume " +
                    std::to_string(volume) + ")");
    return true;
}

} // namespace ani
