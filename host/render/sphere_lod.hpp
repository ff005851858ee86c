// Coarser levels of a sphere's mesh than an edge-collapse simplifier finds: a UV sphere crowds its
// vertices at the poles, and meshoptimizer's quadric collapses of one keep that shape, so its
// levels of a few hundred triangles stray from the sphere 3 to 5 times as far as a mesh of as many
// even triangles does (sphere.obj: 248 triangles 0.118 of the radius, 496 triangles 0.030). Here a
// level is the convex hull of points spread evenly over the sphere (a Fibonacci lattice relaxed by
// Lloyd's method): on a sphere the hull is their Delaunay triangulation, triangles near
// equilateral. Its vertices are its own, normals along the radius, and pushed out of the sphere
// so that the level strays as far outside the mesh's surface as inside it: sphere.obj's level of
// 96 triangles strays 0.032 of the radius (its own vertices nearest a Fibonacci lattice, as
// before: 238 triangles for 0.032). They have no texture coordinates, so a level is for
// untextured models (LodLevel::keeps_texture false; docs/rendering.md, "Levels of detail").
#pragma once

#include "assets/mesh.hpp"

#include <cstdint>
#include <vector>

namespace animator {

struct SphereLevel {
    std::vector<glm::dvec3> positions;    // on a sphere about the mesh's bounding one's centre
    std::vector<glm::dvec3> normals;      // along the radius, out or in as the mesh's normals are
    std::vector<std::uint32_t> triangles; // three indices each into positions, wound as the mesh's
};

// A level of `mesh` (whose vertices lie on its bounding sphere: approximates_sphere) of
// `vertices` vertices; empty (no triangles) when fewer than four.
SphereLevel sphere_even_level(const Mesh &mesh, std::size_t vertices);

} // namespace animator
