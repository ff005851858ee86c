// Add model, Duplicate and Delete without a window (editor_session.hpp, model_edits.hpp): each
// one undoable edit; the session's per-model state (meshes, selection, hidden and pinned models)
// follows the models through the edit, its undo and its redo; names are unique; the mesh of a
// file is named relative to the document under its folder, else absolutely; the export reopens
// with the new models.
#include "editor/editor_session.hpp"

#include "support.hpp"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <cmath>

using namespace animator;
using namespace animator::test;

namespace fs = std::filesystem;

namespace {

fs::path simple_lua() { return source_dir() / "assets" / "scenes" / "simple.lua"; }
fs::path puppet_lua() { return source_dir() / "assets" / "scenes" / "puppet.lua"; }

void bake_all(EditorSession &s) {
    for (int i = 0; i < 100000 && s.bake_some(0.05); ++i) {
    }
    REQUIRE_FALSE(s.baking());
    REQUIRE(s.bake_error().empty());
}

int index_of(const EditorSession &s, const std::string &name) { return s.document().find_model(name); }

const ModelState &key0(const EditorSession &s, const std::string &name) {
    const int i = index_of(s, name);
    REQUIRE(i >= 0);
    return *s.document().keyframe_at(0).states[static_cast<size_t>(i)];
}

std::vector<std::string> names(const EditorSession &s) {
    std::vector<std::string> out;
    for (const Model &m : s.document().models()) out.push_back(m.name);
    return out;
}

// Every per-model list of the session is as long as the model list, and each model's mesh is
// the one its id names.
void check_in_step(const EditorSession &s) {
    const auto &models = s.document().models();
    REQUIRE(s.meshes().size() == models.size());
    for (int m : s.selection()) CHECK(m < static_cast<int>(models.size()));
    CHECK(s.last_selected() < static_cast<int>(models.size()));
    for (size_t m = 0; m < models.size(); ++m) CHECK((s.meshes()[m] != nullptr) == !models[m].mesh.empty());
    for (const auto &k : s.document().keyframes()) CHECK(k.states.size() == models.size());
}

// A regular tetrahedron in ASCII PLY: corners at distance sqrt(3) from the origin.
const char *kTetraPly =
    "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 4\nproperty list uchar int vertex_indices\nend_header\n"
    "1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n3 1 3 2\n3 0 2 3\n3 0 3 1\n3 0 1 2\n";

const char *kBallAni = R"(animator-ani 1
settings
  max_time_ms 5000
  gravity 9.81
  down y
  cel_shading false
  skybox ""
  physics_backend "physics.custom"
end
model "ball"
  mesh "sphere"
end
keyframe 0
  camera position 0 0 12 rotation 1 0 0 0 fov 50
  state "ball" center -3 0 0 angles 0 0 0 scale 1 1 1 turn 0 0 0
end
)";

} // namespace

TEST_CASE("Add model from the asset path: a unique name, the default material, keyed at t = 0 where the view looks, selected, one undo", "[session][models]") {
    Environment env;
    EditorSession s(env);
    std::string error, message;
    REQUIRE(s.open(simple_lua(), error));
    s.set_time_ms(3000); // away from t = 0: the key still goes to t = 0
    const std::size_t before = s.document().models().size();
    REQUIRE(s.add_model_from_asset("cube", message));
    CHECK(message == "added 'cube.001'");
    REQUIRE(s.document().models().size() == before + 1);
    const Model &added = s.document().models().back();
    CHECK(added.name == "cube.001");
    CHECK(added.mesh == "cube");
    CHECK(added.parent == -1);
    CHECK(added.material == Material{});
    CHECK(added.texture.empty());
    CHECK_FALSE(added.dynamics);
    CHECK(s.document().keys_of(static_cast<int>(before)).size() == 1); // t = 0 only
    CHECK(s.selection() == std::set<int>{static_cast<int>(before)});
    CHECK(s.last_selected() == static_cast<int>(before));
    check_in_step(s);
    CHECK(s.meshes().back() == s.meshes()[static_cast<size_t>(index_of(s, "cube"))]); // the same mesh, loaded once
    // simple.lua's camera looks from (0, 4, 14) at (0, 1, 0): the model is on that line.
    const glm::dvec3 eye(0, 4, 14), ahead = glm::normalize(glm::dvec3(0, 1, 0) - eye);
    const glm::dvec3 c = key0(s, "cube.001").center;
    CHECK(glm::length(glm::cross(c - eye, ahead)) < 1e-6);
    CHECK(glm::dot(c - eye, ahead) > 5.0);
    CHECK(s.dirty());

    // A second one counts on; undo takes one at a time, redo brings it back.
    REQUIRE(s.add_model_from_asset("cube", message));
    CHECK(message == "added 'cube.002'");
    REQUIRE(s.undo());
    CHECK(s.document().models().size() == before + 1);
    CHECK(s.selection().empty());
    check_in_step(s);
    REQUIRE(s.undo());
    CHECK(s.document().models().size() == before);
    check_in_step(s);
    CHECK_FALSE(s.dirty());
    REQUIRE(s.redo());
    CHECK(names(s).back() == "cube.001");
    check_in_step(s);
    bake_all(s);

    // A mesh that is not there: refused, said, nothing changes.
    const auto version = s.version();
    CHECK_FALSE(s.add_model_from_asset("teapot", message));
    CHECK_THAT(message, Catch::StartsWith("cannot add a model: mesh 'teapot' not found"));
    CHECK(s.version() == version);
    CHECK_FALSE(s.add_model_from_file(fresh_dir("models_missing") / "gone.ply", message));
    CHECK_THAT(message, Catch::Contains("gone.ply: no such mesh file"));
}

TEST_CASE("Duplicate copies the selection beside itself (its bounding sphere's diameter along +x at every key), selects the copies, hidden models stay hidden", "[session][models]") {
    Environment env;
    EditorSession s(env);
    std::string error, message;
    REQUIRE(s.open(simple_lua(), error));
    const int cube = index_of(s, "cube"), cone = index_of(s, "cone"), torus = index_of(s, "torus");
    s.set_hidden(cone, true);
    s.pin_path(torus, true);
    s.click(cube, false);
    REQUIRE(s.duplicate_selected(message));
    CHECK(message == "duplicated 'cube' as 'cube.001'");
    const int copy = index_of(s, "cube.001");
    REQUIRE(copy == 6);
    CHECK(s.selection() == std::set<int>{copy});
    CHECK(s.last_selected() == copy);
    CHECK(s.hidden(cone));
    CHECK_FALSE(s.hidden(copy));
    CHECK(s.path_pinned(torus));
    check_in_step(s);
    // The cube's mesh spans -1..1: bounding sphere of radius sqrt(3), so 2 sqrt(3) along x.
    Model expected = s.document().models()[static_cast<size_t>(cube)];
    expected.name = "cube.001";
    CHECK(s.document().models()[static_cast<size_t>(copy)] == expected);
    const glm::dvec3 moved = key0(s, "cube.001").center - key0(s, "cube").center;
    CHECK_THAT(moved.x, Catch::Matchers::WithinRel(2.0 * std::sqrt(3.0), 1e-9));
    CHECK(moved.y == 0.0);
    CHECK(moved.z == 0.0);
    CHECK(key0(s, "cube.001").angles == key0(s, "cube").angles);

    // A key of the cube at 2 s: a second copy has it too, moved alike.
    s.click(cube, false);
    s.set_time_ms(2000);
    s.set_mode(EditMode::Translate);
    s.begin_drag(DragButton::Right, 500);
    s.update_drag({40.0, 0.0});
    s.end_drag();
    REQUIRE(s.document().find_keyframe(2000) >= 0);
    s.click(cube, false);
    REQUIRE(s.duplicate_selected(message));
    CHECK(message == "duplicated 'cube' as 'cube.002'");
    const auto &k = s.document().keyframe_at(2000);
    REQUIRE(k.states[static_cast<size_t>(index_of(s, "cube.002"))].has_value());
    const glm::dvec3 at2 = k.states[static_cast<size_t>(index_of(s, "cube.002"))]->center -
                           k.states[static_cast<size_t>(cube)]->center;
    CHECK_THAT(at2.x, Catch::Matchers::WithinRel(2.0 * std::sqrt(3.0), 1e-9));
    CHECK_FALSE(k.states[static_cast<size_t>(index_of(s, "cube.001"))].has_value()); // copied before the key
    bake_all(s);

    // Undo both: the hidden cone and the pinned torus are where they were.
    REQUIRE(s.undo());
    REQUIRE(s.undo()); // the key at 2 s
    REQUIRE(s.undo());
    CHECK(s.document().models().size() == 6);
    CHECK(s.hidden(cone));
    CHECK(s.path_pinned(torus));
    check_in_step(s);
    CHECK_FALSE(s.dirty());

    // Nothing selected: nothing to duplicate, said.
    s.click(-1, false);
    CHECK_FALSE(s.duplicate_selected(message));
    CHECK(message == "nothing selected to duplicate");
}

TEST_CASE("Duplicate of a joint copies what hangs under it, the copies under the joint's copy", "[session][models]") {
    Environment env;
    EditorSession s(env);
    std::string error, message;
    REQUIRE(s.open(puppet_lua(), error));
    s.click(index_of(s, "left_shoulder"), false);
    REQUIRE(s.duplicate_selected(message));
    CHECK(message == "duplicated 'left_shoulder' as 'left_shoulder.001' with the model under it");
    const int joint = index_of(s, "left_shoulder.001"), arm = index_of(s, "left_arm.001");
    REQUIRE(joint >= 0);
    REQUIRE(arm >= 0);
    CHECK(s.document().models()[static_cast<size_t>(arm)].parent == joint);
    CHECK(s.document().models()[static_cast<size_t>(joint)].parent == index_of(s, "puppet"));
    CHECK(s.selection() == std::set<int>{joint});
    // The arm keeps its place under its joint; the joint moved.
    CHECK(key0(s, "left_arm.001").center == key0(s, "left_arm").center);
    CHECK(key0(s, "left_shoulder.001").center.x > key0(s, "left_shoulder").center.x);
    check_in_step(s);
    bake_all(s);
}

TEST_CASE("Delete removes the selection and what is under it, undo brings them back with their meshes and visibility", "[session][models]") {
    Environment env;
    EditorSession s(env);
    std::string error, message;
    REQUIRE(s.open(puppet_lua(), error));
    const auto meshes_before = s.meshes();
    const auto names_before = names(s);
    const int right_arm = index_of(s, "right_arm");
    s.set_hidden(right_arm, true);
    s.click(index_of(s, "left_shoulder"), false);
    CHECK(s.models_to_delete() == std::set<int>{index_of(s, "left_shoulder"), index_of(s, "left_arm")});
    REQUIRE(s.delete_selected(message));
    CHECK(message == "deleted 'left_shoulder' and the model under it");
    CHECK(names(s) == std::vector<std::string>{"puppet", "torso", "head", "right_shoulder", "right_arm"});
    CHECK(s.selection().empty());
    CHECK(s.last_selected() == -1);
    CHECK(s.hidden(index_of(s, "right_arm")));
    CHECK(s.hidden_models() == std::set<int>{index_of(s, "right_arm")});
    CHECK(s.meshes()[static_cast<size_t>(index_of(s, "right_arm"))] == meshes_before[static_cast<size_t>(right_arm)]);
    CHECK(s.document().models()[static_cast<size_t>(index_of(s, "right_arm"))].parent == index_of(s, "right_shoulder"));
    check_in_step(s);
    bake_all(s);

    REQUIRE(s.undo());
    CHECK(names(s) == names_before);
    CHECK(s.meshes() == meshes_before);
    CHECK(s.hidden_models() == std::set<int>{right_arm});
    CHECK_FALSE(s.dirty());
    check_in_step(s);
    bake_all(s);
    REQUIRE(s.redo());
    CHECK(names(s).size() == 5);
    check_in_step(s);

    // Two selected, one of them with a child: both and the child.
    s.click(index_of(s, "head"), false);
    s.click(index_of(s, "right_shoulder"), true);
    REQUIRE(s.delete_selected(message));
    CHECK(message == "deleted 2 models and the model under them");
    CHECK(names(s) == std::vector<std::string>{"puppet", "torso"});
    CHECK(s.hidden_models().empty());
    check_in_step(s);
    s.click(-1, false);
    CHECK_FALSE(s.delete_selected(message));
    CHECK(message == "nothing selected to delete");
}

TEST_CASE("A mesh file under the document's folder is named relative to it, else absolutely, the export reopens with the new models", "[session][models]") {
    const fs::path dir = fresh_dir("models_export");
    write_file(dir / "scene.ani", kBallAni);
    fs::create_directories(dir / "shapes");
    write_file(dir / "shapes" / "tetra.ply", kTetraPly);
    const fs::path outside = fresh_dir("models_outside") / "far.ply";
    write_file(outside, kTetraPly);

    Environment env;
    EditorSession s(env);
    std::string error, message;
    REQUIRE(s.open(dir / "scene.ani", error));
    const bool added = s.add_model_from_file(dir / "shapes" / "tetra.ply", message);
    INFO(message);
    REQUIRE(added);
    CHECK(message == "added 'tetra'");
    CHECK(s.document().models().back().mesh == "shapes/tetra.ply");
    CHECK_THAT(s.meshes().back()->bound_radius, Catch::Matchers::WithinRel(std::sqrt(3.0), 1e-6));
    // The camera at (0, 0, 12) looks down -z; the ball is 12 m ahead: the tetrahedron too.
    CHECK(glm::length(key0(s, "tetra").center - glm::dvec3(0, 0, 0)) < 1e-9);
    REQUIRE(s.duplicate_selected(message));
    CHECK(message == "duplicated 'tetra' as 'tetra.001'");
    REQUIRE(s.add_model_from_file(outside, message));
    CHECK(s.document().models().back().mesh == fs::weakly_canonical(outside).generic_string());
    s.click(index_of(s, "ball"), false);
    REQUIRE(s.delete_selected(message));
    CHECK(message == "deleted 'ball'");
    bake_all(s);
    const auto result = s.export_animation();
    REQUIRE(result.ok);
    CHECK(result.path == dir / "scene.ani");

    EditorSession again(env);
    REQUIRE(again.open(dir / "scene.ani", error));
    CHECK(again.warnings().empty());
    CHECK(names(again) == std::vector<std::string>{"tetra", "tetra.001", "far"});
    CHECK(again.document() == s.document());
    check_in_step(again);
    CHECK_THAT(key0(again, "tetra.001").center.x, Catch::Matchers::WithinRel(2.0 * std::sqrt(3.0), 1e-9));
}
