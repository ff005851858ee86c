// A mesh in vertex buffers, uploaded once: position, normal and UV interleaved as floats at the
// attribute locations shading.h names (ANI_VERTEX_*), and the triangles as 32-bit indices.
#pragma once

#include "assets/mesh.hpp"

#include <cstdint>

namespace animator {

class GpuMesh {
  public:
    // Needs a current GL context, for its whole life.
    explicit GpuMesh(const Mesh &mesh);
    ~GpuMesh();
    GpuMesh(const GpuMesh &) = delete;
    GpuMesh &operator=(const GpuMesh &) = delete;

    // Draws every triangle with whatever program and uniforms are bound.
    void draw() const;

    // A cube from -1 to 1, its triangles facing inward, for the skybox.
    static Mesh skybox_cube();

  private:
    unsigned vertex_array_ = 0, vertices_ = 0, indices_ = 0;
    std::int32_t index_count_ = 0;
};

} // namespace animator
