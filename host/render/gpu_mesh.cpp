#include "render/gpu_mesh.hpp"

#include <animator/mesh_topology.hpp>
#include <animator/shading.h>
#include <glad/gl.h>

#include <vector>

namespace animator {

namespace {
constexpr int kFloatsPerVertex = 8; // position 3, normal 3, uv 2
}

GpuMesh::GpuMesh(const Mesh &mesh) {
    std::vector<float> interleaved;
    interleaved.reserve(mesh.positions.size() * kFloatsPerVertex);
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        const glm::dvec3 &p = mesh.positions[i];
        const glm::dvec3 n = i < mesh.normals.size() ? mesh.normals[i] : glm::dvec3(0.0);
        const glm::dvec2 uv = i < mesh.uvs.size() ? mesh.uvs[i] : glm::dvec2(0.0);
        for (double x : {p.x, p.y, p.z, n.x, n.y, n.z, uv.x, uv.y})
            interleaved.push_back(static_cast<float>(x));
    }
    const LodChain chain = build_lod_chain(mesh);
    levels_ = chain.levels;
    // The levels' own vertices after the mesh's (a sphere's even levels), without texture
    // coordinates.
    for (size_t i = 0; i < chain.added_positions.size(); ++i) {
        const glm::dvec3 &p = chain.added_positions[i], &n = chain.added_normals[i];
        for (double x : {p.x, p.y, p.z, n.x, n.y, n.z, 0.0, 0.0})
            interleaved.push_back(static_cast<float>(x));
    }
    static_assert(sizeof(glm::dvec3) == 3 * sizeof(double), "positions are read as doubles");
    ani_mesh_view view{};
    view.struct_size = sizeof view;
    view.positions = &mesh.positions.data()->x; // glm::dvec3 is three doubles
    view.vertex_count = static_cast<std::uint32_t>(mesh.positions.size());
    view.triangles = mesh.triangles.data();
    view.triangle_count = static_cast<std::uint32_t>(mesh.triangle_count());
    closed_ = !mesh.positions.empty() && ani::is_closed(view);

    glGenVertexArrays(1, &vertex_array_);
    glGenBuffers(1, &vertices_);
    glGenBuffers(1, &indices_);
    glBindVertexArray(vertex_array_);
    glBindBuffer(GL_ARRAY_BUFFER, vertices_);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(interleaved.size() * sizeof(float)),
                 interleaved.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                 static_cast<GLsizeiptr>(chain.indices.size() * sizeof(std::uint32_t)),
                 chain.indices.data(), GL_STATIC_DRAW);
    const GLsizei stride = kFloatsPerVertex * sizeof(float);
    auto attribute = [&](GLuint location, GLint size, size_t first_float) {
        glEnableVertexAttribArray(location);
        glVertexAttribPointer(location, size, GL_FLOAT, GL_FALSE, stride,
                              reinterpret_cast<const void *>(first_float * sizeof(float)));
    };
    attribute(ANI_VERTEX_POSITION, 3, 0);
    attribute(ANI_VERTEX_NORMAL, 3, 3);
    attribute(ANI_VERTEX_UV, 2, 6);
    glBindVertexArray(0);
}

GpuMesh::~GpuMesh() {
    glDeleteVertexArrays(1, &vertex_array_);
    glDeleteBuffers(1, &vertices_);
    glDeleteBuffers(1, &indices_);
}

void GpuMesh::draw(std::size_t level) const {
    const LodLevel &l = levels_[level];
    glBindVertexArray(vertex_array_);
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(l.count), GL_UNSIGNED_INT,
                   reinterpret_cast<const void *>(std::uintptr_t{l.first} * sizeof(std::uint32_t)));
}

Mesh GpuMesh::skybox_cube() {
    Mesh cube;
    for (int i = 0; i < 8; ++i)
        cube.positions.emplace_back(i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0);
    cube.normals.assign(8, glm::dvec3(0.0));
    cube.uvs.assign(8, glm::dvec2(0.0));
    // Two triangles per face, wound to face the inside where the camera is.
    cube.triangles = {0, 1, 3, 0, 3, 2, 4, 6, 7, 4, 7, 5, 0, 4, 5, 0, 5, 1,
                      2, 3, 7, 2, 7, 6, 0, 2, 6, 0, 6, 4, 1, 5, 7, 1, 7, 3};
    return cube;
}

} // namespace animator
