// The status line's texts and the screen state the window redraws on (editor/status_line.hpp,
// editor/screen_state.hpp): what the panels show must change when playback ends, a bake
// finishes, an undo changes what can be undone, or the message changes, with no input event.
#include "editor/editor_session.hpp"
#include "editor/screen_state.hpp"
#include "editor/status_line.hpp"

#include "support.hpp"

#include <catch2/catch.hpp>

using namespace animator;
using namespace animator::test;

namespace {
std::filesystem::path drop_ani() { return source_dir() / "assets" / "animations" / "drop.ani"; }
} // namespace

TEST_CASE("the bake status says the backend and how far it baked, then that it is done", "[status]") {
    Environment env;
    EditorSession s(env);
    std::string error;
    REQUIRE(s.open(drop_ani(), error));
    CHECK(bake_status(s) == "physics.custom: baked to 0 s of 10 s");
    const ScreenState before = screen_state(s, "");
    while (s.bake_some(0.05)) {
    }
    CHECK(bake_status(s) == "physics.custom: baked, 10 s");
    // A finished bake is a change of what the screen shows, with no input event.
    CHECK(screen_state(s, "") != before);
}

TEST_CASE("playback reaching the end changes the screen state (the button and the time)", "[status]") {
    Environment env;
    EditorSession s(env);
    std::string error;
    REQUIRE(s.open(drop_ani(), error));
    while (s.bake_some(0.05)) {
    }
    s.set_time_ms(9900);
    s.toggle_play(50.0);
    s.tick(50.05);
    const ScreenState playing = screen_state(s, "");
    CHECK(playing.playing);
    s.tick(51.0); // past the end: playback stops there
    const ScreenState stopped = screen_state(s, "");
    CHECK_FALSE(stopped.playing);
    CHECK(stopped.time_ms == 10000);
    CHECK(stopped != playing);
    // Nothing happening is no change: the window may sleep.
    s.tick(52.0);
    CHECK(screen_state(s, "") == stopped);
}

TEST_CASE("an undo, and a new message, each change the screen state", "[status]") {
    Environment env;
    EditorSession s(env);
    std::string error;
    REQUIRE(s.open(drop_ani(), error));
    Settings settings = s.document().settings();
    settings.cel_shading = !settings.cel_shading;
    REQUIRE(s.set_settings(settings));
    const ScreenState edited = screen_state(s, "");
    CHECK(edited.can_undo);
    REQUIRE(s.undo());
    const ScreenState undone = screen_state(s, "");
    CHECK(undone != edited);
    CHECK(undone.can_redo);
    CHECK(screen_state(s, "undone") != undone);
}

TEST_CASE("the frame rate counts the last second of frames, and says idle after a sleep", "[status]") {
    FrameRate rate;
    CHECK(rate.text() == "idle");
    for (int i = 0; i <= 60; ++i) rate.frame(10.0 + i / 60.0);
    CHECK(rate.text() == "60 fps");
    // Frames older than a second no longer count: 20 fps now.
    for (int i = 1; i <= 40; ++i) rate.frame(11.0 + i / 20.0);
    CHECK(rate.text() == "20 fps");
    rate.idle();
    CHECK(rate.text() == "idle");
    rate.frame(30.0);
    CHECK(rate.text() == "idle"); // one frame is no rate
}
