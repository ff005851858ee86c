// Collision shapes for the models (docs/physics-bullet.md, "Shapes"): a sphere for a mesh that is
// a sphere under a uniform scale, a box for a mesh that is a box along its own axes, a convex hull
// for any other closed convex mesh, and its triangles for any other mesh: a BVH triangle mesh when
// the model never moves, GImpact when it does.
#pragma once

#include <animator/physics.h>
#include <glm/vec3.hpp>

#include <memory>
#include <string>
#include <vector>

class btCollisionShape;
class btTriangleIndexVertexArray;

namespace physics_bullet {

// What a mesh is, in the model's own coordinates.
struct MeshInfo {
    bool closed = false;   // every edge belongs to exactly two triangles
    bool convex = false;   // closed, and every vertex on or behind every face's plane
    bool has_area = false; // at least one triangle that is not degenerate
    double reach = 0.0;    // the farthest vertex from the model's origin
};

// Checks the mesh: every vertex on or behind every face plane within 1e-6 of the mesh's size.
MeshInfo analyse_mesh(const ani_mesh_view &mesh);

// Whether p (in the mesh's own coordinates) is behind every face plane of the mesh: inside it,
// for a closed convex mesh.
bool inside_convex(const ani_mesh_view &mesh, const glm::dvec3 &p);

// The centre of mass of a closed mesh under a scale, as a uniform solid (the signed
// tetrahedra from the origin to each triangle); the origin when it has no volume.
glm::dvec3 centre_of_mass(const ani_mesh_view &mesh, const glm::dvec3 &scale);

enum class ShapeKind { kSphere, kBox, kHull, kBvhTriangles, kGImpactTriangles };

// A Bullet shape with what it points into, for a mesh under a scale (rotation and translation
// are the body's transform).
struct Shape {
    Shape();
    ~Shape();
    Shape(const Shape &) = delete;
    Shape &operator=(const Shape &) = delete;

    ShapeKind kind = ShapeKind::kSphere;
    glm::dvec3 scale{1.0};
    double reach = 0.0; // bounding radius about the model's origin, scaled
    double inner = 0.0; // a radius that fits inside the shape (for the CCD sweep)
    double margin = 0.0;
    std::vector<double> vertices; // for triangle meshes: scaled, 3 per vertex
    std::vector<int> indices;
    // For a BVH triangle mesh, per triangle: bit k (0..2) when its edge from corner k to corner
    // k + 1 is shared with exactly one coplanar triangle (an inner edge of a flat region), bit
    // 3 + k when every edge at corner k is such an edge.
    std::vector<uint8_t> flat;
    std::unique_ptr<btTriangleIndexVertexArray> triangles;
    std::unique_ptr<btCollisionShape> shape;

    // "sphere shape (radius 0.5)", "convex hull (8 vertices)", ...
    std::string describe() const;
    // The name of the count it adds to.
    const char *count_name() const;
};

std::unique_ptr<Shape> sphere_shape(double radius);
// `offset`: a point of the mesh's own frame (scaled) that becomes the shape's origin (a body
// that turns about its centre of mass).
std::unique_ptr<Shape> hull_shape(const ani_mesh_view &mesh, const glm::dvec3 &scale,
                                  double margin = 0.04, const glm::dvec3 &offset = glm::dvec3(0.0));
// A box shape for a mesh that is a box along its own axes (eight corners, its faces the box's),
// centred on `offset` under the scale; null for any other mesh. Bullet meets two boxes by
// clipping one's face against the other's (btBoxBoxDetector: the whole face in contact at every
// step), where two hulls are met by one point per step: a box resting on a box, or sliding on
// one, is then held at its four corners from the first step (physics-bullet.md, "Shapes").
std::unique_ptr<Shape> box_shape(const ani_mesh_view &mesh, const glm::dvec3 &scale,
                                 double margin = 0.04, const glm::dvec3 &offset = glm::dvec3(0.0));
std::unique_ptr<Shape> triangle_shape(const ani_mesh_view &mesh, const glm::dvec3 &scale,
                                      bool moving, const glm::dvec3 &offset = glm::dvec3(0.0));

// Whether a contact found at `point` (the mesh's own coordinates, scaled) on triangle `index`
// with normal `normal` (same frame) is an artefact of an inner edge or corner of a flat region:
// the normal is not the face's, and the point lies on an edge or corner that a coplanar
// neighbour shares, so the true contact is with the face's plane.
// `face` receives the triangle's unit normal.
bool inner_edge_contact(const Shape &shape, int index, const glm::dvec3 &point,
                        const glm::dvec3 &normal, glm::dvec3 *face);
// Corner 0 of a triangle of a triangle mesh shape (scaled, the mesh's own coordinates).
glm::dvec3 corner_of(const Shape &shape, int triangle);

} // namespace physics_bullet
