// Exact time of first contact between two rigid triangle meshes that translate on parabolic paths
// without rotating (seed, "Collision Detection": the vertex-face, face-vertex, edge-face and
// face-edge tests between two models, made exact; for translating bodies the first contact of an
// edge with a face is on the face's boundary edges, so edge-face and face-edge become edge-edge).
// Each mesh carries a bounding volume hierarchy over its triangles (the seed's reference [4]), and
// a brute-force version that tests every feature pair is kept as the oracle for it.
//
// Contact rules, shared by both versions so that they give bit-identical answers:
// - A contact is the moment a separation function reaches zero from above: a vertex's signed
//   distance to a face's plane (with the vertex inside the triangle, inclusive), or the signed
//   distance between two edges' lines (with both segment parameters in [0, 1]). A quadratic in t
//   for parabolic relative motion; its root is exact to the last bit (the closed form brackets
//   it, bisection of the few doubles around it settles it, as first_contact does).
// - A feature already touching at t = 0 counts only if approaching (or pressed in by the relative
//   acceleration with no relative velocity: a resting contact). Touching and separating (the
//   step after a bounce), or sliding in the plane, is no contact. "Touching" allows 1e-12 of the
//   scene's size either way: where the bodies are after advancing to a contact is rounded.
// - Faces of a closed mesh (every edge shared by two triangles in opposite directions) are
//   one-sided: their back is the body's inside (a closed mesh turned inside out is a cavity, a
//   room whose walls are met from within). Faces of an open mesh (a floor, a sheet) are
//   two-sided: met first from the side the vertex is on at t = 0 (when touching the plane, the
//   side its body's center is on: a box resting on a floor sheet is above it), and, if the
//   vertex passes the plane beside the triangle, from the other side on its way back.
// - An edge pair counts only where the two edges can touch without the bodies overlapping (their
//   normal arcs cross on the Gauss map, Gregorius's Minkowski-face test): an edge between two
//   coplanar triangles, or a concave edge of a closed mesh, takes no part. Without this, a body
//   sliding on a triangulated floor would "hit" every internal edge it crosses.
// - Likewise a vertex counts against a face only if its own mesh lies on the face's side around
//   it (every edge from it points away from the face or along it): a vertex sliding past a
//   face's rim, such as a floor's vertex gliding under a box, does not "hit" the box's side.
// - A touch is no contact where the bodies also share a plane of one of the faces around it that
//   the motion does not approach: a box sliding onto another box (or floor tile) of the same
//   height touches its top edge "head on", but slides on over its top.
// - Parallel edges are skipped (their contacts are vertex-face ones).
#pragma once

#include "time_of_impact.hpp"

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace physics_custom {

// A rigid mesh, built once per model and again when its orientation or scale changes. Its world
// vertices at time t are path.at(t) + vertices[i].
struct MeshShape {
    std::vector<glm::dvec3> vertices; // world-oriented, relative to the reference point
    std::vector<std::array<uint32_t, 3>> triangles; // counter-clockwise seen from outside
    std::vector<std::array<uint32_t, 2>> edges;     // unique undirected edges, lower index first

    // Derived by build().
    std::vector<glm::dvec3> normals; // unit, towards outside (counter-clockwise); 0: degenerate
    bool closed = false;             // faces one-sided (see the contact rules above)

    // Where an edge can be touched by another edge: the unit normals n (pointing from this mesh
    // outwards) of the planes through it that keep the mesh on one side, all perpendicular to it.
    enum class EdgeReach : uint8_t {
        none,    // coplanar triangles or a concave edge of a closed mesh: never
        bounded, // n . a >= 0 and n . b >= 0: the arc between the two faces' normals (or their
                 // opposites, for a sheet's valley), or the half-plane beyond a sheet's rim (b = 0)
        any,     // non-manifold or beside a degenerate triangle: no restriction
    };
    struct EdgeCone {
        EdgeReach reach = EdgeReach::any;
        glm::dvec3 a{0.0}, b{0.0};
    };
    std::vector<EdgeCone> edge_cones; // per edge

    std::vector<Box> triangle_boxes, edge_boxes;
    // Vertex v's neighbours along edges: neighbors[neighbor_begin[v] .. neighbor_begin[v + 1]),
    // and the triangles around it: fan[fan_begin[v] .. fan_begin[v + 1]).
    std::vector<uint32_t> neighbor_begin, neighbors, fan_begin, fan;

    // The hierarchy: nodes[0] is the root, a node's children are adjacent (first, first + 1).
    // Each leaf holds up to 4 triangles (order[first .. first + count)) and owns the vertices
    // and edges that it is the first leaf to reference, so that every feature is tested once.
    struct Node {
        Box box;
        uint32_t first = 0;                        // leaf: into `order`; inner: the first child
        uint32_t count = 0;                        // leaf: its triangles; 0 for an inner node
        uint32_t vertex_begin = 0, vertex_end = 0; // leaf: its range of owned_vertices
        uint32_t edge_begin = 0, edge_end = 0;     // leaf: its range of owned_edges
        bool leaf() const { return count > 0; }
    };
    std::vector<Node> nodes;
    std::vector<uint32_t> order;          // triangle indices, leaf by leaf
    std::vector<uint32_t> owned_vertices; // every vertex used by a triangle, once, leaf by leaf
    std::vector<uint32_t> owned_edges;    // every edge, once, leaf by leaf

    // Throws std::invalid_argument for a triangle index out of range. Vertices that no triangle
    // uses take no part in contacts.
    static MeshShape build(std::vector<glm::dvec3> vertices,
                           std::vector<std::array<uint32_t, 3>> triangles);

    // The box around the vertices that triangles use (relative to the reference point); an empty
    // mesh gives the box at the origin.
    Box bounds() const;
};

// What a query did: feature pairs tested (vertex-face + face-vertex + edge-edge) and node pairs
// whose swept boxes overlapped.
struct PairStats {
    uint64_t primitive_tests = 0;
    uint64_t nodes_visited = 0;
};

// The first contact of A (moving along pa) and B (moving along pb) within [0, t_max]: its time,
// the point of contact (world, at that time) and the unit normal pointing from B towards A: the
// face's normal for a vertex-face or face-vertex contact, the normalised cross product of the two
// edges for an edge-edge one. Contacts within 1e-12 t_max of the earliest count as simultaneous:
// among them a face normal wins over an edge-edge one (then the earliest, then the lowest feature
// indices), and the time reported is the earliest. None for a negative or NaN t_max.
//
// mesh_mesh descends both hierarchies together, best first, visiting a node pair only when A's
// box, swept by the relative displacement over [0, the earliest contact so far and its window],
// overlaps B's. mesh_mesh_brute tests every vertex of A against every face of B, every vertex of
// B against every face of A and every edge of A against every edge of B. Both give the same
// answer, to the bit.
std::optional<Contact> mesh_mesh(const MeshShape &a, const Path &pa, const MeshShape &b,
                                 const Path &pb, double t_max, PairStats *stats = nullptr);
std::optional<Contact> mesh_mesh_brute(const MeshShape &a, const Path &pa, const MeshShape &b,
                                       const Path &pb, double t_max, PairStats *stats = nullptr);

} // namespace physics_custom
