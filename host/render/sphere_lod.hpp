// Coarser levels of a sphere's mesh than an edge-collapse simplifier finds: a UV sphere crowds its
// vertices at the poles, and meshoptimizer's quadric collapses of one keep that shape, so its
// levels of a few hundred triangles stray from the sphere 3 to 5 times as far as a mesh of as many
// even triangles does (sphere.obj: 248 triangles 0.118 of the radius, 496 triangles 0.030). Here a
// level is the convex hull of some of the mesh's own vertices, chosen spread evenly over the
// sphere (the nearest to each point of a Fibonacci lattice): on a sphere the hull is its Delaunay
// triangulation, triangles near equilateral, and such a level of 248 triangles strays about 0.03
// of the radius. The level indexes the mesh's vertices (positions and normals as they are); where
// the mesh has split a vertex for its texture coordinates (a UV sphere's seam and poles), the
// hull's triangles take one of the copies, so a level does not keep the texture's seam: it is for
// untextured models (LodLevel::keeps_texture false; docs/rendering.md, "Levels of detail").
#pragma once

#include "assets/mesh.hpp"

#include <cstdint>
#include <vector>

namespace animator {

// A level of `mesh` (whose vertices lie on its bounding sphere: approximates_sphere) over about
// `vertices` of its vertices: triangles (three indices each into mesh.positions) wound as the
// mesh's are. Empty when fewer than four distinct vertices are found.
std::vector<std::uint32_t> sphere_hull_level(const Mesh &mesh, std::size_t vertices);

} // namespace animator
