// Keys familiar from Blender and Maya, without a window (editor_session.hpp): I keys the
// selected models where they are drawn now (the interpolation's place between keys, the
// physics' after the last one: checked against the closed forms), ALT+I takes those keys away,
// A / ALT+A select all or none, H / ALT+H hide and show; all undoable where they are edits.
#include "editor/editor_session.hpp"
#include "timeline/keyed_motion.hpp"

#include "support.hpp"

#include <catch2/catch.hpp>

using namespace animator;
using namespace animator::test;
using Catch::Matchers::WithinAbs;

namespace fs = std::filesystem;

namespace {

fs::path drop_ani() { return source_dir() / "assets" / "animations" / "drop.ani"; }

const ModelState &key_of(const EditorSession &s, std::int64_t ms, const std::string &name) {
    const int k = s.document().find_keyframe(ms);
    REQUIRE(k >= 0);
    const auto &state = s.document().keyframes()[static_cast<size_t>(k)].states[static_cast<size_t>(s.document().find_model(name))];
    REQUIRE(state);
    return *state;
}

// A cube keyed at x = 0 (t = 0) and x = 4 (t = 2 s), linear between.
const char *kSlideAni = R"(animator-ani 1
settings
  max_time_ms 4000
  gravity 9.81
  down y
  cel_shading false
  skybox ""
  physics_backend "physics.custom"
end
model "cube"
  mesh "cube"
end
keyframe 0
  camera position 0 3 12 rotation 1 0 0 0 fov 50
  state "cube" center 0 1 0 angles 0 0 0 scale 1 1 1 turn 0 0 0
end
keyframe 2000
  state "cube" center 4 1 0 angles 90 0 0 scale 1 1 1 turn 1 0 0
end
)";

} // namespace

TEST_CASE("I keys a falling ball where gravity has taken it, u takes the key back", "[session][keys]") {
    Environment env;
    EditorSession s(env);
    std::string error;
    REQUIRE(s.open(drop_ani(), error));
    s.set_mode(EditMode::Translate);
    s.click(s.document().find_model("ball"), false);
    s.set_time_ms(500);
    const Document before = s.document();
    bool ok = false;
    const std::string said = s.insert_keys(&ok);
    INFO(said);
    REQUIRE(ok);
    CHECK(said.find("'ball'") != std::string::npos);
    // Dropped from y = 5 at rest: y = 5 - g t^2 / 2 at 0.5 s (it meets the floor at 0.90 s).
    const ModelState &key = key_of(s, 500, "ball");
    CHECK_THAT(key.center.y, WithinAbs(5.0 - 0.5 * 9.81 * 0.25, 1e-9));
    CHECK_THAT(key.center.x, WithinAbs(0.0, 1e-12));
    CHECK(s.dirty());
    // Only the selected model is keyed there; the floor is not.
    const auto &k = s.document().keyframes()[static_cast<size_t>(s.document().find_keyframe(500))];
    CHECK_FALSE(k.states[static_cast<size_t>(s.document().find_model("floor"))]);
    CHECK_FALSE(k.camera);
    // Keyed already: a second I changes nothing.
    const Document keyed = s.document();
    CHECK(s.insert_keys(&ok).find("already keyed") != std::string::npos);
    CHECK(s.document() == keyed);
    REQUIRE(s.undo());
    CHECK(s.document() == before);
}

TEST_CASE("I keys a model between its keys where the interpolation has it, and ALT+I deletes that key", "[session][keys]") {
    const fs::path dir = fresh_dir("session_keys");
    write_file(dir / "slide.ani", kSlideAni);
    Environment env;
    EditorSession s(env);
    std::string error;
    REQUIRE(s.open(dir / "slide.ani", error));
    s.set_mode(EditMode::Rotate);
    s.click(0, false);
    s.set_time_ms(500);
    for (int i = 0; i < 1000 && s.bake_some(0.05); ++i) {
    }
    const ModelPose later = s.timeline().evaluate(1.25).models[0]; // before the new key
    bool ok = false;
    REQUIRE(s.insert_keys(&ok).find("keyed 'cube' at 0.500 s") == 0);
    REQUIRE(ok);
    // A quarter of the way from x = 0 to x = 4, and of the turn to 90 degrees, which the key
    // at 2 s makes clockwise (turn 1: the angle decreases, 0 -> -270): -67.5, stored as 292.5.
    const ModelState key = key_of(s, 500, "cube");
    CHECK_THAT(key.center.x, WithinAbs(1.0, 1e-9));
    CHECK_THAT(key.center.y, WithinAbs(1.0, 1e-9));
    CHECK_THAT(key.angles.x, WithinAbs(292.5, 1e-9));
    // The new key turns clockwise too, so the motion after it is as it was: halfway from 0.5 s
    // to 2 s, x = 2.5 and the angle 292.5 - 202.5 / 2 = 191.25 (the shorter way would go back).
    CHECK(key.turn.x == 1.0);
    for (int i = 0; i < 1000 && s.bake_some(0.05); ++i) {
    }
    const ModelPose now = s.timeline().evaluate(1.25).models[0];
    CHECK_THAT(now.center.x, WithinAbs(2.5, 1e-9));
    CHECK_THAT(now.angles.x, WithinAbs(191.25, 1e-9));
    CHECK_THAT(now.angles.x, WithinAbs(later.angles.x, 1e-9));
    CHECK_THAT(now.center.x, WithinAbs(later.center.x, 1e-9));

    // ALT+I: the key at 0.5 s goes (and its keyframe, keying nothing else); the one at 0 s stays.
    const std::string deleted = s.delete_keys_here(&ok);
    INFO(deleted);
    CHECK(ok);
    CHECK(s.document().find_keyframe(500) < 0);
    s.set_time_ms(0);
    CHECK(s.delete_keys_here(&ok).find("initial placement") != std::string::npos);
    CHECK_FALSE(ok);
    CHECK(s.document().find_keyframe(0) == 0);
}

TEST_CASE("I with nothing selected keys the camera", "[session][keys]") {
    const fs::path dir = fresh_dir("session_keys_camera");
    write_file(dir / "slide.ani", kSlideAni);
    Environment env;
    EditorSession s(env);
    std::string error;
    REQUIRE(s.open(dir / "slide.ani", error));
    s.set_time_ms(1000);
    bool ok = false;
    CHECK(s.insert_keys(&ok).find("the camera") != std::string::npos);
    CHECK(ok);
    const int k = s.document().find_keyframe(1000);
    REQUIRE(k >= 0);
    const Keyframe &key = s.document().keyframes()[static_cast<size_t>(k)];
    REQUIRE(key.camera);
    CHECK(key.camera->position == glm::dvec3(0, 3, 12)); // keyed only at 0: it stays there
    CHECK_FALSE(key.states[0]);
}

TEST_CASE("A selects every shown model, ALT+A none, H hides the selection, ALT+H shows all", "[session][keys]") {
    Environment env;
    EditorSession s(env);
    std::string error;
    REQUIRE(s.open(source_dir() / "assets" / "scenes" / "simple.lua", error));
    const int count = static_cast<int>(s.document().models().size());
    REQUIRE(count >= 3);
    s.select_all();
    CHECK(static_cast<int>(s.selection().size()) == count);
    CHECK(s.last_selected() >= 0);
    s.select_none();
    CHECK(s.selection().empty());
    CHECK(s.last_selected() == -1);

    const int ball = s.document().find_model("ball"), cube = s.document().find_model("cube");
    s.click(ball, false);
    s.click(cube, true);
    CHECK(s.hide_selected() == 2);
    CHECK(s.hidden(ball));
    CHECK(s.hidden(cube));
    CHECK(s.selection().empty()); // what cannot be seen is not left selected
    s.select_all();
    CHECK(static_cast<int>(s.selection().size()) == count - 2); // hidden ones are not selected
    CHECK_FALSE(s.dirty()); // views, not edits
    CHECK(s.show_all() == 2);
    CHECK(s.hidden_models().empty());
}
