// An indexed triangle mesh in the shape of a Wavefront OBJ: positions, texture coordinates and
// normals are separate pools, and each triangle corner picks one of each. Keeping positions
// separate is what makes the solids watertight: a UV seam or a hard edge duplicates the vt or vn
// of a corner, never its position.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace animator::assetgen {

struct Corner {
    std::uint32_t v = 0, vt = 0, vn = 0; // 0-based; the writer adds 1
};

class Mesh {
  public:
    std::uint32_t add_position(const glm::dvec3 &p);
    std::uint32_t add_uv(const glm::dvec2 &uv);
    // Normalises, so every generator gets unit normals without having to remember.
    std::uint32_t add_normal(const glm::dvec3 &n);
    // Corners counter-clockwise as seen from the side the normals face.
    void add_triangle(const Corner &a, const Corner &b, const Corner &c);
    void add_quad(const Corner &a, const Corner &b, const Corner &c, const Corner &d);

    const std::vector<glm::dvec3> &positions() const { return positions_; }
    const std::vector<glm::dvec2> &uvs() const { return uvs_; }
    const std::vector<glm::dvec3> &normals() const { return normals_; }
    const std::vector<std::array<Corner, 3>> &triangles() const { return triangles_; }

  private:
    std::vector<glm::dvec3> positions_;
    std::vector<glm::dvec2> uvs_;
    std::vector<glm::dvec3> normals_;
    std::vector<std::array<Corner, 3>> triangles_;
};

} // namespace animator::assetgen
