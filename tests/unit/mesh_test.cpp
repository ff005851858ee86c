// Loading meshes and images, and resolving asset ids, against hand-made files.
#include "assets/asset_paths.hpp"
#include "assets/image.hpp"
#include "assets/mesh.hpp"

#include "support.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace animator;
namespace fs = std::filesystem;

namespace {

fs::path write(const std::string &dir, const std::string &name, const std::string &text) {
    const fs::path d = test::fresh_dir(dir);
    test::write_file(d / name, text);
    return d / name;
}

const char *kTetrahedron =
    "# a tetrahedron with one corner at the origin\n"
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
    "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

} // namespace

TEST_CASE("a mesh's bounding sphere is the seed's: mean of the vertices, largest distance") {
    const LoadedMesh loaded = load_mesh(write("mesh_tetra", "tetra.obj", kTetrahedron));
    const Mesh &m = loaded.mesh;
    CHECK(loaded.warnings.empty());
    CHECK(m.triangle_count() == 4);
    CHECK(m.bound_center.x == Approx(0.25));
    CHECK(m.bound_center.y == Approx(0.25));
    CHECK(m.bound_center.z == Approx(0.25));
    // The farthest corners, e.g. (1, 0, 0): sqrt(0.75^2 + 0.25^2 + 0.25^2).
    CHECK(m.bound_radius == Approx(std::sqrt(0.6875)));
    for (const auto &n : m.normals) CHECK(glm::length(n) == Approx(1.0));
    CHECK_FALSE(m.has_uvs);
}

TEST_CASE("polygons are triangulated and UVs and normals are read") {
    const LoadedMesh loaded = load_mesh(write("mesh_quad", "quad.obj",
        "v -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\n"
        "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 1 0\n"
        "f 1/1/1 4/4/1 3/3/1 2/2/1\n"));
    const Mesh &m = loaded.mesh;
    REQUIRE(m.triangle_count() == 2);
    CHECK(m.has_uvs);
    for (size_t i = 0; i < m.positions.size(); ++i) {
        CHECK(m.normals[i] == glm::dvec3(0, 1, 0));
        // Each corner keeps its own UV: u = (x + 1) / 2, v = (z + 1) / 2 in this file.
        CHECK(m.uvs[i].x == Approx((m.positions[i].x + 1.0) / 2.0));
        CHECK(m.uvs[i].y == Approx((m.positions[i].z + 1.0) / 2.0));
    }
    // Winding: the face normal of each triangle points along +Y as written.
    for (size_t t = 0; t < m.triangles.size(); t += 3) {
        const auto &a = m.positions[m.triangles[t]], &b = m.positions[m.triangles[t + 1]],
                   &c = m.positions[m.triangles[t + 2]];
        CHECK(glm::cross(b - a, c - a).y > 0.0);
    }
}

TEST_CASE("a vertex split for its UVs counts once in the bounding sphere") {
    // Two triangles share the edge (1,0,0)-(0,1,0) but with different UVs there.
    const LoadedMesh loaded = load_mesh(write("mesh_seam", "seam.obj",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvt 0.5 0.5\nvt 1 1\n"
        "f 1/1 2/2 3/3\nf 2/4 4/5 3/4\n"));
    CHECK(loaded.mesh.bound_center.x == Approx(0.5));
    CHECK(loaded.mesh.bound_center.y == Approx(0.5));
    CHECK(loaded.mesh.bound_radius == Approx(std::sqrt(0.5)));
}

TEST_CASE("empty, non-finite and degenerate meshes are named in an error or warning") {
    CHECK_THROWS_WITH(load_mesh(write("mesh_empty", "empty.obj", "# nothing here\n")),
                      Catch::Contains("empty.obj"));
    CHECK_THROWS_WITH(load_mesh(test::fresh_dir("mesh_none") / "none.obj"), Catch::Contains("none.obj: no such mesh file"));
    CHECK_THROWS_WITH(load_mesh(write("mesh_nan", "nan.obj", "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")),
                      Catch::Contains("nan.obj") && Catch::Contains("not a finite number"));
    CHECK_THROWS_WITH(load_mesh(write("mesh_flat", "flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n")),
                      Catch::Contains("flat.obj: every triangle is degenerate"));

    const LoadedMesh some = load_mesh(write("mesh_some", "some.obj",
        "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 4\n"));
    CHECK(some.mesh.triangle_count() == 1);
    REQUIRE(some.warnings.size() == 1);
    CHECK_THAT(some.warnings[0], Catch::Contains("some.obj: 1 degenerate") && Catch::Contains("triangle 1"));
}

TEST_CASE("a BMP written byte by byte loads with its pixels, and a broken image is named") {
    // A 2 x 2, 24-bit BMP: rows bottom-up, BGR, each row padded to 4 bytes.
    std::string bmp = "BM";
    auto u32 = [&](std::uint32_t v) { for (int i = 0; i < 4; ++i) bmp.push_back(static_cast<char>((v >> (8 * i)) & 0xff)); };
    auto u16 = [&](std::uint16_t v) { bmp.push_back(static_cast<char>(v & 0xff)); bmp.push_back(static_cast<char>(v >> 8)); };
    u32(54 + 16); u32(0); u32(54);
    u32(40); u32(2); u32(2); u16(1); u16(24); u32(0); u32(16); u32(2835); u32(2835); u32(0); u32(0);
    const unsigned char bottom[] = {255, 0, 0, 0, 255, 0, 0, 0};    // blue, green, padding
    const unsigned char top[] = {0, 0, 255, 255, 255, 255, 0, 0};   // red, white, padding
    bmp.append(reinterpret_cast<const char *>(bottom), 8);
    bmp.append(reinterpret_cast<const char *>(top), 8);
    const Image image = load_image(write("image_bmp", "tiny.bmp", bmp));
    REQUIRE(image.width == 2);
    REQUIRE(image.height == 2);
    const std::vector<std::uint8_t> expected = {255, 0, 0, 255, 255, 255, 0, 0, 255, 0, 255, 0};
    CHECK(image.rgb == expected); // top row first: red, white; then blue, green

    CHECK_THROWS_WITH(load_image(write("image_bad", "bad.png", "not a png")),
                      Catch::Contains("bad.png: cannot be read as an image"));
}

TEST_CASE("asset ids resolve to a path relative to the document first, then the roots in order") {
    const fs::path root_a = test::fresh_dir("assets_root_a"), root_b = test::fresh_dir("assets_root_b");
    const fs::path scene_dir = test::fresh_dir("assets_scene");
    fs::create_directories(root_a / "meshes");
    fs::create_directories(root_b / "meshes");
    fs::create_directories(root_b / "sounds");
    fs::create_directories(root_b / "skyboxes" / "night");
    fs::create_directories(scene_dir / "local");
    test::write_file(root_a / "meshes" / "ball.obj", kTetrahedron);
    test::write_file(root_b / "meshes" / "ball.obj", kTetrahedron);
    test::write_file(root_b / "meshes" / "cube.obj", kTetrahedron);
    test::write_file(root_b / "sounds" / "click.wav", "RIFF");
    test::write_file(scene_dir / "local" / "rock.obj", kTetrahedron);

    const AssetPaths assets({root_a, root_b});
    const fs::path scene = scene_dir / "scene.lua";
    CHECK(assets.resolve(ANI_ASSET_MESH, "ball", scene) == root_a / "meshes" / "ball.obj");
    CHECK(assets.resolve(ANI_ASSET_MESH, "cube", scene) == root_b / "meshes" / "cube.obj");
    CHECK(assets.resolve(ANI_ASSET_MESH, "local/rock.obj", scene) == scene_dir / "local" / "rock.obj");
    CHECK(assets.resolve(ANI_ASSET_SOUND, "click") == root_b / "sounds" / "click.wav");
    CHECK(assets.resolve(ANI_ASSET_SKYBOX, "night") == root_b / "skyboxes" / "night");
    CHECK_FALSE(assets.resolve(ANI_ASSET_MESH, "teapot", scene));
    CHECK_FALSE(assets.resolve(ANI_ASSET_MESH, "", scene));
    CHECK_THAT(assets.searched(ANI_ASSET_MESH, "teapot", scene),
               Catch::Contains((root_a / "meshes" / "teapot.obj").string()) &&
                   Catch::Contains((root_b / "meshes" / "teapot.obj").string()));
    // A name that already ends in the mesh's extension (the course's ray tracer writes
    // gr.mesh('floor', 'plane.obj')) is that file in the asset folders, not "plane.obj.obj".
    CHECK(assets.resolve(ANI_ASSET_MESH, "cube.obj", scene) == root_b / "meshes" / "cube.obj");
    CHECK_THAT(assets.searched(ANI_ASSET_MESH, "teapot.obj", scene),
               Catch::Contains((root_a / "meshes" / "teapot.obj").string()) &&
                   !Catch::Contains("teapot.obj.obj"));
}

TEST_CASE("the generated PNG and BMP textures load through the host's loader alike") {
    const fs::path textures = test::bin_dir().parent_path() / "assets" / "textures";
    const Image png = load_image(textures / "checker.png");
    const Image bmp = load_image(textures / "checker.bmp");
    CHECK(png.width == 256);
    CHECK(png.height == 256);
    CHECK(png.rgb == bmp.rgb);
    // An 8 x 8 checker of 32-pixel squares: the two squares of the first row differ.
    auto pixel = [&](int x, int y) { return png.rgb[static_cast<size_t>(3 * (y * 256 + x))]; };
    CHECK(pixel(0, 0) != pixel(32, 0));
    CHECK(pixel(0, 0) == pixel(64, 0));
    CHECK(pixel(0, 0) == pixel(32, 32));
    for (const char *name : {"wood.png", "marble.png", "brick.png"}) CHECK(load_image(textures / name).width == 256);
    for (const char *face : {"right", "left", "top", "bottom", "front", "back"})
        CHECK(load_image(textures.parent_path() / "skyboxes" / "night" / (std::string(face) + ".png")).height == 256);
}
