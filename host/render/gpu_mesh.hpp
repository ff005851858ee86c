// A mesh in vertex buffers, uploaded once: position, normal and UV interleaved as floats at the
// attribute locations shading.h names (ANI_VERTEX_*), and the triangles as 32-bit indices: the
// mesh's own, then those of its coarser levels of detail (mesh_lod.hpp), in one buffer.
#pragma once

#include "assets/mesh.hpp"
#include "render/mesh_lod.hpp"

#include <cstdint>

namespace animator {

class GpuMesh {
  public:
    // Needs a current GL context, for its whole life.
    explicit GpuMesh(const Mesh &mesh);
    ~GpuMesh();
    GpuMesh(const GpuMesh &) = delete;
    GpuMesh &operator=(const GpuMesh &) = delete;

    // Draws the triangles of level `level` (0: the mesh itself) with whatever program and
    // uniforms are bound.
    void draw(std::size_t level = 0) const;
    const std::vector<LodLevel> &levels() const { return levels_; }
    // The mesh is a closed surface wound outward (animator/mesh_topology.hpp): seen from outside
    // it, its back faces are hidden behind its front ones and need not be drawn.
    bool closed() const { return closed_; }

    // A cube from -1 to 1, its triangles facing inward, for the skybox.
    static Mesh skybox_cube();

  private:
    unsigned vertex_array_ = 0, vertices_ = 0, indices_ = 0;
    std::vector<LodLevel> levels_;
    bool closed_ = false;
};

} // namespace animator
