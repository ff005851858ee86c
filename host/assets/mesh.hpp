// Triangle meshes loaded with assimp from Wavefront OBJ, PLY, STL and self-contained glTF files
// (mesh_format_scan.hpp), with the seed's bounding sphere
// ("Collision Detection": center = mean of the vertices, radius = the largest distance from it
// to a vertex).
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace animator {

// An asset could not be loaded; the message starts with its path.
struct AssetError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct Mesh {
    std::vector<glm::dvec3> positions;
    std::vector<glm::dvec3> normals; // one per position, unit length
    std::vector<glm::dvec2> uvs;     // one per position; (0, 0) where the file has none
    std::vector<std::uint32_t> triangles; // 3 indices per triangle, counter-clockwise outward
    glm::dvec3 bound_center{0.0};
    double bound_radius = 0.0;
    bool has_uvs = false;
    // Drawn in place of a mesh that was not found (stand_in_mesh): the renderer shows it plainly
    // as a placeholder; it collides as the cube it is.
    bool stand_in = false;

    std::size_t triangle_count() const { return triangles.size() / 3; }
};

struct LoadedMesh {
    Mesh mesh;
    std::vector<std::string> warnings; // each names the file
};

// Loads every mesh in the file as one, triangulated, its identical corners joined, read as
// its extension says (.ply, .stl, .glb, .gltf; anything else as OBJ). Throws AssetError for a
// file that cannot be read, passes the limits of obj_scan.hpp (the message names the line) or
// mesh_format_scan.hpp (a glTF naming another file), has no triangles, or has a vertex that is not finite. Degenerate
// (zero-area) triangles are dropped with a warning. No other file is opened (no 'mtllib').
LoadedMesh load_mesh(const std::filesystem::path &path);

// The seed's bounding sphere over distinct positions (a vertex split for its UVs or normals
// counts once, so seams do not pull the center).
void compute_bounding_sphere(Mesh &mesh);

// Whether the mesh is a tessellated sphere, so physics may use the seed's sphere special case
// (its bounding sphere): every vertex on the bounding sphere, and every face close to it (its
// centroid beyond 0.9 of the radius), which a tetrahedron or a cube is not.
bool approximates_sphere(const Mesh &mesh);

// The stand-in for a mesh that is not found: the course's unit cube, -1 to 1 on each axis (so a
// node scaled for its mesh shows about where and how large the mesh would be), `stand_in` set.
std::shared_ptr<const Mesh> stand_in_mesh();

// Loads the meshes named by `ids` for the document at `document` (one per id, each file once):
// null for ""; for a mesh that is not found, the stand-in, with a warning naming the mesh and
// where it was looked for (the document keeps the id: the real mesh is used once it is there);
// null for a mesh that cannot be read, with a warning.
std::vector<std::shared_ptr<const Mesh>> load_meshes(const std::vector<std::string> &ids,
                                                     const class AssetPaths &assets,
                                                     const std::filesystem::path &document,
                                                     std::vector<std::string> &warnings);

} // namespace animator
