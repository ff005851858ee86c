// Motion paths (editor/motion_paths.hpp) against the closed forms they sample: a ball keyed
// linearly from x = 0 to x = 2.4 over 2 s, then dropped from y = 5 onto a floor (it touches it
// with its center at y = 1, 4 m below, at sqrt(2 * 4 / g)); and the session's paths following a
// drag before it is dropped (the dragged document's own bake), without editing anything.
#include "editor/editor_session.hpp"
#include "editor/motion_paths.hpp"
#include "editor/time_steps.hpp"

#include "support.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>

using namespace animator;
using namespace animator::test;
using Catch::Matchers::WithinAbs;

namespace fs = std::filesystem;

namespace {

// drop.ani's ball, keyed to slide 2.4 m right over its first 2 s (linearly: without Dynamics its
// keys are interpolated by the document's interpolator) before it falls, and stops on the floor
// (without Dynamics a contact stops it).
const char *kSlideThenDrop = R"(animator-ani 1
settings
  max_time_ms 4000
  gravity 9.81
  down y
  physics_backend "physics.custom"
end
model "floor"
  mesh "plane"
end
model "ball"
  mesh "sphere"
  gravity true
end
keyframe 0
  camera position 0 3 12 rotation 1 0 0 0 fov 50
  state "floor" center 0 0 0 angles 0 0 0 scale 10 1 10 turn 0 0 0
  state "ball" center 0 5 0 angles 0 0 0 scale 1 1 1 turn 0 0 0
end
keyframe 2000
  state "ball" center 2.4 5 0 angles 0 0 0 scale 1 1 1 turn 0 0 0
end
)";

fs::path scene_file() {
    const fs::path path = fresh_dir("motion_paths") / "slide.ani";
    std::ofstream(path) << kSlideThenDrop;
    return path;
}

void bake_all(EditorSession &s) {
    for (int i = 0; i < 100000 && s.bake_some(0.05); ++i) {
    }
    REQUIRE_FALSE(s.baking());
}

} // namespace

TEST_CASE("a motion path samples every frame of keyed and free motion, with its keys and hits", "[paths]") {
    Environment env;
    EditorSession s(env);
    std::string error;
    REQUIRE(s.open(scene_file(), error));
    bake_all(s);
    const int ball = s.document().find_model("ball");
    const auto paths = sample_motion_paths(s.document(), s.timeline(), {ball}, 4.0, kStepFramesPerSecond);
    REQUIRE(paths.size() == 1);
    const MotionPath &p = paths[0];
    CHECK(p.model == ball);
    REQUIRE(p.frames.size() == 121); // 0 .. 4 s at 30 frames a second
    // Keyed: linear in x, level at y = 5, over the first 2 s.
    for (int k = 0; k <= 60; ++k) {
        CHECK_THAT(p.frames[static_cast<size_t>(k)].x, WithinAbs(2.4 * (k / 30.0) / 2.0, 1e-9));
        CHECK_THAT(p.frames[static_cast<size_t>(k)].y, WithinAbs(5.0, 1e-9));
    }
    // Free after its last key, from rest (without Dynamics its keys' velocity is not kept):
    // straight down, g t^2 / 2, until the floor stops it with its center at y = 1.
    const double g = 9.81, fall = std::sqrt(2.0 * 4.0 / g);
    for (int k = 61; k <= 120; ++k) {
        const double t = k / 30.0 - 2.0;
        CHECK_THAT(p.frames[static_cast<size_t>(k)].x, WithinAbs(2.4, 1e-9));
        CHECK_THAT(p.frames[static_cast<size_t>(k)].y, WithinAbs(t < fall ? 5.0 - g * t * t / 2.0 : 1.0, 1e-6));
    }
    // Its keys where they put it; its first bounce where it meets the floor.
    REQUIRE(p.keys.size() == 2);
    CHECK(p.keys[0] == glm::dvec3(0, 5, 0));
    CHECK(p.keys[1] == glm::dvec3(2.4, 5, 0));
    REQUIRE(!p.hits.empty());
    CHECK_THAT(p.hits[0].x, WithinAbs(2.4, 1e-9));
    CHECK_THAT(p.hits[0].y, WithinAbs(1.0, 1e-6)); // meshes are single precision
    // The floor is in no path it was not asked for.
    CHECK(sample_motion_paths(s.document(), s.timeline(), {}, 4.0, 30.0).empty());
}

TEST_CASE("the paths follow a drag before it is dropped, and the drag edits nothing until then", "[paths]") {
    Environment env;
    EditorSession s(env);
    std::string error;
    REQUIRE(s.open(scene_file(), error));
    bake_all(s);
    const int ball = s.document().find_model("ball");
    s.click(ball, false);
    CHECK(s.path_models().empty()); // paths are off until asked for
    s.set_paths_on(true);
    REQUIRE(s.path_models() == std::vector<int>{ball});
    const auto before = s.motion_paths();
    REQUIRE(before.size() == 1);

    // Drag the ball's second key (at 2 s) 100 px right in Translate mode.
    s.set_time_ms(2000);
    s.set_mode(EditMode::Translate);
    s.begin_drag(DragButton::Right, 720);
    s.update_drag({100.0, 0.0});
    for (int i = 0; i < 10000 && s.preview_some(0.05); ++i) {
    }
    const double moved = s.frame().models[static_cast<size_t>(ball)].center.x - 2.4; // the drag's preview
    REQUIRE(moved > 0.5);
    const auto during = s.motion_paths();
    REQUIRE(during.size() == 1);
    REQUIRE(during[0].frames.size() == before[0].frames.size());
    // Keyed: now from 0 to 2.4 + moved; free: the same fall from there.
    for (int k = 0; k <= 60; ++k)
        CHECK_THAT(during[0].frames[static_cast<size_t>(k)].x, WithinAbs((2.4 + moved) * (k / 30.0) / 2.0, 1e-9));
    const double t = 0.5;
    CHECK_THAT(during[0].frames[75].x, WithinAbs(2.4 + moved, 1e-9));
    CHECK_THAT(during[0].frames[75].y, WithinAbs(5.0 - 9.81 * t * t / 2.0, 1e-9));
    CHECK(during[0].keys[1].x == Approx(2.4 + moved));
    // Nothing edited yet.
    CHECK(s.document().keyframes()[1].states[static_cast<size_t>(ball)]->center.x == 2.4);
    CHECK_FALSE(s.dirty());

    // Dropped: the edit is made, and the main bake's paths are the ones the drag showed.
    s.end_drag();
    bake_all(s);
    const auto after = s.motion_paths();
    REQUIRE(after.size() == 1);
    REQUIRE(after[0].frames.size() == during[0].frames.size());
    for (size_t k = 0; k < after[0].frames.size(); ++k)
        CHECK(glm::length(after[0].frames[k] - during[0].frames[k]) < 1e-9);
    // Cancelled instead: the paths go back to the document's.
    s.begin_drag(DragButton::Right, 720);
    s.update_drag({0.0, -80.0});
    for (int i = 0; i < 10000 && s.preview_some(0.05); ++i) {
    }
    CHECK(s.motion_paths()[0].frames[60].y > 5.5);
    s.cancel_drag();
    CHECK_THAT(s.motion_paths()[0].frames[60].y, WithinAbs(5.0, 1e-9));
}

TEST_CASE("a pinned path shows without selection, paths off shows only pinned ones", "[paths]") {
    Environment env;
    EditorSession s(env);
    std::string error;
    REQUIRE(s.open(scene_file(), error));
    const int floor = s.document().find_model("floor"), ball = s.document().find_model("ball");
    s.click(floor, false);
    s.pin_path(ball, true);
    CHECK(s.path_models() == std::vector<int>{ball});
    s.set_paths_on(true);
    CHECK(s.path_models() == std::vector<int>{floor, ball});
    s.pin_path(ball, false);
    s.click(-1, false);
    CHECK(s.path_models().empty());
}
