// Hostile meshes: each is refused at its line, or read without the minutes, the gigabytes or the
// other files the OBJ it is would have cost (host/assets/obj_scan.hpp, docs/fuzzing.md).
#include "assets/mesh.hpp"

#include "support.hpp"

#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <cmath>
#include <fcntl.h>
#include <string>
#include <sys/stat.h>
#include <thread>
#include <unistd.h>

using namespace animator;
namespace fs = std::filesystem;

namespace {

fs::path write(const std::string &dir, const std::string &name, const std::string &text) {
    const fs::path d = test::fresh_dir(dir);
    test::write_file(d / name, text);
    return d / name;
}

// `n` vertices on the unit circle, so that any polygon over them in order is convex.
std::string circle_vertices(int n) {
    std::string text;
    for (int i = 0; i < n; ++i) {
        const double a = 2.0 * 3.141592653589793 * i / n;
        text += "v " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0\n";
    }
    return text;
}

std::string polygon(int first, int corners) {
    std::string face = "f";
    for (int i = 0; i < corners; ++i) face += " " + std::to_string(first + i);
    return face + "\n";
}

} // namespace

TEST_CASE("a polygon of more than 1024 corners is refused at its line") {
    // assimp's triangulation is quadratic in a polygon's corners (20,000 took 6 s).
    const fs::path ok =
        write("mesh_polygon_ok", "ok.obj", circle_vertices(1024) + polygon(1, 1024));
    CHECK(load_mesh(ok).mesh.triangle_count() == 1022);
    const fs::path file =
        write("mesh_polygon", "big.obj", circle_vertices(1025) + polygon(1, 1025));
    CHECK_THROWS_WITH(
        load_mesh(file),
        Catch::StartsWith(file.string() + ":1026: a face of 1025 corners; at most 1024"));
}

TEST_CASE("polygons too costly to triangulate together are refused at the face that passes it") {
    // 64 faces of 1024 corners are 2^26 corners squared, the most; the 65th passes it.
    std::string text = circle_vertices(1024);
    for (int f = 0; f < 65; ++f) text += polygon(1, 1024);
    const fs::path file = write("mesh_polygons", "many.obj", text);
    CHECK_THROWS_WITH(
        load_mesh(file),
        Catch::StartsWith(file.string() + ":1089: the faces so far would take too long"));
}

TEST_CASE(
    "more than 1024 objects, groups and material changes are refused, however the lines end") {
    // assimp's OBJ importer is quadratic in them (50,000 'usemtl' lines, 1.5 MB, took 90 s).
    std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    for (int i = 0; i < 400; ++i) text += "o part" + std::to_string(i) + "\nf 1 2 3\n";
    for (int i = 0; i < 400; ++i) text += "g group" + std::to_string(i) + "\nf 1 2 3\n";
    const fs::path ok = write("mesh_parts_ok", "ok.obj", text + "usemtl a\nusemtl b\n");
    CHECK(load_mesh(ok).mesh.triangle_count() == 800);
    for (int i = 0; i < 300; ++i) text += "usemtl m" + std::to_string(i) + "\n";
    const fs::path file = write("mesh_parts", "parts.obj", text);
    // Lines 1-3 the vertices, 4-1603 the objects and groups, then 'usemtl' m0 at 1604.
    CHECK_THROWS_WITH(load_mesh(file), Catch::StartsWith(file.string() + ":1828: more than 1024"));

    // assimp also ends a line at a carriage return, a NUL or a form feed.
    std::string one_line = "v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3";
    for (int i = 0; i < 1025; ++i)
        one_line += (i % 3 == 0   ? "\rusemtl m"
                     : i % 3 == 1 ? std::string(1, '\0') + "o m"
                                  : "\fg m") +
                    std::to_string(i);
    const fs::path hidden = write("mesh_parts_hidden", "hidden.obj", one_line + "\n");
    CHECK_THROWS_WITH(load_mesh(hidden), Catch::StartsWith(hidden.string() + ":1: more than 1024"));
}

TEST_CASE("a mesh file larger than 64 MiB is refused before it is read") {
    const fs::path file = write("mesh_huge", "huge.obj", "");
    fs::resize_file(file, (std::uintmax_t{64} << 20) + 1); // sparse: no disk is written
    CHECK_THROWS_WITH(
        load_mesh(file),
        Catch::StartsWith(file.string() + ": the mesh file is 67108865 bytes; at most 67108864"));
}

TEST_CASE("a mesh is read as OBJ unless named .ply, .stl, .glb or .gltf: assimp's other importers are not reached") {
    // An Object File Format mesh, which assimp's OFF importer would read.
    const std::string off = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    const fs::path file = write("mesh_off", "triangle.off", off);
    CHECK_THROWS_WITH(load_mesh(file), Catch::StartsWith(file.string() + ": "));
}

TEST_CASE("a mesh's material library is never opened: a FIFO named there cannot block the reader") {
    const fs::path dir = test::fresh_dir("mesh_fifo");
    const fs::path fifo = dir / "materials.mtl";
    REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
    const fs::path file = dir / "mesh.obj";
    test::write_file(file,
                     "mtllib materials.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n");

    std::atomic<bool> done{false};
    std::size_t triangles = 0;
    std::thread reader([&] {
        triangles = load_mesh(file).mesh.triangle_count();
        done = true;
    });
    // A reader that opens the FIFO blocks until a writer comes: be that writer, so that the test
    // ends either way, and note that it was needed.
    bool opened_by_reader = false;
    while (!done && !opened_by_reader) {
        const int fd = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK); // fails while no one reads
        if (fd >= 0) {
            opened_by_reader = true;
            ::close(fd);
        } else {
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
    }
    reader.join();
    CHECK_FALSE(opened_by_reader);
    CHECK(triangles == 1);
}

TEST_CASE("no material library is parsed, not even the one beside the mesh") {
    // When 'mtllib' names a file that cannot be opened, assimp parses "<mesh>.mtl" instead, and
    // its MTL parser crashed on these 16 bytes (the mesh fuzzer's finding, as the OBJ's own text
    // read as its material library).
    const std::string crashes_mtl_parser("\0\0\0a\rmtllib 94/b", 16);
    const fs::path dir = test::fresh_dir("mesh_mtl");
    test::write_file(dir / "mesh.obj", "mtllib missing.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    test::write_file(dir / "mesh.mtl", crashes_mtl_parser);
    CHECK(load_mesh(dir / "mesh.obj").mesh.triangle_count() == 1);
    test::write_file(dir / "self.obj", crashes_mtl_parser);
    CHECK_THROWS_WITH(load_mesh(dir / "self.obj"),
                      Catch::StartsWith((dir / "self.obj").string() + ": "));
}

TEST_CASE("thousands of differing corners at one point are joined in one pass") {
    // 450,000 corners at three positions, each with its own UV: assimp's join compares each
    // with every other at its position, quadratic (30,000 took 10 s), so these would take about
    // 36 minutes, past ctest's 25-minute limit. Nothing here is timed: the join is ours now.
    const int corners = 450000;
    std::string text = "v 0 0 1\nv 1 1 1\nv 2 4 1\n";
    for (int i = 0; i < corners; ++i) text += "vt " + std::to_string(i) + " 0\n";
    for (int i = 0; i < corners; i += 3)
        text += "f 1/" + std::to_string(i + 1) + " 2/" + std::to_string(i + 2) + " 3/" +
                std::to_string(i + 3) + "\n";
    const Mesh mesh = load_mesh(write("mesh_corners", "corners.obj", text)).mesh;
    CHECK(mesh.positions.size() == static_cast<std::size_t>(corners));
    CHECK(mesh.triangle_count() == static_cast<std::size_t>(corners / 3));
    CHECK(mesh.uvs[corners - 1] == glm::dvec2(corners - 1, 0));
}
