// `animator export` as a user runs it, its file read back with tinygltf and compared with the
// document it came from; and the refusals.
#include "io/document_io.hpp"
#include "physics/scene_support.hpp"

#include <catch2/catch.hpp>

#include <tiny_gltf.h>

#include <glm/geometric.hpp>

#include <fstream>

using namespace animator;
using physics_test::env;

namespace {

tinygltf::Model read_back(const std::filesystem::path &file) {
    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string error, warning;
    const bool ok = file.extension() == ".glb"
                        ? loader.LoadBinaryFromFile(&model, &error, &warning, file.string())
                        : loader.LoadASCIIFromFile(&model, &error, &warning, file.string());
    INFO(error << warning);
    REQUIRE(ok);
    return model;
}

const tinygltf::Node &node_named(const tinygltf::Model &model, const std::string &name) {
    const auto it = std::find_if(model.nodes.begin(), model.nodes.end(),
                                 [&](const tinygltf::Node &n) { return n.name == name; });
    REQUIRE(it != model.nodes.end());
    return *it;
}

bool uses(const tinygltf::Model &model, const std::string &extension) {
    return std::find(model.extensionsUsed.begin(), model.extensionsUsed.end(), extension) !=
           model.extensionsUsed.end();
}

} // namespace

TEST_CASE("materials, camera and the camera's light of orbs.ani read back as the document "
          "has them") {
    const auto dir = test::fresh_dir("export_orbs");
    const auto file = test::source_dir() / "assets/animations/orbs.ani";
    const auto r =
        test::run_animator("export " + file.string() + " --to " + (dir / "orbs.gltf").string());
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Contains("glTF has no skybox"));
    const tinygltf::Model model = read_back(dir / "orbs.gltf");
    const Document doc = open_document(env().plugins, file).document;

    CHECK(uses(model, "KHR_materials_transmission"));
    CHECK(uses(model, "KHR_materials_ior"));
    CHECK(uses(model, "KHR_lights_punctual"));
    for (const Model &m : doc.models()) {
        CAPTURE(m.name);
        const tinygltf::Node &n = node_named(model, m.name);
        REQUIRE(n.mesh >= 0);
        const tinygltf::Material &mat = model.materials[static_cast<size_t>(
            model.meshes[static_cast<size_t>(n.mesh)].primitives[0].material)];
        const auto &pbr = mat.pbrMetallicRoughness;
        CHECK(pbr.baseColorFactor ==
              std::vector<double>{m.material.kd.x, m.material.kd.y, m.material.kd.z, 1.0});
        CHECK(pbr.metallicFactor == Approx(m.reflectivity));
        // Blinn-Phong shininess n as roughness sqrt(sqrt(2 / (n + 2))).
        CHECK(pbr.roughnessFactor ==
              Approx(std::sqrt(std::sqrt(2.0 / (m.material.shininess + 2.0)))));
        const auto transmission = mat.extensions.find("KHR_materials_transmission");
        CHECK((transmission != mat.extensions.end()) == (m.transparency > 0.0));
        if (m.transparency > 0.0) {
            CHECK(transmission->second.Get("transmissionFactor").GetNumberAsDouble() ==
                  Approx(m.transparency));
            CHECK(mat.extensions.at("KHR_materials_ior").Get("ior").GetNumberAsDouble() ==
                  Approx(m.refractive_index));
        }
    }
    // The camera, at its keyed place at t = 0, with the light that rides with it.
    const tinygltf::Node &camera = node_named(model, "camera");
    REQUIRE(camera.camera == 0);
    const CameraState start = *doc.keyframes()[0].camera;
    CHECK(model.cameras[0].perspective.yfov == Approx(glm::radians(start.fov_degrees)));
    CHECK(camera.translation ==
          std::vector<double>{start.position.x, start.position.y, start.position.z});
    REQUIRE(camera.children.size() == 1);
    CHECK(model.nodes[static_cast<size_t>(camera.children[0])].extensions.count(
              "KHR_lights_punctual") == 1);
    CHECK(model.scenes[0].extras.Get("animator").Get("skybox").Get<std::string>() ==
          doc.settings().skybox);
}

TEST_CASE("a course scene's tree, lights and shear read back as its reader made them") {
    const auto dir = test::fresh_dir("export_a4");
    const auto file = test::source_dir() / "tests/data/cs488/a4_hier.lua";
    const auto r =
        test::run_animator("export " + file.string() + " --to " + (dir / "a4.glb").string());
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    const tinygltf::Model model = read_back(dir / "a4.glb");
    const Document doc = open_document(env().plugins, file).document;
    // Every model a node, under its parent's node.
    for (const Model &m : doc.models()) {
        CAPTURE(m.name);
        const tinygltf::Node &n = node_named(model, m.name);
        for (int c : n.children) {
            const std::string &child = model.nodes[static_cast<size_t>(c)].name;
            const int index = doc.find_model(child);
            REQUIRE(index >= 0);
            CHECK(doc.models()[static_cast<size_t>(index)].parent == doc.find_model(m.name));
        }
    }
    size_t children = 0;
    for (const Model &m : doc.models()) children += m.parent >= 0;
    size_t linked = 0;
    for (const Model &m : doc.models()) linked += node_named(model, m.name).children.size();
    CHECK(linked == children);
    // The document's lights, each a point light at its place: no light rides with the camera.
    REQUIRE(model.lights.size() == doc.settings().lights.size());
    for (const Light &l : doc.settings().lights) {
        const tinygltf::Node &n = node_named(model, l.name);
        CHECK(n.translation == std::vector<double>{l.position.x, l.position.y, l.position.z});
        CHECK(n.extensions.count("KHR_lights_punctual") == 1);
    }
    CHECK(node_named(model, "camera").children.empty());
}

TEST_CASE("a sheared model's mesh is its rest shape, which glTF nodes cannot hold") {
    const auto dir = test::fresh_dir("export_shear");
    const auto file = test::source_dir() / "tests/data/cs488/sheared_puppet.lua";
    const auto r =
        test::run_animator("export " + file.string() + " --to " + (dir / "puppet.glb").string());
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    const tinygltf::Model model = read_back(dir / "puppet.glb");
    const Document doc = open_document(env().plugins, file).document;
    size_t sheared = 0;
    for (const Model &m : doc.models()) {
        if (m.rest == glm::dmat3(1.0) || m.mesh.empty()) continue;
        ++sheared;
        CAPTURE(m.name);
        const tinygltf::Node &n = node_named(model, m.name);
        const tinygltf::Primitive &p = model.meshes[static_cast<size_t>(n.mesh)].primitives[0];
        const tinygltf::Accessor &a =
            model.accessors[static_cast<size_t>(p.attributes.at("POSITION"))];
        const tinygltf::BufferView &v = model.bufferViews[static_cast<size_t>(a.bufferView)];
        const float *positions = reinterpret_cast<const float *>(model.buffers[0].data.data() +
                                                                 v.byteOffset + a.byteOffset);
        const Mesh mesh =
            load_mesh(env().assets.resolve(ANI_ASSET_MESH, m.mesh, file).value()).mesh;
        REQUIRE(a.count == mesh.positions.size());
        double worst = 0.0;
        for (size_t i = 0; i < a.count; ++i) {
            const glm::dvec3 want = m.rest * mesh.positions[i];
            worst = std::max(worst, glm::length(glm::dvec3(positions[3 * i], positions[3 * i + 1],
                                                           positions[3 * i + 2]) -
                                                want));
        }
        CHECK(worst < 1e-5);
    }
    CHECK(sheared > 0);
}

TEST_CASE("an export ends at --to S, and --from starts its animation at 0") {
    const auto dir = test::fresh_dir("export_range");
    const std::string drop = (test::source_dir() / "assets/animations/drop.ani").string();
    auto r = test::run_animator("export " + drop + " --to " + (dir / "a.glb").string() +
                                " --from 0.5 --to 2");
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    const tinygltf::Model model = read_back(dir / "a.glb");
    REQUIRE(model.animations.size() == 1);
    for (const auto &s : model.animations[0].samplers) {
        const tinygltf::Accessor &times = model.accessors[static_cast<size_t>(s.input)];
        CHECK(times.minValues[0] == 0.0);
        CHECK(times.maxValues[0] == Approx(1.5));
    }
}

TEST_CASE(
    "export: bad requests are refused with what was expected, and a previous file is left whole") {
    const auto dir = test::fresh_dir("export_refused");
    const std::string drop = (test::source_dir() / "assets/animations/drop.ani").string();
    const auto previous = dir / "keep.glb";
    test::write_file(previous, "a previous export");

    auto r = test::run_animator("export " + drop + " --to " + (dir / "x.obj").string());
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.out, Catch::Contains("expected the file to write (ending in .glb or .gltf)"));
    r = test::run_animator("export " + drop);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.out, Catch::Contains("the file to write is missing"));
    r = test::run_animator("export " + drop + " --to " + previous.string() + " --to b.glb");
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.out, Catch::Contains("two files to write"));
    r = test::run_animator("export " + (dir / "none.ani").string() + " --to " + previous.string());
    CHECK(r.exit_code == 1);
    CHECK_THAT(r.out, Catch::Contains("none.ani"));
    r = test::run_animator("export " + drop + " --to " + previous.string() + " --until 99");
    CHECK(r.exit_code == 1);
    r = test::run_animator("export " + drop + " --to " + previous.string() + " --from 8 --to 2");
    CHECK(r.exit_code == 1);
    CHECK_THAT(r.out, Catch::Contains("--from 8 s is after the export's end, 2 s"));
    CHECK(test::read_file(previous) == "a previous export");
    r = test::run_animator("export " + drop + " --to " + (dir / "no/such/folder/a.glb").string());
    CHECK(r.exit_code == 1);
    CHECK_THAT(r.out, Catch::Contains("a.glb: cannot be written"));
    // A successful export replaces it, leaving nothing beside it.
    r = test::run_animator("export " + drop + " --to " + previous.string());
    CHECK(r.exit_code == 0);
    CHECK(test::read_file(previous).substr(0, 4) == "glTF");
    size_t files = 0;
    for (const auto &e : std::filesystem::directory_iterator(dir)) files += e.is_regular_file();
    CHECK(files == 1);
}
