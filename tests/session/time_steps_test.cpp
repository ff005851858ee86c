// The arrow keys' arithmetic (editor/time_steps.hpp) and the session's use of it: Left/Right
// step one frame of 30 fps, Up/Down jump between keyframes, both pause playback.
#include "editor/editor_session.hpp"
#include "editor/time_steps.hpp"

#include "support.hpp"

#include <catch2/catch.hpp>

using namespace animator;
using namespace animator::test;

TEST_CASE("a frame step lands on the 30 fps grid and walks it without drift", "[time_steps]") {
    // Frames at round(k * 1000 / 30): 0, 33, 67, 100, 133, ...
    CHECK(step_frames(0, 1, 30.0, 5000) == 33);
    CHECK(step_frames(33, 1, 30.0, 5000) == 67);
    CHECK(step_frames(67, 1, 30.0, 5000) == 100);
    CHECK(step_frames(100, -1, 30.0, 5000) == 67);
    CHECK(step_frames(67, -1, 30.0, 5000) == 33);
    // Thirty steps from 0 are exactly one second, and thirty back return to 0.
    std::int64_t t = 0;
    for (int i = 0; i < 30; ++i) t = step_frames(t, 1, 30.0, 5000);
    CHECK(t == 1000);
    for (int i = 0; i < 30; ++i) t = step_frames(t, -1, 30.0, 5000);
    CHECK(t == 0);
}

TEST_CASE("from between two frames a step goes to the neighbouring frame, not past it", "[time_steps]") {
    CHECK(step_frames(50, 1, 30.0, 5000) == 67);
    CHECK(step_frames(50, -1, 30.0, 5000) == 33);
    CHECK(step_frames(34, -1, 30.0, 5000) == 33);
}

TEST_CASE("frame steps stop at 0 and at the max time, even off the grid", "[time_steps]") {
    CHECK(step_frames(0, -1, 30.0, 5000) == 0);
    CHECK(step_frames(4990, 1, 30.0, 5000) == 5000); // 5000 is frame 150
    CHECK(step_frames(5000, 1, 30.0, 5000) == 5000);
    CHECK(step_frames(1000, 1, 30.0, 1010) == 1010); // the next frame (1033) is past the end
    CHECK(step_frames(1010, -1, 30.0, 1010) == 1000);
}

TEST_CASE("Up and Down find the previous and next keyframe, and stay put past the last", "[time_steps]") {
    Document doc;
    for (std::int64_t ms : {2000, 4500}) {
        Keyframe k;
        k.time_ms = ms;
        k.states.resize(doc.models().size());
        doc.insert_keyframe(k);
    }
    CHECK(neighbour_keyframe(doc, 0, 1) == 2000);
    CHECK(neighbour_keyframe(doc, 2000, 1) == 4500);
    CHECK(neighbour_keyframe(doc, 3000, 1) == 4500);
    CHECK(neighbour_keyframe(doc, 4500, 1) == 4500);
    CHECK(neighbour_keyframe(doc, 3000, -1) == 2000);
    CHECK(neighbour_keyframe(doc, 2000, -1) == 0);
    CHECK(neighbour_keyframe(doc, 0, -1) == 0);
}

TEST_CASE("the session's frame steps and keyframe jumps pause playback and edit nothing", "[session]") {
    Environment env;
    EditorSession s(env);
    std::string error;
    REQUIRE(s.open(source_dir() / "assets" / "animations" / "drop.ani", error));
    while (s.bake_some(0.05)) {
    }
    const std::uint64_t version = s.version();
    s.toggle_play(10.0);
    s.tick(10.5);
    REQUIRE(s.playing());
    s.step_frames(1);
    CHECK_FALSE(s.playing());
    CHECK(s.time_ms() == step_frames(500, 1, kStepFramesPerSecond, s.document().settings().max_time_ms));
    s.step_frames(-1);
    s.step_frames(-1);
    CHECK(s.time_ms() == 467);
    s.jump_keyframe(-1);
    CHECK(s.time_ms() == 0);
    s.jump_keyframe(1); // drop.ani has only the keyframe at 0
    CHECK(s.time_ms() == 0);
    CHECK(s.version() == version);
    CHECK_FALSE(s.dirty());
}
