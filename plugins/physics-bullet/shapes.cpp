#include "shapes.hpp"

#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btBvhTriangleMeshShape.h>
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletCollision/CollisionShapes/btTriangleIndexVertexArray.h>
#include <BulletCollision/Gimpact/btGImpactShape.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace physics_bullet {

namespace {

glm::dvec3 vertex(const ani_mesh_view &mesh, uint32_t k) {
    const double *p = mesh.positions + 3 * static_cast<size_t>(k);
    return {p[0], p[1], p[2]};
}

std::vector<glm::dvec3> scaled_vertices(const ani_mesh_view &mesh, const glm::dvec3 &scale) {
    std::vector<glm::dvec3> out(mesh.vertex_count);
    for (uint32_t k = 0; k < mesh.vertex_count; ++k) out[k] = vertex(mesh, k) * scale;
    return out;
}

struct Plane {
    glm::dvec3 n; // unit, outward
    double d;     // n . x = d on the plane
};

// The planes of the non-degenerate triangles, each once.
std::vector<Plane> face_planes(const std::vector<glm::dvec3> &v, const ani_mesh_view &mesh,
                               double size) {
    std::vector<Plane> planes;
    for (uint32_t t = 0; t < mesh.triangle_count; ++t) {
        const uint32_t *i = mesh.triangles + 3 * static_cast<size_t>(t);
        const glm::dvec3 c = glm::cross(v[i[1]] - v[i[0]], v[i[2]] - v[i[0]]);
        const double len = glm::length(c);
        if (!(len > 1e-12 * size * size)) continue;
        const Plane p{c / len, glm::dot(c / len, v[i[0]])};
        const bool seen = std::any_of(planes.begin(), planes.end(), [&](const Plane &q) {
            return glm::dot(p.n, q.n) > 1.0 - 1e-12 && std::abs(p.d - q.d) <= 1e-9 * size;
        });
        if (!seen) planes.push_back(p);
    }
    return planes;
}

// The corners of the convex polytope bounded by the planes moved inward by `margin`: every
// intersection of three planes that lies inside all of them (to a tolerance relative to `size`).
std::vector<glm::dvec3> shrunk_corners(const std::vector<Plane> &planes, double margin,
                                       double size) {
    std::vector<glm::dvec3> corners;
    const size_t n = planes.size();
    const double tolerance = 1e-9 * size;
    for (size_t i = 0; i < n; ++i)
        for (size_t j = i + 1; j < n; ++j)
            for (size_t k = j + 1; k < n; ++k) {
                const glm::dvec3 &a = planes[i].n, &b = planes[j].n, &c = planes[k].n;
                const glm::dvec3 bc = glm::cross(b, c), ca = glm::cross(c, a),
                                 ab = glm::cross(a, b);
                const double det = glm::dot(a, bc);
                if (std::abs(det) < 1e-9) continue;
                const glm::dvec3 x = ((planes[i].d - margin) * bc + (planes[j].d - margin) * ca +
                                      (planes[k].d - margin) * ab) /
                                     det;
                const bool inside = std::all_of(planes.begin(), planes.end(), [&](const Plane &p) {
                    return glm::dot(p.n, x) - (p.d - margin) <= tolerance;
                });
                const bool known =
                    std::any_of(corners.begin(), corners.end(), [&](const glm::dvec3 &y) {
                        return glm::length(x - y) <= tolerance;
                    });
                if (inside && !known) corners.push_back(x);
            }
    return corners;
}

// Shape::flat (shapes.hpp): inner edges and corners of flat regions, vertices taken by position.
void mark_flat_edges(Shape &s, const std::vector<glm::dvec3> &v, double size) {
    const size_t n = s.indices.size() / 3;
    std::map<std::array<double, 3>, uint32_t> welded;
    std::vector<uint32_t> id(v.size());
    for (size_t k = 0; k < v.size(); ++k)
        id[k] =
            welded.emplace(std::array<double, 3>{v[k].x, v[k].y, v[k].z}, static_cast<uint32_t>(k))
                .first->second;
    auto vertex_of = [&](size_t t, int k) {
        return id[static_cast<size_t>(s.indices[3 * t + static_cast<size_t>(k)])];
    };
    std::vector<glm::dvec3> normals(n, glm::dvec3(0.0));
    for (size_t t = 0; t < n; ++t) {
        const glm::dvec3 a = v[vertex_of(t, 0)], b = v[vertex_of(t, 1)], c = v[vertex_of(t, 2)];
        const glm::dvec3 f = glm::cross(b - a, c - a);
        const double len = glm::length(f);
        if (len > 1e-12 * size * size) normals[t] = f / len;
    }
    std::map<std::pair<uint32_t, uint32_t>, std::vector<size_t>> edges;
    for (size_t t = 0; t < n; ++t)
        for (int k = 0; k < 3; ++k) {
            uint32_t a = vertex_of(t, k), b = vertex_of(t, (k + 1) % 3);
            if (b < a) std::swap(a, b);
            edges[{a, b}].push_back(t);
        }
    auto flat_edge = [&](uint32_t a, uint32_t b) {
        if (b < a) std::swap(a, b);
        const auto it = edges.find({a, b});
        if (it == edges.end() || it->second.size() != 2) return false;
        const glm::dvec3 &p = normals[it->second[0]], &q = normals[it->second[1]];
        return glm::length(p) > 0.0 && glm::length(q) > 0.0 && glm::dot(p, q) > 1.0 - 1e-9;
    };
    // A corner is inner when every edge at it is.
    std::vector<char> vertex_flat(v.size(), 1);
    for (const auto &[edge, triangles] : edges)
        if (!flat_edge(edge.first, edge.second))
            vertex_flat[edge.first] = vertex_flat[edge.second] = 0;
    s.flat.assign(n, 0);
    for (size_t t = 0; t < n; ++t)
        for (int k = 0; k < 3; ++k) {
            if (flat_edge(vertex_of(t, k), vertex_of(t, (k + 1) % 3)))
                s.flat[t] = static_cast<uint8_t>(s.flat[t] | (1u << k));
            if (vertex_flat[vertex_of(t, k)])
                s.flat[t] = static_cast<uint8_t>(s.flat[t] | (1u << (3 + k)));
        }
}

double reach_of(const std::vector<glm::dvec3> &v) {
    double r = 0.0;
    for (const glm::dvec3 &p : v) r = std::max(r, glm::length(p));
    return r;
}

} // namespace

Shape::Shape() = default;
Shape::~Shape() {
    shape.reset(); // before the triangles it points into
    triangles.reset();
}

MeshInfo analyse_mesh(const ani_mesh_view &mesh) {
    MeshInfo info;
    const std::vector<glm::dvec3> v = scaled_vertices(mesh, glm::dvec3(1.0));
    info.reach = reach_of(v);
    glm::dvec3 lo(0.0), hi(0.0);
    if (!v.empty()) lo = hi = v[0];
    for (const glm::dvec3 &p : v) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const double size = glm::length(hi - lo);
    // Closed: each undirected edge used by exactly two triangles, vertices taken by position (a
    // loader may split a corner for its normals or texture coordinates).
    std::map<std::array<double, 3>, uint32_t> welded;
    std::vector<uint32_t> canonical(mesh.vertex_count);
    for (uint32_t k = 0; k < mesh.vertex_count; ++k)
        canonical[k] =
            welded.emplace(std::array<double, 3>{v[k].x, v[k].y, v[k].z}, k).first->second;
    std::map<std::pair<uint32_t, uint32_t>, int> edges;
    for (uint32_t t = 0; t < mesh.triangle_count; ++t)
        for (int e = 0; e < 3; ++e) {
            uint32_t a =
                canonical[mesh.triangles[3 * static_cast<size_t>(t) + static_cast<size_t>(e)]];
            uint32_t b = canonical[mesh.triangles[3 * static_cast<size_t>(t) +
                                                  static_cast<size_t>((e + 1) % 3)]];
            if (a == b) continue;
            if (b < a) std::swap(a, b);
            ++edges[{a, b}];
        }
    info.closed = !edges.empty() && std::all_of(edges.begin(), edges.end(),
                                                [](const auto &e) { return e.second == 2; });
    const std::vector<Plane> planes = face_planes(v, mesh, size > 0.0 ? size : 1.0);
    info.has_area = !planes.empty();
    if (!info.closed || planes.size() < 4) return info;
    const double tolerance = 1e-6 * size;
    info.convex = std::all_of(planes.begin(), planes.end(), [&](const Plane &p) {
        return std::all_of(v.begin(), v.end(), [&](const glm::dvec3 &x) {
            return glm::dot(p.n, x) - p.d <= tolerance;
        });
    });
    return info;
}

bool inside_convex(const ani_mesh_view &mesh, const glm::dvec3 &p) {
    for (uint32_t t = 0; t < mesh.triangle_count; ++t) {
        const uint32_t *i = mesh.triangles + 3 * static_cast<size_t>(t);
        const glm::dvec3 a = vertex(mesh, i[0]);
        const glm::dvec3 n = glm::cross(vertex(mesh, i[1]) - a, vertex(mesh, i[2]) - a);
        if (glm::dot(n, p - a) >= 0.0 && glm::length(n) > 0.0) return false;
    }
    return mesh.triangle_count > 0;
}

std::unique_ptr<Shape> sphere_shape(double radius) {
    auto s = std::make_unique<Shape>();
    s->kind = ShapeKind::kSphere;
    s->scale = glm::dvec3(1.0);
    s->reach = s->inner = s->margin = radius;
    s->shape = std::make_unique<btSphereShape>(radius);
    return s;
}

// A convex hull keeps Bullet's collision margin outside its points; with few face planes the
// hull is shrunk by the margin first, so its faces stay where the mesh's are (only its edges and
// corners are rounded by the margin: `largest`, at most a fifth of its inner radius).
std::unique_ptr<Shape> hull_shape(const ani_mesh_view &mesh, const glm::dvec3 &scale,
                                  double largest, const glm::dvec3 &offset) {
    auto s = std::make_unique<Shape>();
    s->kind = ShapeKind::kHull;
    s->scale = scale;
    std::vector<glm::dvec3> v = scaled_vertices(mesh, scale);
    for (glm::dvec3 &p : v) p -= offset;
    s->reach = reach_of(v);
    glm::dvec3 centroid(0.0);
    for (const glm::dvec3 &p : v) centroid += p;
    centroid /= static_cast<double>(std::max<size_t>(v.size(), 1));
    const std::vector<Plane> planes = face_planes(v, mesh, std::max(2.0 * s->reach, 1e-300));
    double inradius = s->reach;
    for (const Plane &p : planes) inradius = std::min(inradius, p.d - glm::dot(p.n, centroid));
    s->inner = std::max(0.0, inradius);
    auto hull = std::make_unique<btConvexHullShape>();
    if (planes.size() <= 40 && inradius > 0.0) {
        const double margin = std::min(largest, 0.2 * inradius);
        for (const glm::dvec3 &p : shrunk_corners(planes, margin, s->reach))
            hull->addPoint(btVector3(p.x, p.y, p.z), false);
        if (hull->getNumPoints() >= 4)
            s->margin = margin;
        else
            hull = std::make_unique<btConvexHullShape>();
    }
    if (hull->getNumPoints() == 0) {
        for (const glm::dvec3 &p : v) hull->addPoint(btVector3(p.x, p.y, p.z), false);
        s->margin = std::min(largest, 1e-3 * s->reach);
    }
    hull->setMargin(s->margin);
    hull->recalcLocalAabb();
    s->shape = std::move(hull);
    return s;
}

std::unique_ptr<Shape> box_shape(const ani_mesh_view &mesh, const glm::dvec3 &scale, double largest,
                                 const glm::dvec3 &offset) {
    std::vector<glm::dvec3> v = scaled_vertices(mesh, scale);
    if (v.empty() || mesh.triangle_count == 0) return nullptr;
    glm::dvec3 lo = v[0] - offset, hi = lo;
    for (glm::dvec3 &p : v) {
        p -= offset;
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const glm::dvec3 half = 0.5 * (hi - lo);
    const double size = glm::length(hi - lo);
    const double tolerance = 1e-9 * size;
    if (!(std::min({half.x, half.y, half.z}) > 1e-6 * size) ||
        glm::length(lo + hi) > 2.0 * tolerance)
        return nullptr;
    // Every vertex a corner of the bounds, and every triangle on one of the bounds' faces (a
    // closed mesh of such triangles is the box itself).
    auto at_bound = [&](double x, double l, double h) {
        return std::abs(x - l) <= tolerance || std::abs(x - h) <= tolerance;
    };
    for (const glm::dvec3 &p : v)
        if (!at_bound(p.x, lo.x, hi.x) || !at_bound(p.y, lo.y, hi.y) || !at_bound(p.z, lo.z, hi.z))
            return nullptr;
    for (uint32_t t = 0; t < mesh.triangle_count; ++t) {
        const uint32_t *i = mesh.triangles + 3 * static_cast<size_t>(t);
        bool on_face = false;
        for (int axis = 0; axis < 3 && !on_face; ++axis)
            for (double side : {lo[axis], hi[axis]})
                on_face = on_face || (std::abs(v[i[0]][axis] - side) <= tolerance &&
                                      std::abs(v[i[1]][axis] - side) <= tolerance &&
                                      std::abs(v[i[2]][axis] - side) <= tolerance);
        if (!on_face) return nullptr;
    }
    auto s = std::make_unique<Shape>();
    s->kind = ShapeKind::kBox;
    s->scale = scale;
    s->reach = glm::length(half);
    s->inner = std::min({half.x, half.y, half.z});
    // The margin lies inside the box's faces (btBoxShape keeps them at the half extents), and
    // rounds its edges and corners: at most a fifth of its smallest half extent.
    s->margin = std::min(largest, 0.2 * s->inner);
    auto box = std::make_unique<btBoxShape>(btVector3(half.x, half.y, half.z));
    box->setMargin(s->margin);
    s->shape = std::move(box);
    return s;
}

std::unique_ptr<Shape> triangle_shape(const ani_mesh_view &mesh, const glm::dvec3 &scale,
                                      bool moving, const glm::dvec3 &offset) {
    auto s = std::make_unique<Shape>();
    s->kind = moving ? ShapeKind::kGImpactTriangles : ShapeKind::kBvhTriangles;
    s->scale = scale;
    std::vector<glm::dvec3> v = scaled_vertices(mesh, scale);
    for (glm::dvec3 &p : v) p -= offset;
    s->reach = reach_of(v);
    glm::dvec3 lo(0.0), hi(0.0);
    if (!v.empty()) lo = hi = v[0];
    for (const glm::dvec3 &p : v) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
        s->vertices.insert(s->vertices.end(), {p.x, p.y, p.z});
    }
    const glm::dvec3 extent = hi - lo;
    s->inner = 0.25 * std::min({extent.x, extent.y, extent.z});
    for (uint32_t k = 0; k < 3 * mesh.triangle_count; ++k)
        s->indices.push_back(static_cast<int>(mesh.triangles[k]));
    btIndexedMesh part;
    part.m_numTriangles = static_cast<int>(mesh.triangle_count);
    part.m_triangleIndexBase = reinterpret_cast<const unsigned char *>(s->indices.data());
    part.m_triangleIndexStride = 3 * static_cast<int>(sizeof(int));
    part.m_numVertices = static_cast<int>(mesh.vertex_count);
    part.m_vertexBase = reinterpret_cast<const unsigned char *>(s->vertices.data());
    part.m_vertexStride = 3 * static_cast<int>(sizeof(double));
    part.m_indexType = PHY_INTEGER;
    part.m_vertexType = PHY_DOUBLE;
    s->triangles = std::make_unique<btTriangleIndexVertexArray>();
    s->triangles->addIndexedMesh(part, PHY_INTEGER);
    if (moving) {
        auto g = std::make_unique<btGImpactMeshShape>(s->triangles.get());
        s->margin = std::min(0.04, 1e-3 * s->reach);
        g->setMargin(s->margin);
        g->updateBound();
        s->shape = std::move(g);
    } else {
        auto b = std::make_unique<btBvhTriangleMeshShape>(s->triangles.get(), true, true);
        s->margin = b->getMargin();
        s->shape = std::move(b);
        mark_flat_edges(*s, v, s->reach);
    }
    return s;
}

namespace {
glm::dvec3 corner(const Shape &s, int triangle, int k) {
    const size_t i =
        static_cast<size_t>(s.indices[3 * static_cast<size_t>(triangle) + static_cast<size_t>(k)]);
    return {s.vertices[3 * i], s.vertices[3 * i + 1], s.vertices[3 * i + 2]};
}

double to_segment(const glm::dvec3 &p, const glm::dvec3 &a, const glm::dvec3 &b) {
    const glm::dvec3 e = b - a;
    const double len2 = glm::dot(e, e);
    const double s = len2 > 0.0 ? std::clamp(glm::dot(p - a, e) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + s * e));
}
} // namespace

glm::dvec3 corner_of(const Shape &shape, int triangle) {
    return corner(shape, triangle, 0);
}

bool inner_edge_contact(const Shape &shape, int index, const glm::dvec3 &point,
                        const glm::dvec3 &normal, glm::dvec3 *face_normal) {
    if (index < 0 || static_cast<size_t>(index) >= shape.flat.size()) return false;
    const uint8_t flags = shape.flat[static_cast<size_t>(index)];
    if (flags == 0) return false;
    const glm::dvec3 c[3] = {corner(shape, index, 0), corner(shape, index, 1),
                             corner(shape, index, 2)};
    const glm::dvec3 face = glm::cross(c[1] - c[0], c[2] - c[0]);
    const double len = glm::length(face);
    if (!(len > 0.0) || std::abs(glm::dot(face / len, normal)) >= 1.0 - 1e-9) return false;
    if (face_normal) *face_normal = face / len;
    const double tolerance = 1e-6 * std::max(shape.reach, 1e-300);
    for (int k = 0; k < 3; ++k)
        if (glm::length(point - c[k]) <= tolerance) return (flags >> (3 + k)) & 1;
    for (int k = 0; k < 3; ++k)
        if (to_segment(point, c[k], c[(k + 1) % 3]) <= tolerance) return (flags >> k) & 1;
    return false;
}

std::string Shape::describe() const {
    std::ostringstream out;
    switch (kind) {
    case ShapeKind::kSphere:
        out << "sphere shape (radius " << reach << ")";
        break;
    case ShapeKind::kBox: {
        const btVector3 h =
            static_cast<const btBoxShape *>(shape.get())->getHalfExtentsWithMargin();
        out << "box shape (" << 2.0 * h.x() << " x " << 2.0 * h.y() << " x " << 2.0 * h.z()
            << ", margin " << margin << ")";
        break;
    }
    case ShapeKind::kHull:
        out << "convex hull ("
            << static_cast<const btConvexHullShape *>(shape.get())->getNumPoints()
            << " points, margin " << margin << ")";
        break;
    case ShapeKind::kBvhTriangles:
        out << "BVH triangle mesh (" << indices.size() / 3 << " triangles, two-sided)";
        break;
    case ShapeKind::kGImpactTriangles:
        out << "GImpact triangle mesh (" << indices.size() / 3 << " triangles, margin " << margin
            << ")";
        break;
    }
    return out.str();
}

const char *Shape::count_name() const {
    switch (kind) {
    case ShapeKind::kSphere:
        return "sphere shapes";
    case ShapeKind::kBox:
        return "box shapes";
    case ShapeKind::kHull:
        return "convex hulls";
    default:
        return "triangle meshes";
    }
}

glm::dvec3 centre_of_mass(const ani_mesh_view &mesh, const glm::dvec3 &scale) {
    double volume = 0.0;
    glm::dvec3 moment(0.0);
    const auto at = [&](uint32_t k) {
        const double *p = mesh.positions + 3 * static_cast<size_t>(k);
        return scale * glm::dvec3(p[0], p[1], p[2]);
    };
    for (uint32_t t = 0; t < mesh.triangle_count; ++t) {
        const glm::dvec3 a = at(mesh.triangles[3 * t]), b = at(mesh.triangles[3 * t + 1]),
                         c = at(mesh.triangles[3 * t + 2]);
        const double v = glm::dot(a, glm::cross(b, c)) / 6.0;
        volume += v;
        moment += v * (a + b + c) / 4.0;
    }
    return volume > 0.0 ? moment / volume : glm::dvec3(0.0);
}

} // namespace physics_bullet
