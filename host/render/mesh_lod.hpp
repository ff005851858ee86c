// Levels of detail of a mesh, for drawing only (physics and export see the mesh itself): the mesh,
// then copies with about half the triangles of the one before, made by meshoptimizer's
// edge-collapse simplifier (Garland and Heckbert's quadrics; seams of split vertices kept), each
// with how far its surface strays from the mesh's, measured. The renderer draws the coarsest level
// whose error, seen from the camera, is below a fraction of a pixel (RenderOptions::detail_pixels;
// the same level in the shadow maps, so a model never shadows itself; a cube map's faces, seen
// from its centre, may take a coarser one, the shadow lookups' offset widened to match): a far
// model's triangles are then a few pixels each, not fractions of one, which a software rasterizer
// (llvmpipe shades blocks of 4x4 pixels a triangle) pays for many times over
// (docs/performance.md, "Levels of detail").
#pragma once

#include "assets/mesh.hpp"

#include <cstdint>
#include <vector>

namespace animator {

struct LodLevel {
    std::uint32_t first = 0; // its first index in LodChain::indices
    std::uint32_t count = 0; // its indices, 3 a triangle
    // How far its surface strays from the mesh's, in the mesh's own units: the two-sided
    // Hausdorff distance, sampled (from the mesh's vertices to its triangles, from its triangles'
    // centroids and edge midpoints to the mesh's), and at least meshoptimizer's own estimate,
    // which falls short of it; 0 for the mesh itself.
    double error = 0.0;
    // Whether it keeps the mesh's texture coordinates: a sphere's even levels (sphere_lod.hpp),
    // over vertices of their own, do not, and are for untextured models only.
    bool keeps_texture = true;
};

struct LodChain {
    std::vector<std::uint32_t> indices; // every level's triangles, one after the other
    // Vertices the levels add after the mesh's own (index mesh.positions.size() + k is added k):
    // a sphere's even levels' (sphere_lod.hpp), with no texture coordinates.
    std::vector<glm::dvec3> added_positions, added_normals;
    // levels[0]: the mesh itself; then its simplified levels, fewer triangles and larger errors
    // each; then, for a sphere, its even levels that beat those (fewer triangles for the error).
    std::vector<LodLevel> levels;
};

// The chain for `mesh`: the mesh itself, and simplified levels while each has at most 3/4 of the
// triangles of the one before, down to about 24 triangles; for a mesh whose vertices lie on a
// sphere (approximates_sphere), its even levels too. A mesh of fewer than 64 triangles gets one
// level.
LodChain build_lod_chain(const Mesh &mesh);

// The index of the level of fewest triangles whose error is at most `allowed` (mesh units), of
// those that keep the texture's seam when `textured`; 0 when none is.
std::size_t choose_level(const std::vector<LodLevel> &levels, double allowed, bool textured = false);

} // namespace animator
