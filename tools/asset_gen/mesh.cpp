#include "mesh.hpp"

#include <glm/geometric.hpp>

namespace animator::assetgen {

std::uint32_t Mesh::add_position(const glm::dvec3 &p) {
    positions_.push_back(p);
    return static_cast<std::uint32_t>(positions_.size() - 1);
}

std::uint32_t Mesh::add_uv(const glm::dvec2 &uv) {
    uvs_.push_back(uv);
    return static_cast<std::uint32_t>(uvs_.size() - 1);
}

std::uint32_t Mesh::add_normal(const glm::dvec3 &n) {
    normals_.push_back(glm::normalize(n));
    return static_cast<std::uint32_t>(normals_.size() - 1);
}

void Mesh::add_triangle(const Corner &a, const Corner &b, const Corner &c) {
    triangles_.push_back({a, b, c});
}

void Mesh::add_quad(const Corner &a, const Corner &b, const Corner &c, const Corner &d) {
    add_triangle(a, b, c);
    add_triangle(a, c, d);
}

} // namespace animator::assetgen
