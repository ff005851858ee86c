#include "assets/mesh.hpp"

#include "assets/asset_paths.hpp"
#include "assets/mesh_format_scan.hpp"
#include "assets/obj_scan.hpp"

#include <assimp/BaseImporter.h>
#include <assimp/IOStream.hpp>
#include <assimp/IOSystem.hpp>
#include <assimp/Importer.hpp>
#include <assimp/MemoryIOWrapper.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <tuple>
#include <unordered_map>

namespace animator {

namespace {

bool finite(const aiVector3D &v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The only file assimp may open: the mesh's bytes, under a name of ours ending in .obj, .ply,
// .stl, .glb or .gltf (mesh_format_scan.hpp, by the file's extension), so that one of those five
// importers reads them whatever else the file is called (a mesh may be a path relative to its
// document, and assimp's other importers are code no asset needs). Every other name is
// refused: a glTF's external buffers (refused before, with their names) and an OBJ's materials. An OBJ names material libraries ('mtllib') by any path, and when one cannot be
// opened the importer tries "<mesh>.mtl" beside it: assimp's MTL parser crashes on a 16-byte
// file (the mesh fuzzer's finding), and a FIFO blocks the reader forever. animator takes
// materials from the document.
class OnlyTheMesh : public Assimp::IOSystem {
  public:
    OnlyTheMesh(const std::string &bytes, const char *name) : bytes_(bytes), name_(name) {}
    bool Exists(const char *file) const override { return file && std::strcmp(file, name_) == 0; }
    char getOsSeparator() const override { return '/'; }
    Assimp::IOStream *Open(const char *file, const char *mode) override {
        if (!Exists(file) || !mode || mode[0] != 'r') return nullptr;
        return new Assimp::MemoryIOStream(reinterpret_cast<const std::uint8_t *>(bytes_.data()), bytes_.size());
    }
    void Close(Assimp::IOStream *stream) override { delete stream; }

  private:
    const std::string &bytes_; // outlives the importer
    const char *name_;
};

// Takes every importer out of `importer` but those of the extension of `name` ("mesh.glb":
// glTF's). When the importers of an extension all decline a file, assimp tries every other
// importer's signature check (a "mesh.glb" holding an ASCII STL was read as one): with only
// those left, such a file is refused. The importer owns its importers, so those taken out are
// deleted here.
void keep_only_importers_of(Assimp::Importer &importer, const std::string &name) {
    const std::string extension = name.substr(name.rfind('.') + 1);
    std::vector<Assimp::BaseImporter *> others;
    for (std::size_t i = 0; i < importer.GetImporterCount(); ++i) {
        Assimp::BaseImporter *candidate = importer.GetImporter(i);
        std::set<std::string> extensions;
        candidate->GetExtensionList(extensions);
        if (!extensions.count(extension)) others.push_back(candidate);
    }
    for (Assimp::BaseImporter *other : others) {
        importer.UnregisterLoader(other);
        delete other;
    }
}

// The file's bytes, refusing one larger than kMaxMeshFileBytes before reading it.
std::string read_mesh_file(const std::filesystem::path &path) {
    const std::string name = path.string();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) throw AssetError(name + ": no such mesh file");
    const auto size = std::filesystem::file_size(path, ec);
    if (ec) throw AssetError(name + ": cannot be read as a mesh: " + ec.message());
    if (size > kMaxMeshFileBytes)
        throw AssetError(name + ": the mesh file is " + std::to_string(size) + " bytes; at most " +
                         std::to_string(kMaxMeshFileBytes) + " are read");
    std::ifstream in(path, std::ios::binary);
    std::string text(static_cast<std::size_t>(size), '\0');
    if (!in.read(text.data(), static_cast<std::streamsize>(size)))
        throw AssetError(name + ": cannot be read as a mesh: the file could not be read");
    return text;
}

// A vertex as the join below compares it: position, normal and UV, with -0 made +0 so that
// equal values have equal bits.
using VertexKey = std::array<double, 8>;
struct VertexKeyHash {
    std::size_t operator()(const VertexKey &k) const {
        std::size_t h = 1469598103934665603u;
        for (double d : k) {
            std::uint64_t bits = 0;
            std::memcpy(&bits, &d, sizeof bits);
            h = (h ^ static_cast<std::size_t>(bits)) * 1099511628211u;
        }
        return h;
    }
};

// Smooth normals for a mesh that has none, as assimp gives an OBJ's: at each position the sum of
// the unit normals of the faces with a corner there, made unit. Computed here for the other
// formats, since assimp's step gives a vertex shared by several faces (glTF's indexed ones) the
// normal of the last of them only; the OBJ importer makes a vertex per corner, so its normals
// stay assimp's, as they always were.
std::vector<aiVector3D> smooth_normals(const aiMesh &mesh) {
    std::map<std::tuple<float, float, float>, aiVector3D> sums;
    const auto key = [&](unsigned v) {
        const aiVector3D &p = mesh.mVertices[v];
        return std::make_tuple(p.x + 0.0f, p.y + 0.0f, p.z + 0.0f);
    };
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
        const aiFace &face = mesh.mFaces[f];
        if (face.mNumIndices != 3) continue;
        const aiVector3D &a = mesh.mVertices[face.mIndices[0]], &b = mesh.mVertices[face.mIndices[1]],
                         &c = mesh.mVertices[face.mIndices[2]];
        aiVector3D n = (b - a) ^ (c - a);
        n.NormalizeSafe();
        for (unsigned k = 0; k < 3; ++k) sums[key(face.mIndices[k])] += n;
    }
    std::vector<aiVector3D> normals(mesh.mNumVertices);
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
        const auto it = sums.find(key(v));
        if (it != sums.end()) normals[v] = aiVector3D(it->second).NormalizeSafe();
    }
    return normals;
}

} // namespace

std::shared_ptr<const Mesh> stand_in_mesh() {
    static const std::shared_ptr<const Mesh> cube = [] {
        Mesh m;
        for (int axis = 0; axis < 3; ++axis)
            for (double side : {-1.0, 1.0}) { // a face: 4 corners with its normal, 2 triangles
                glm::dvec3 n(0.0), u(0.0), v(0.0);
                n[axis] = side;
                u[(axis + 1) % 3] = 1.0;
                v[(axis + 2) % 3] = 1.0;
                if (side < 0.0) std::swap(u, v); // counter-clockwise seen from outside
                const auto base = static_cast<std::uint32_t>(m.positions.size());
                for (int k = 0; k < 4; ++k) {
                    const double a = (k == 1 || k == 2) ? 1.0 : -1.0, b = k >= 2 ? 1.0 : -1.0;
                    m.positions.push_back(n + a * u + b * v);
                    m.normals.push_back(n);
                    m.uvs.emplace_back(0.5 * (a + 1.0), 0.5 * (b + 1.0));
                }
                for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) m.triangles.push_back(base + i);
            }
        m.has_uvs = true;
        m.stand_in = true;
        compute_bounding_sphere(m);
        return std::make_shared<const Mesh>(std::move(m));
    }();
    return cube;
}

void compute_bounding_sphere(Mesh &mesh) {
    std::set<std::tuple<double, double, double>> distinct;
    for (const glm::dvec3 &p : mesh.positions) distinct.emplace(p.x, p.y, p.z);
    glm::dvec3 sum(0.0);
    for (const auto &[x, y, z] : distinct) sum += glm::dvec3(x, y, z);
    mesh.bound_center = distinct.empty() ? glm::dvec3(0.0) : sum / static_cast<double>(distinct.size());
    double radius = 0.0;
    for (const auto &[x, y, z] : distinct) radius = std::max(radius, glm::length(glm::dvec3(x, y, z) - mesh.bound_center));
    mesh.bound_radius = radius;
}

bool approximates_sphere(const Mesh &mesh) {
    const double r = mesh.bound_radius;
    if (!(r > 0.0) || mesh.triangles.size() < std::size_t{60} /* 20 triangles */) return false;
    for (const glm::dvec3 &p : mesh.positions)
        if (std::abs(glm::length(p - mesh.bound_center) - r) > 1e-6 * r) return false;
    for (size_t t = 0; t < mesh.triangles.size(); t += 3) {
        const glm::dvec3 centroid =
            (mesh.positions[mesh.triangles[t]] + mesh.positions[mesh.triangles[t + 1]] + mesh.positions[mesh.triangles[t + 2]]) / 3.0;
        if (glm::length(centroid - mesh.bound_center) < 0.9 * r) return false;
    }
    return true;
}

std::vector<std::shared_ptr<const Mesh>> load_meshes(const std::vector<std::string> &ids, const AssetPaths &assets,
                                                     const std::filesystem::path &document,
                                                     std::vector<std::string> &warnings) {
    std::map<std::filesystem::path, std::shared_ptr<const Mesh>> loaded;
    // Each id is looked for once (the search asks the file system, folder by folder): a scene of
    // 100,000 balls named one mesh 100,000 times.
    std::map<std::string, std::optional<std::filesystem::path>> resolved;
    std::vector<std::shared_ptr<const Mesh>> out;
    for (const std::string &id : ids) {
        if (id.empty()) {
            out.push_back(nullptr);
            continue;
        }
        auto found = resolved.find(id);
        if (found == resolved.end())
            found = resolved.emplace(id, assets.resolve(ANI_ASSET_MESH, id, document)).first;
        const std::optional<std::filesystem::path> &path = found->second;
        if (!path) {
            warnings.push_back("mesh '" + id + "' not found (" + assets.searched(ANI_ASSET_MESH, id, document) +
                               "); shown as a stand-in cube until it is there");
            out.push_back(stand_in_mesh());
            continue;
        }
        auto it = loaded.find(*path);
        if (it == loaded.end()) {
            std::shared_ptr<const Mesh> mesh;
            try {
                LoadedMesh lm = load_mesh(*path);
                warnings.insert(warnings.end(), lm.warnings.begin(), lm.warnings.end());
                mesh = std::make_shared<const Mesh>(std::move(lm.mesh));
            } catch (const AssetError &e) {
                warnings.push_back(e.what());
            }
            it = loaded.emplace(*path, mesh).first;
        }
        out.push_back(it->second);
    }
    return out;
}

LoadedMesh load_mesh(const std::filesystem::path &path) {
    const std::string name = path.string();
    const std::string text = read_mesh_file(path);
    const MeshFormat format = mesh_format_of(name);
    const std::string too_large =
        format == MeshFormat::Obj ? obj_beyond_limits(name, text) : mesh_beyond_limits(name, format, text);
    if (!too_large.empty()) throw AssetError(too_large);

    Assimp::Importer importer;
    const char *assimp_name = assimp_name_of(format);
    importer.SetIOHandler(new OnlyTheMesh(text, assimp_name)); // the importer owns it
    keep_only_importers_of(importer, assimp_name);
    // Keep degenerate triangles (we report them ourselves) and lines/points out.
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    // The identical corners are joined below, not by aiProcess_JoinIdenticalVertices, which
    // compares every corner near a position with every other: quadratic in a file that puts
    // thousands at one point.
    const unsigned normals = format == MeshFormat::Obj ? aiProcess_GenSmoothNormals : 0u; // else smooth_normals()
    const unsigned steps = aiProcess_Triangulate | aiProcess_PreTransformVertices | normals | aiProcess_SortByPType |
                           aiProcess_ValidateDataStructure;
    const aiScene *scene = nullptr;
    if (format == MeshFormat::Obj) {
        scene = importer.ReadFile(assimp_name, steps);
    } else {
        // Read, then the primitive types each mesh claims made those of its faces, then the
        // steps: assimp's PLY importer can claim polygons a mesh does not have, and its
        // triangulation then aborts the program on an assertion (the mesh fuzzer's finding).
        scene = importer.ReadFile(assimp_name, aiProcess_ValidateDataStructure);
        if (scene && !(scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE)) {
            for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
                aiMesh *mesh = scene->mMeshes[m];
                unsigned types = 0;
                std::size_t work = 0;
                for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
                    const unsigned n = mesh->mFaces[f].mNumIndices;
                    // The OBJ limits of a polygon (obj_scan.hpp): triangulation is quadratic.
                    work += std::size_t{n} * n;
                    if (n > kMaxPolygonCorners || work > kMaxTriangulationWork)
                        throw AssetError(name + ": face " + std::to_string(f + 1) + " has " + std::to_string(n) +
                                         " corners; at most " + std::to_string(kMaxPolygonCorners) +
                                         " a face, and the faces' corners squared at most " +
                                         std::to_string(kMaxTriangulationWork) + " in all");
                    if (n == 0) throw AssetError(name + ": face " + std::to_string(f + 1) + " has no corners");
                    types |= n == 1 ? aiPrimitiveType_POINT : n == 2 ? aiPrimitiveType_LINE
                                                            : n == 3 ? aiPrimitiveType_TRIANGLE
                                                                     : aiPrimitiveType_POLYGON;
                }
                mesh->mPrimitiveTypes = types;
            }
            scene = importer.ApplyPostProcessing(steps & ~unsigned{aiProcess_ValidateDataStructure});
        }
    }
    if (!scene || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE)) {
        const std::string reason = importer.GetErrorString();
        // assimp's validation words an empty file in terms of its own structures.
        if (reason.find("mNumMeshes is 0") != std::string::npos || reason.find("no faces") != std::string::npos)
            throw AssetError(name + ": the mesh has no triangles");
        throw AssetError(name + ": cannot be read as a mesh: " + reason);
    }

    LoadedMesh out;
    Mesh &mesh = out.mesh;
    std::size_t degenerate = 0, first_degenerate = 0, triangle_index = 0;
    bool any_uvs = false;
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
        const aiMesh *src = scene->mMeshes[m];
        if (!(src->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
        // Each corner of the file is a vertex of assimp's; those equal in position, normal and
        // UV become one, the first keeping its place.
        std::unordered_map<VertexKey, std::uint32_t, VertexKeyHash> joined;
        std::vector<std::uint32_t> index_of(src->mNumVertices);
        const std::vector<aiVector3D> computed = src->mNormals ? std::vector<aiVector3D>{} : smooth_normals(*src);
        const aiVector3D *src_normals = src->mNormals ? src->mNormals : computed.data();
        for (unsigned v = 0; v < src->mNumVertices; ++v) {
            const aiVector3D &p = src->mVertices[v];
            if (!finite(p))
                throw AssetError(name + ": vertex " + std::to_string(v + 1) + " is not a finite number");
            const glm::dvec3 position(p.x, p.y, p.z);
            glm::dvec3 n(0.0, 0.0, 0.0);
            if (finite(src_normals[v])) n = {src_normals[v].x, src_normals[v].y, src_normals[v].z};
            const double len = glm::length(n);
            const glm::dvec3 normal = len > 0.0 ? n / len : glm::dvec3(0.0, 1.0, 0.0);
            glm::dvec2 uv(0.0, 0.0);
            if (src->mTextureCoords[0]) {
                uv = {src->mTextureCoords[0][v].x, src->mTextureCoords[0][v].y};
                any_uvs = true;
            }
            const VertexKey key = {position.x + 0.0, position.y + 0.0, position.z + 0.0, normal.x + 0.0,
                                   normal.y + 0.0,   normal.z + 0.0,   uv.x + 0.0,       uv.y + 0.0};
            const auto [it, added] = joined.emplace(key, static_cast<std::uint32_t>(mesh.positions.size()));
            if (added) {
                mesh.positions.push_back(position);
                mesh.normals.push_back(normal);
                mesh.uvs.push_back(uv);
            }
            index_of[v] = it->second;
        }
        for (unsigned f = 0; f < src->mNumFaces; ++f, ++triangle_index) {
            const aiFace &face = src->mFaces[f];
            if (face.mNumIndices != 3) continue;
            const std::uint32_t corner[3] = {index_of[face.mIndices[0]], index_of[face.mIndices[1]],
                                             index_of[face.mIndices[2]]};
            const glm::dvec3 &a = mesh.positions[corner[0]];
            const glm::dvec3 &b = mesh.positions[corner[1]];
            const glm::dvec3 &c = mesh.positions[corner[2]];
            const double scale = std::max({glm::length(b - a), glm::length(c - a), 1e-300});
            if (glm::length(glm::cross(b - a, c - a)) <= 1e-12 * scale * scale) {
                if (degenerate++ == 0) first_degenerate = triangle_index + 1;
                continue;
            }
            for (std::uint32_t k : corner) mesh.triangles.push_back(k);
        }
    }
    if (mesh.triangles.empty())
        throw AssetError(name + (degenerate ? ": every triangle is degenerate (zero area)" : ": the mesh has no triangles"));
    if (degenerate)
        out.warnings.push_back(name + ": " + std::to_string(degenerate) +
                               " degenerate (zero-area) triangles dropped, the first is triangle " +
                               std::to_string(first_degenerate));
    mesh.has_uvs = any_uvs;
    compute_bounding_sphere(mesh);
    return out;
}

} // namespace animator
