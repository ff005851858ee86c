#include "render/sphere_lod.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <tuple>
#include <utility>

namespace animator {

namespace {

// The mesh's vertices in a uniform grid of cubes, for the nearest one to a point.
class VertexGrid {
  public:
    VertexGrid(const Mesh &mesh, double cell) : mesh_(mesh), cell_(cell) {
        for (std::size_t i = 0; i < mesh.positions.size(); ++i)
            cells_[cell_of(mesh.positions[i])].push_back(static_cast<std::uint32_t>(i));
    }

    // The nearest vertex to p: the cells around p's, shell after shell, until no farther cell
    // can hold a nearer one.
    std::uint32_t nearest(const glm::dvec3 &p) const {
        const glm::ivec3 home = cell_of(p);
        double best = std::numeric_limits<double>::max();
        std::uint32_t found = 0;
        for (int r = 0; best > (r - 1) * cell_; ++r)
            for (int x = -r; x <= r; ++x)
                for (int y = -r; y <= r; ++y)
                    for (int z = -r; z <= r; ++z) {
                        if (std::max({std::abs(x), std::abs(y), std::abs(z)}) != r) continue;
                        const auto cell = cells_.find(home + glm::ivec3(x, y, z));
                        if (cell == cells_.end()) continue;
                        for (std::uint32_t i : cell->second) {
                            const double d = glm::length(mesh_.positions[i] - p);
                            if (d < best) {
                                best = d;
                                found = i;
                            }
                        }
                    }
        return found;
    }

  private:
    struct Less {
        bool operator()(const glm::ivec3 &a, const glm::ivec3 &b) const {
            return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
        }
    };
    glm::ivec3 cell_of(const glm::dvec3 &p) const {
        return glm::ivec3(static_cast<int>(std::floor(p.x / cell_)),
                          static_cast<int>(std::floor(p.y / cell_)),
                          static_cast<int>(std::floor(p.z / cell_)));
    }

    const Mesh &mesh_;
    double cell_;
    std::map<glm::ivec3, std::vector<std::uint32_t>, Less> cells_;
};

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

std::vector<std::uint32_t> sphere_hull_level(const Mesh &mesh, std::size_t vertices) {
    const glm::dvec3 centre = mesh.bound_center;
    const double radius = mesh.bound_radius;
    if (vertices < 4 || mesh.positions.empty() || !(radius > 0.0)) return {};
    // The mesh's n vertices lie about r sqrt(4 pi / n) apart: cells twice that, so that a
    // point's nearest vertex is mostly in its own cell or the next.
    const double spacing =
        radius * std::sqrt(4.0 * M_PI / static_cast<double>(mesh.positions.size()));
    const VertexGrid grid(mesh, 2.0 * spacing);
    const double golden = M_PI * (3.0 - std::sqrt(5.0));
    std::vector<std::uint32_t> chosen; // mesh vertices, once each
    std::set<std::uint32_t> taken;
    std::vector<glm::dvec3> points;
    for (std::size_t i = 0; i < vertices; ++i) {
        const double y = 1.0 - (2.0 * static_cast<double>(i) + 1.0) / static_cast<double>(vertices);
        const double ring = std::sqrt(std::max(0.0, 1.0 - y * y));
        const double angle = golden * static_cast<double>(i);
        const glm::dvec3 at =
            centre + radius * glm::dvec3(ring * std::cos(angle), y, ring * std::sin(angle));
        const std::uint32_t v = grid.nearest(at);
        if (!taken.insert(v).second) continue;
        chosen.push_back(v);
        points.push_back(mesh.positions[v] - centre);
    }
    // Copies of one vertex (a seam's) lie within rounding of each other: on the hull's faces,
    // so not added twice.
    const std::vector<Face> hull = convex_hull(points, 1e-9 * radius);
    if (hull.empty()) return {};
    // Wound as the mesh: its triangles' normals by their corners' order point out of the sphere
    // (counter-clockwise seen from outside) or all in.
    double outward = 0.0;
    for (std::size_t t = 0; t + 2 < mesh.triangles.size(); t += 3) {
        const glm::dvec3 &a = mesh.positions[mesh.triangles[t]],
                         &b = mesh.positions[mesh.triangles[t + 1]],
                         &c = mesh.positions[mesh.triangles[t + 2]];
        outward += glm::dot(glm::cross(b - a, c - a), a - centre);
    }
    std::vector<std::uint32_t> indices;
    indices.reserve(hull.size() * 3);
    for (const Face &f : hull) {
        indices.push_back(chosen[f.a]);
        if (outward >= 0.0) {
            indices.push_back(chosen[f.b]);
            indices.push_back(chosen[f.c]);
        } else {
            indices.push_back(chosen[f.c]);
            indices.push_back(chosen[f.b]);
        }
    }
    return indices;
}

} // namespace animator
