#include "render/mesh_lod.hpp"

#include "render/sphere_lod.hpp"

#include <animator/triangle_geometry.hpp>

#include <meshoptimizer.h>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace animator {

namespace {
constexpr std::size_t kFewestTriangles = 64; // below it, one level: nothing to gain
constexpr std::size_t kCoarsest = 24;        // no level of fewer triangles is asked for

// Some triangles (corners in `positions`) in a uniform grid of cubes about two triangles wide,
// for the distance from a point to the nearest of them. The cells' triangles are in one list
// (counting sort).
class TriangleGrid {
  public:
    TriangleGrid(const std::vector<glm::dvec3> &positions, const std::uint32_t *indices,
                 std::size_t count)
        : positions_(positions), indices_(indices) {
        low_ = glm::dvec3(std::numeric_limits<double>::max());
        glm::dvec3 high(-std::numeric_limits<double>::max());
        double edges = 0.0;
        for (std::size_t t = 0; t < count; t += 3)
            for (int v = 0; v < 3; ++v) {
                const glm::dvec3 &p = positions[indices[t + v]];
                low_ = glm::min(low_, p);
                high = glm::max(high, p);
                edges += glm::length(positions[indices[t + (v + 1) % 3]] - p);
            }
        const glm::dvec3 extent = high - low_;
        // (At most 128 cells along an axis: a long thin mesh gets wider cells.)
        cell_ = std::max({2.0 * edges / static_cast<double>(count), extent.x / 127.0, extent.y / 127.0,
                          extent.z / 127.0, 1e-9 * glm::length(extent) + 1e-300});
        for (int k = 0; k < 3; ++k) cells_[k] = std::min(128, static_cast<int>(extent[k] / cell_) + 1);
        std::vector<std::pair<std::size_t, std::uint32_t>> entries; // (cell, first index)
        for (std::size_t t = 0; t < count; t += 3) {
            glm::ivec3 a = cell_of(positions[indices[t]]), b = a;
            for (int v = 1; v < 3; ++v) {
                const glm::ivec3 c = cell_of(positions[indices[t + v]]);
                a = glm::min(a, c);
                b = glm::max(b, c);
            }
            for (int x = a.x; x <= b.x; ++x)
                for (int y = a.y; y <= b.y; ++y)
                    for (int z = a.z; z <= b.z; ++z)
                        entries.emplace_back(index(x, y, z), static_cast<std::uint32_t>(t));
        }
        start_.assign(static_cast<std::size_t>(cells_[0]) * cells_[1] * cells_[2] + 1, 0);
        for (const auto &e : entries) ++start_[e.first + 1];
        for (std::size_t i = 1; i < start_.size(); ++i) start_[i] += start_[i - 1];
        triangles_.resize(entries.size());
        std::vector<std::uint32_t> next(start_.begin(), start_.end() - 1);
        for (const auto &e : entries) triangles_[next[e.first]++] = e.second;
    }

    // The distance from p to the nearest triangle, or any distance at most `enough` once one
    // within it is found: shell after shell of cells around p's, until no cell farther out can
    // hold a nearer one.
    double distance(const glm::dvec3 &p, double enough) const {
        const glm::ivec3 home = cell_of(p);
        // p may lie outside the grid (by less than the surfaces' distance): the first shells can
        // then be nearer than their number says.
        glm::dvec3 outside(0.0);
        for (int k = 0; k < 3; ++k)
            outside[k] = std::max({low_[k] - p[k], p[k] - (low_[k] + cells_[k] * cell_), 0.0});
        const double slack = glm::length(outside);
        double best = std::numeric_limits<double>::max();
        const int shells = std::max({cells_[0], cells_[1], cells_[2]});
        for (int r = 0; r <= shells && best > (r - 1) * cell_ - slack; ++r)
            for (int x = std::max(home.x - r, 0); x <= std::min(home.x + r, cells_[0] - 1); ++x)
                for (int y = std::max(home.y - r, 0); y <= std::min(home.y + r, cells_[1] - 1); ++y) {
                    // Inside the shell's x and y span, only its two z faces; on its rim, every z.
                    const bool rim = std::abs(x - home.x) == r || std::abs(y - home.y) == r;
                    for (int z = home.z - r; z <= home.z + r; z += rim ? 1 : std::max(2 * r, 1)) {
                        if (z < 0 || z >= cells_[2]) continue;
                        const std::size_t i = index(x, y, z);
                        for (std::uint32_t k = start_[i]; k < start_[i + 1]; ++k) {
                            const std::uint32_t t = triangles_[k];
                            const glm::dvec3 &a = positions_[indices_[t]],
                                             &b = positions_[indices_[t + 1]],
                                             &c = positions_[indices_[t + 2]];
                            best = std::min(best, glm::length(p - ani::closest_point_on_triangle(p, a, b, c)));
                            if (best <= enough) return best;
                        }
                    }
                }
        return best;
    }

  private:
    glm::ivec3 cell_of(const glm::dvec3 &p) const {
        glm::ivec3 c;
        for (int k = 0; k < 3; ++k)
            c[k] = std::clamp(static_cast<int>(std::floor((p[k] - low_[k]) / cell_)), 0, cells_[k] - 1);
        return c;
    }
    std::size_t index(int x, int y, int z) const {
        return (static_cast<std::size_t>(z) * cells_[1] + y) * cells_[0] + x;
    }

    const std::vector<glm::dvec3> &positions_;
    const std::uint32_t *indices_;
    glm::dvec3 low_;
    double cell_ = 1.0;
    int cells_[3] = {1, 1, 1};
    std::vector<std::uint32_t> start_;     // per cell, where its triangles begin in triangles_
    std::vector<std::uint32_t> triangles_; // first indices
};

// The points of a level's triangle where it parts most from the mesh: its centroid and the
// midpoints of its edges (its corners lie on both).
template <typename Visit>
void sample_triangles(const std::vector<glm::dvec3> &positions, const std::uint32_t *indices,
                      std::size_t count, Visit &&visit) {
    for (std::size_t t = 0; t < count; t += 3) {
        const glm::dvec3 &a = positions[indices[t]], &b = positions[indices[t + 1]],
                         &c = positions[indices[t + 2]];
        visit((a + b + c) / 3.0);
        visit((a + b) * 0.5);
        visit((b + c) * 0.5);
        visit((c + a) * 0.5);
    }
}

} // namespace

LodChain build_lod_chain(const Mesh &mesh) {
    LodChain chain;
    chain.indices = mesh.triangles;
    chain.levels.push_back({0, static_cast<std::uint32_t>(mesh.triangles.size()), 0.0});
    if (mesh.triangle_count() < kFewestTriangles) return chain;

    std::vector<float> positions;
    positions.reserve(mesh.positions.size() * 3);
    for (const glm::dvec3 &p : mesh.positions)
        for (int k = 0; k < 3; ++k) positions.push_back(static_cast<float>(p[k]));
    const std::size_t vertex_count = mesh.positions.size();
    // meshoptimizer's errors are relative to the mesh's extent: this turns them into lengths.
    const double scale = meshopt_simplifyScale(positions.data(), vertex_count, 3 * sizeof(float));
    const double rounding = 1e-9 * scale; // distances below it are 0 (a flat grid's levels)

    // The mesh's surface, for measuring how far each level strays from it: a two-sided Hausdorff
    // distance, sampled, from the mesh's vertices to the level's triangles (the vertices it left
    // out are where it strays) and from the level's triangles (their centroids and edge
    // midpoints, and corners where they are not the mesh's) to the mesh's, at least `estimate`.
    // (A point nearer than the largest distance so far cannot raise it: its search stops at the
    // first triangle that near.) `with` holds the level's vertices: the mesh's, or the mesh's
    // and those added after them.
    const TriangleGrid whole(mesh.positions, mesh.triangles.data(), mesh.triangles.size());
    const auto measure = [&](const std::vector<glm::dvec3> &with, const std::uint32_t *indices,
                             std::size_t count, double estimate) {
        double distance = estimate;
        const auto farthest = [&](const TriangleGrid &surface, const glm::dvec3 &p) {
            distance = std::max(distance, surface.distance(p, std::max(distance, rounding)));
        };
        sample_triangles(with, indices, count, [&](const glm::dvec3 &p) { farthest(whole, p); });
        for (std::size_t t = 0; t < count; ++t)
            if (indices[t] >= mesh.positions.size()) farthest(whole, with[indices[t]]);
        const TriangleGrid level(with, indices, count);
        for (const glm::dvec3 &p : mesh.positions) farthest(level, p);
        return distance;
    };
    std::vector<std::uint32_t> simplified(mesh.triangles.size());
    std::size_t previous = mesh.triangles.size();
    double error_so_far = 0.0;
    for (std::size_t target = previous / 2; target >= 3 * kCoarsest; target /= 2) {
        float error = 0.0f;
        // Each level from the mesh itself (not from the level before), so errors do not add up;
        // no error limit (1 = the whole extent): the triangle count decides.
        const std::size_t count = meshopt_simplify(
            simplified.data(), mesh.triangles.data(), mesh.triangles.size(), positions.data(),
            vertex_count, 3 * sizeof(float), target, 1.0f, 0, &error);
        if (count == 0 || count * 4 > previous * 3) break; // it stopped reducing
        // meshoptimizer's own estimate (error * scale) falls short of the distance between the
        // surfaces, by up to 3 times on a torus: it is measured instead, and is at least the
        // estimate.
        const double distance =
            measure(mesh.positions, simplified.data(), count, static_cast<double>(error) * scale);
        error_so_far = std::max(error_so_far, distance);
        chain.levels.push_back({static_cast<std::uint32_t>(chain.indices.size()),
                                static_cast<std::uint32_t>(count), error_so_far});
        chain.indices.insert(chain.indices.end(), simplified.begin(),
                             simplified.begin() + static_cast<std::ptrdiff_t>(count));
        previous = count;
    }
    // A sphere's levels of even triangles (sphere_lod.hpp), each kept where no level has as few
    // triangles or fewer with as small an error or smaller; their vertices are added after the
    // mesh's, and they keep no texture coordinates. Measured against the mesh as the others are,
    // over the mesh's vertices and those added (`every_position`: the mesh's, then the kept
    // levels').
    if (approximates_sphere(mesh)) {
        std::vector<glm::dvec3> every_position = mesh.positions;
        previous = mesh.triangles.size();
        // (From about 1,000 triangles down: where a far sphere's few pixels are drawn, and where
        // the simplifier's levels stray most. Measuring each costs a few ms.)
        for (std::size_t vertices = std::min<std::size_t>(mesh.positions.size() / 2, 512);
             2 * vertices >= kCoarsest + 4; vertices = vertices * 3 / 4) {
            const SphereLevel even = sphere_even_level(mesh, vertices);
            if (even.triangles.empty() || even.triangles.size() * 4 > previous * 3) continue;
            previous = even.triangles.size();
            const auto first = static_cast<std::uint32_t>(every_position.size());
            std::vector<std::uint32_t> level(even.triangles);
            for (std::uint32_t &i : level) i += first;
            every_position.insert(every_position.end(), even.positions.begin(),
                                  even.positions.end());
            const double distance = measure(every_position, level.data(), level.size(), 0.0);
            const bool beaten =
                std::any_of(chain.levels.begin(), chain.levels.end(), [&](const LodLevel &l) {
                    return l.count <= level.size() && l.error <= distance;
                });
            if (beaten) {
                every_position.resize(first);
                continue;
            }
            chain.levels.push_back({static_cast<std::uint32_t>(chain.indices.size()),
                                    static_cast<std::uint32_t>(level.size()), distance, false});
            chain.indices.insert(chain.indices.end(), level.begin(), level.end());
            chain.added_normals.insert(chain.added_normals.end(), even.normals.begin(),
                                       even.normals.end());
        }
        chain.added_positions.assign(every_position.begin() +
                                         static_cast<std::ptrdiff_t>(mesh.positions.size()),
                                     every_position.end());
    }
    return chain;
}

std::size_t choose_level(const std::vector<LodLevel> &levels, double allowed, bool textured) {
    std::size_t chosen = 0;
    for (std::size_t i = 1; i < levels.size(); ++i)
        if (levels[i].error <= allowed && (levels[i].keeps_texture || !textured) &&
            levels[i].count < levels[chosen].count)
            chosen = i;
    return chosen;
}

} // namespace animator
