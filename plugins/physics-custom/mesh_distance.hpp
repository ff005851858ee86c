// Distances between triangle meshes placed in the world, for conservative advancement of
// models that turn under their keys (keyed_contact.hpp): the nearest points of two meshes'
// surfaces and the normal there. Brute force over every vertex-triangle and edge-edge pair,
// fine for the few small models that keys move.
#pragma once

#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace physics_custom {

// A mesh's vertices in world space, its triangles (3 indices each) and its edges (each once).
struct PlacedMesh {
    glm::dvec3 center{0.0}; // a point inside it, to orient normals when the meshes touch
    std::vector<glm::dvec3> vertices;
    const uint32_t *triangles = nullptr;
    std::size_t triangle_count = 0;
    const std::array<uint32_t, 2> *edges = nullptr;
    std::size_t edge_count = 0;
};

// The closest points c1 on segment p1q1 and c2 on p2q2 (Ericson, Real-Time Collision
// Detection 5.1.9).
void closest_on_segments(const glm::dvec3 &p1, const glm::dvec3 &q1, const glm::dvec3 &p2,
                         const glm::dvec3 &q2, glm::dvec3 &c1, glm::dvec3 &c2);

// The distance between the surfaces of a and b, the nearest points, and the unit normal there
// pointing from b towards a. Where they touch the nearest points coincide, so the normal comes
// from the features that touch: the face's normal for a vertex nearest to a face, the edges'
// cross product for two edges; where they are apart and nearest at a rim, the direction between
// the points.
double mesh_distance(const PlacedMesh &a, const PlacedMesh &b, glm::dvec3 &on_a, glm::dvec3 &on_b,
                     glm::dvec3 &normal);

// Whether the surfaces of a and b cross: an edge of one passes through a triangle of the other,
// its ends on either side of the triangle's plane by more than `tol` and through the triangle's
// inside by more than `tol` from each side. A box resting on a floor, or passing over a step's
// edge, only touches it: its edges lie in or end on the floor's plane, or meet a face on its rim.
// (Not seen: a mesh wholly inside another, and one sunk into another exactly aligned with it,
// every face in a plane of the other, where no edge crosses a face's inside.)
bool surfaces_cross(const PlacedMesh &a, const PlacedMesh &b, double tol);

// The unique undirected edges of a triangle list, lower index first.
std::vector<std::array<uint32_t, 2>> edges_of(const uint32_t *triangles,
                                              std::size_t triangle_count);

} // namespace physics_custom
