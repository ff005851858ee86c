// The test meshes. Conventions (docs/assets.md): metres, Y up, triangles counter-clockwise seen
// from outside, unit per-vertex normals, closed solids weld their positions.
#pragma once

#include "mesh.hpp"

#include <string>
#include <vector>

namespace animator::assetgen {

// UV sphere of radius 1; each pole is one position, so there are no degenerate triangles there.
Mesh uv_sphere(int stacks, int slices);
// Icosahedron with each triangle split into four `subdivisions` times, projected onto radius 1.
Mesh icosphere(int subdivisions);
// Axis-aligned cube from -1 to 1, flat normals, UVs 0..1 per face.
Mesh cube();
// The square -1..1 in X and Z at y = 0 split into cells x cells quads, facing +Y.
Mesh floor_grid(int cells);
// Radius 1 from y = -1 to 1, capped.
Mesh cylinder(int slices);
// Base of radius 1 at y = -1, apex at y = 1, capped.
Mesh cone(int slices);
// Axis Y, lying in the XZ plane.
Mesh torus(double major_radius, double minor_radius, int major_segments, int minor_segments);
// Five steps descending along +X; see the geometry comment in meshes.cpp.
Mesh stairs();

struct NamedMesh {
    std::string file; // e.g. "sphere.obj"
    std::string description;
    Mesh mesh;
};
std::vector<NamedMesh> all_meshes();

} // namespace animator::assetgen
