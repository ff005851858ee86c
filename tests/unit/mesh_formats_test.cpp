// PLY, STL and glTF meshes (host/assets/mesh_format_scan.hpp), each written here by hand, in
// ASCII and binary, and read against what the shape says: a regular tetrahedron around the
// origin (corners (1,1,1), (1,-1,-1), (-1,1,-1), (-1,-1,1): bounding sphere at the origin,
// radius sqrt(3)) and a cube of side 2. What the format cannot hold or should not open is
// refused with a message naming the file.
#include "assets/mesh.hpp"
#include "assets/mesh_format_scan.hpp"

#include "support.hpp"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

using namespace animator;
namespace fs = std::filesystem;

namespace {

using Triangle = std::array<int, 3>;

const std::vector<glm::dvec3> kTetra = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};

// Each face leaves out one corner; its corners in the order that makes it face outward
// (counter-clockwise seen from outside: its normal points away from the corner left out).
std::vector<Triangle> tetra_faces() {
    std::vector<Triangle> faces;
    for (int out = 0; out < 4; ++out) {
        Triangle t{};
        int k = 0;
        for (int v = 0; v < 4; ++v)
            if (v != out) t[static_cast<size_t>(k++)] = v;
        const glm::dvec3 n = glm::cross(kTetra[t[1]] - kTetra[t[0]], kTetra[t[2]] - kTetra[t[0]]);
        if (glm::dot(n, kTetra[static_cast<size_t>(out)]) > 0) std::swap(t[1], t[2]);
        faces.push_back(t);
    }
    return faces;
}

glm::dvec3 face_normal(const Triangle &t) {
    return glm::normalize(glm::cross(kTetra[t[1]] - kTetra[t[0]], kTetra[t[2]] - kTetra[t[0]]));
}

template <class T> void put(std::string &out, T value) {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T)); // little-endian, as this machine and the formats
    out.append(bytes, sizeof(T));
}

fs::path write(const std::string &name, const std::string &bytes) {
    const fs::path dir = test::fresh_dir("mesh_formats_" + name);
    test::write_file(dir / name, bytes);
    return dir / name;
}

std::string ply_header(const char *format, int vertices, int faces) {
    return std::string("ply\nformat ") + format + " 1.0\ncomment a regular tetrahedron\nelement vertex " +
           std::to_string(vertices) + "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
           std::to_string(faces) + "\nproperty list uchar int vertex_indices\nend_header\n";
}

std::string tetra_ply_ascii() {
    std::string text = ply_header("ascii", 4, 4);
    for (const auto &v : kTetra) text += std::to_string(v.x) + " " + std::to_string(v.y) + " " + std::to_string(v.z) + "\n";
    for (const auto &f : tetra_faces()) text += "3 " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " + std::to_string(f[2]) + "\n";
    return text;
}

std::string tetra_ply_binary() {
    std::string bytes = ply_header("binary_little_endian", 4, 4);
    for (const auto &v : kTetra)
        for (int i = 0; i < 3; ++i) put<float>(bytes, static_cast<float>(v[i]));
    for (const auto &f : tetra_faces()) {
        put<std::uint8_t>(bytes, 3);
        for (int i : f) put<std::int32_t>(bytes, i);
    }
    return bytes;
}

std::string tetra_stl_ascii() {
    std::string text = "solid tetra\n";
    for (const auto &f : tetra_faces()) {
        const glm::dvec3 n = face_normal(f);
        text += "facet normal " + std::to_string(n.x) + " " + std::to_string(n.y) + " " + std::to_string(n.z) + "\n outer loop\n";
        for (int i : f) {
            const auto &v = kTetra[static_cast<size_t>(i)];
            text += "  vertex " + std::to_string(v.x) + " " + std::to_string(v.y) + " " + std::to_string(v.z) + "\n";
        }
        text += " endloop\nendfacet\n";
    }
    return text + "endsolid tetra\n";
}

std::string tetra_stl_binary() {
    std::string bytes(80, '\0');
    std::memcpy(bytes.data(), "binary STL: a regular tetrahedron", 33);
    put<std::uint32_t>(bytes, 4);
    for (const auto &f : tetra_faces()) {
        const glm::dvec3 n = face_normal(f);
        for (int i = 0; i < 3; ++i) put<float>(bytes, static_cast<float>(n[i]));
        for (int v : f)
            for (int i = 0; i < 3; ++i) put<float>(bytes, static_cast<float>(kTetra[static_cast<size_t>(v)][i]));
        put<std::uint16_t>(bytes, 0);
    }
    return bytes;
}

// The glTF's binary buffer: 4 positions (48 bytes), then 12 uint16 indices (24 bytes).
std::string tetra_buffer() {
    std::string bytes;
    for (const auto &v : kTetra)
        for (int i = 0; i < 3; ++i) put<float>(bytes, static_cast<float>(v[i]));
    for (const auto &f : tetra_faces())
        for (int i : f) put<std::uint16_t>(bytes, static_cast<std::uint16_t>(i));
    return bytes;
}

std::string gltf_json(const std::string &buffer) {
    return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
           R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],)"
           R"("accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3","min":[-1,-1,-1],"max":[1,1,1]},)"
           R"({"bufferView":1,"componentType":5123,"count":12,"type":"SCALAR"}],)"
           R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":48},{"buffer":0,"byteOffset":48,"byteLength":24}],)"
           R"("buffers":[)" + buffer + "]}";
}

std::string base64(const std::string &bytes) {
    static const char *digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < bytes.size(); i += 3) {
        std::uint32_t n = static_cast<std::uint8_t>(bytes[i]) << 16;
        if (i + 1 < bytes.size()) n |= static_cast<std::uint8_t>(bytes[i + 1]) << 8;
        if (i + 2 < bytes.size()) n |= static_cast<std::uint8_t>(bytes[i + 2]);
        out += digits[(n >> 18) & 63];
        out += digits[(n >> 12) & 63];
        out += i + 1 < bytes.size() ? digits[(n >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? digits[n & 63] : '=';
    }
    return out;
}

std::string tetra_gltf_embedded() {
    return gltf_json(R"({"byteLength":72,"uri":"data:application/octet-stream;base64,)" + base64(tetra_buffer()) + "\"}");
}

// A .glb (glTF 2.0, "Binary glTF"): a 12-byte header, a JSON chunk padded with spaces to 4
// bytes, a BIN chunk.
std::string tetra_glb() {
    std::string json = gltf_json(R"({"byteLength":72})");
    while (json.size() % 4) json += ' ';
    const std::string bin = tetra_buffer(); // 72 bytes, a multiple of 4
    std::string out = "glTF";
    put<std::uint32_t>(out, 2);
    put<std::uint32_t>(out, static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + bin.size()));
    put<std::uint32_t>(out, static_cast<std::uint32_t>(json.size()));
    out += "JSON";
    out += json;
    put<std::uint32_t>(out, static_cast<std::uint32_t>(bin.size()));
    out += std::string("BIN\0", 4);
    out += bin;
    return out;
}

// What every reading of the tetrahedron holds: its four corners, four outward triangles, the
// bounding sphere at the origin of radius sqrt(3).
void check_tetrahedron(const Mesh &m) {
    CHECK(m.triangle_count() == 4);
    CHECK_THAT(glm::length(m.bound_center), Catch::Matchers::WithinAbs(0.0, 1e-6));
    CHECK_THAT(m.bound_radius, Catch::Matchers::WithinRel(std::sqrt(3.0), 1e-6));
    for (const glm::dvec3 &p : m.positions) {
        bool corner = false;
        for (const glm::dvec3 &c : kTetra) corner |= glm::length(p - c) < 1e-6;
        CHECK(corner);
    }
    for (size_t t = 0; t < m.triangles.size(); t += 3) {
        const glm::dvec3 &a = m.positions[m.triangles[t]], &b = m.positions[m.triangles[t + 1]],
                         &c = m.positions[m.triangles[t + 2]];
        CHECK(glm::dot(glm::cross(b - a, c - a), (a + b + c) / 3.0) > 0.0); // outward
    }
}

// Without normals in the file: smooth ones, which at a corner of a regular tetrahedron (three
// faces of equal area) point straight out from the center.
void check_smooth(const Mesh &m) {
    REQUIRE(m.positions.size() == 4);
    for (size_t v = 0; v < 4; ++v) {
        const glm::dvec3 expected = glm::normalize(m.positions[v]);
        CHECK_THAT(glm::length(m.normals[v] - expected), Catch::Matchers::WithinAbs(0.0, 1e-5));
    }
}

// With the faces' normals (STL): each corner once per face, with that face's normal.
void check_flat(const Mesh &m) {
    REQUIRE(m.positions.size() == 12);
    for (size_t t = 0; t < m.triangles.size(); t += 3) {
        const glm::dvec3 &a = m.positions[m.triangles[t]], &b = m.positions[m.triangles[t + 1]],
                         &c = m.positions[m.triangles[t + 2]];
        const glm::dvec3 expected = glm::normalize(glm::cross(b - a, c - a));
        for (int k = 0; k < 3; ++k)
            CHECK_THAT(glm::length(m.normals[m.triangles[t + k]] - expected), Catch::Matchers::WithinAbs(0.0, 1e-5));
    }
}

} // namespace

TEST_CASE("a mesh's format is chosen by its extension, anything else is read as OBJ", "[mesh]") {
    CHECK(mesh_format_of("a/b/tetra.PLY") == MeshFormat::Ply);
    CHECK(mesh_format_of("tetra.stl") == MeshFormat::Stl);
    CHECK(mesh_format_of("tetra.glb") == MeshFormat::Glb);
    CHECK(mesh_format_of("tetra.gltf") == MeshFormat::Gltf);
    CHECK(mesh_format_of("tetra.obj") == MeshFormat::Obj);
    CHECK(mesh_format_of("tetra.blend") == MeshFormat::Obj);
    CHECK(mesh_format_of("dir.ply/tetra") == MeshFormat::Obj);
}

TEST_CASE("ASCII and binary PLY read as the tetrahedron, with smooth normals", "[mesh]") {
    for (const auto &[name, bytes] : {std::pair<std::string, std::string>{"tetra_ascii.ply", tetra_ply_ascii()},
                                      {"tetra_binary.ply", tetra_ply_binary()}}) {
        INFO(name);
        const LoadedMesh loaded = load_mesh(write(name, bytes));
        CHECK(loaded.warnings.empty());
        check_tetrahedron(loaded.mesh);
        check_smooth(loaded.mesh);
    }
}

TEST_CASE("a binary PLY cube of quads is triangulated, its corners' normals along the diagonals", "[mesh]") {
    std::string bytes =
        "ply\nformat binary_little_endian 1.0\nelement vertex 8\nproperty float x\nproperty float y\n"
        "property float z\nelement face 6\nproperty list uchar int vertex_indices\nend_header\n";
    for (int i = 0; i < 8; ++i) {
        put<float>(bytes, (i & 1) ? 1.0f : -1.0f);
        put<float>(bytes, (i & 2) ? 1.0f : -1.0f);
        put<float>(bytes, (i & 4) ? 1.0f : -1.0f);
    }
    // Counter-clockwise seen from outside: -x, +x, -y, +y, -z, +z.
    const int quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    for (const auto &q : quads) {
        put<std::uint8_t>(bytes, 4);
        for (int v : q) put<std::int32_t>(bytes, v);
    }
    const Mesh m = load_mesh(write("cube.ply", bytes)).mesh;
    CHECK(m.triangle_count() == 12);
    CHECK(m.positions.size() == 8);
    CHECK_THAT(m.bound_radius, Catch::Matchers::WithinRel(std::sqrt(3.0), 1e-6));
    for (size_t v = 0; v < m.positions.size(); ++v) {
        // Each corner is on three faces, each of one or two triangles: assimp's smoothing (and
        // ours) counts a face per triangle, so the normal leans to the faces split at that corner.
        CHECK(glm::dot(m.normals[v], glm::normalize(m.positions[v])) > 0.85);
        CHECK_THAT(glm::length(m.normals[v]), Catch::Matchers::WithinAbs(1.0, 1e-9));
    }
    for (size_t t = 0; t < m.triangles.size(); t += 3) {
        const glm::dvec3 &a = m.positions[m.triangles[t]], &b = m.positions[m.triangles[t + 1]],
                         &c = m.positions[m.triangles[t + 2]];
        CHECK(glm::dot(glm::cross(b - a, c - a), a + b + c) > 0.0);
    }
}

TEST_CASE("ASCII and binary STL read as the tetrahedron, flat: a corner per face", "[mesh]") {
    for (const auto &[name, bytes] : {std::pair<std::string, std::string>{"tetra_ascii.stl", tetra_stl_ascii()},
                                      {"tetra_binary.stl", tetra_stl_binary()}}) {
        INFO(name);
        const LoadedMesh loaded = load_mesh(write(name, bytes));
        CHECK(loaded.warnings.empty());
        check_tetrahedron(loaded.mesh);
        check_flat(loaded.mesh);
    }
}

TEST_CASE("a .glb and a .gltf with a data: buffer read as the tetrahedron, with smooth normals", "[mesh]") {
    for (const auto &[name, bytes] : {std::pair<std::string, std::string>{"tetra.glb", tetra_glb()},
                                      {"tetra.gltf", tetra_gltf_embedded()}}) {
        INFO(name);
        const LoadedMesh loaded = load_mesh(write(name, bytes));
        CHECK(loaded.warnings.empty());
        check_tetrahedron(loaded.mesh);
        check_smooth(loaded.mesh);
    }
}

TEST_CASE("a .gltf naming an external buffer is refused with the file's and the buffer's names", "[mesh]") {
    const fs::path file = write("external.gltf", gltf_json(R"({"byteLength":72,"uri":"tetra.bin"})"));
    test::write_file(file.parent_path() / "tetra.bin", tetra_buffer()); // there, but never opened
    CHECK_THROWS_WITH(load_mesh(file), Catch::StartsWith(file.string() + ": the glTF names the file 'tetra.bin'"));
}

TEST_CASE("counts past what a file holds or a mesh needs are refused before assimp reads them", "[mesh]") {
    // A PLY header promising 4 million vertices in a few bytes.
    std::string ply = ply_header("binary_little_endian", 4000000, 1);
    const fs::path small = write("promise.ply", ply + std::string(20, '\0'));
    CHECK_THROWS_WITH(load_mesh(small), Catch::StartsWith(small.string() + ": the PLY header promises at least"));
    const fs::path huge = write("huge.ply", ply_header("ascii", 5000000, 1));
    CHECK_THROWS_WITH(load_mesh(huge), Catch::StartsWith(huge.string() + ": PLY element 'vertex' has 5000000 instances"));
    // A glTF sparse accessor needs no bytes for its count.
    std::string json = tetra_gltf_embedded();
    json.replace(json.find("\"count\":4,"), 10, "\"count\":400000000,");
    const fs::path sparse = write("many.gltf", json);
    CHECK_THROWS_WITH(load_mesh(sparse), Catch::StartsWith(sparse.string() + ": a glTF accessor has more than"));
    // A binary STL needs no check of its own: 64 MiB hold at most 1.3 million triangles.
}

TEST_CASE("a file of one format named as another is refused, naming the file", "[mesh]") {
    const fs::path file = write("tetra_as.stl", tetra_ply_ascii());
    CHECK_THROWS_WITH(load_mesh(file), Catch::StartsWith(file.string() + ": "));
    const fs::path glb = write("not.glb", tetra_stl_ascii());
    CHECK_THROWS_WITH(load_mesh(glb), Catch::StartsWith(glb.string() + ": "));
}

TEST_CASE("a PLY whose face has no corners is refused, not left to abort assimp's triangulation", "[mesh]") {
    // The mesh fuzzer's finding: assimp's PLY importer made a face of no corners, which its
    // triangulation takes for a polygon and then aborts the program on an assertion.
    const fs::path file = test::source_dir() / "tests" / "fuzz" / "seeds" / "mesh" / "ply_face_without_corners.ply";
    CHECK_THROWS_WITH(load_mesh(file), Catch::StartsWith(file.string() + ": "));
}

TEST_CASE("a mangled PLY header is refused before assimp reads it, naming the line", "[mesh]") {
    // The mesh fuzzer's second finding: assimp's binary PLY reader read past the file on a
    // header with a garbled format line and a misspelled keyword. The header is checked first.
    const std::string body(64, '\0');
    const std::pair<const char *, const char *> cases[] = {
        {"ply\nformat binary_litt\xa8\xa8 1.0\nelement vertex 1\nproperty float x\nend_header\n", "line 2: an unknown format"},
        {"ply\nformat ascii 1.0\nelement vertex 1\noeprprty float x\nend_header\n", "line 4: an unknown keyword 'oeprprty'"},
        {"ply\nformat ascii 1.0\nformat ascii 1.0\nelement vertex 1\nend_header\n", "line 3: a second format line"},
        {"ply\nformat ascii 1.0\nelement vertex 1\nproperty flot x\nend_header\n", "line 4: an unknown property type 'flot'"},
        {"ply\nformat ascii 1.0\nproperty float x\nelement vertex 1\nend_header\n", "line 3: a property before any element"},
        {"ply\nelement vertex 1\nformat ascii 1.0\nend_header\n", "line 2: 'element' before the format line"},
    };
    int i = 0;
    for (const auto &[header, said] : cases) {
        const fs::path file = write("mangled" + std::to_string(i++) + ".ply", std::string(header) + body);
        INFO(header);
        CHECK_THROWS_WITH(load_mesh(file), Catch::StartsWith(file.string() + ": " + said));
    }
}
