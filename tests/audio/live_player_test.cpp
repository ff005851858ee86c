// Live playback without a sound card: one warning line, then nothing; and, with OpenAL's null
// device (the "[.null-device]" test, run by its own CTest entry with ALSOFT_DRIVERS=null), the
// device opens and the cues of each window start voices.
#include "audio/live_player.hpp"

#include "audio_support.hpp"

#include <catch2/catch.hpp>

#include <cstdlib>

using namespace animator;
using namespace audio_test;

namespace {

// Unless the environment picks an OpenAL driver, these tests run as on a server without a sound
// card, whatever this machine has: OpenAL Soft reads ALSOFT_DRIVERS once, when first used.
const bool kNoDeviceUnlessAsked = [] {
    ::setenv("ALSOFT_DRIVERS", "animator-tests-no-such-driver", 0);
    return true;
}();

// Plays `doc` from 0 to `until` in 60 Hz frames, as the editor does.
void play(audio::LivePlayer &player, const Timeline &timeline, double until) {
    const double frame = 1.0 / 60.0;
    for (double t = 0.0; t < until; t += frame)
        player.advance(timeline, t, std::min(until, t + frame));
}

} // namespace

TEST_CASE("without an audio device, playback says so in one line and goes on silently") {
    REQUIRE(kNoDeviceUnlessAsked);
    const double h = 2.0, until = bounce_time(h, 2) + 0.1;
    const Document doc = drop_scene(h, {0, 0, 10}, "click", 1.0, "hum");
    auto timeline = physics_test::timeline_of(doc);
    timeline->bake(until);
    std::vector<std::string> said;
    AssetPaths sounds({generated_assets()});
    const int before = audio::LivePlayer::device_open_attempts();
    audio::LivePlayer player(sounds, [&](const std::string &line) { said.push_back(line); });
    player.set_document(doc);
    play(player, *timeline, until);
    player.stop_all();
    player.set_document(doc);
    play(player, *timeline, until);
    REQUIRE(said.size() == 1);
    CHECK_THAT(said[0], Catch::StartsWith("warning: no audio device"));
    CHECK(said[0].find('\n') == std::string::npos);
    CHECK(audio::LivePlayer::device_open_attempts() == before + 1);
    CHECK_FALSE(player.has_device());
    CHECK(player.stats().started == 0);
}

TEST_CASE("a live player whose sounds are missing says so once per sound", "[.null-device]") {
    const double h = 1.0, until = bounce_time(h, 3);
    const Document doc = drop_scene(h, {0, 0, 10}, "no-such-sound");
    auto timeline = physics_test::timeline_of(doc);
    timeline->bake(until);
    std::vector<std::string> said;
    AssetPaths sounds({generated_assets()});
    audio::LivePlayer player(sounds, [&](const std::string &line) { said.push_back(line); });
    player.set_document(doc);
    play(player, *timeline, until);
    REQUIRE(player.has_device());
    REQUIRE(said.size() == 1);
    CHECK_THAT(said[0], Catch::Contains("sound 'no-such-sound' not found"));
}

TEST_CASE("with a device, each window's collisions start voices at the mixer's volumes",
          "[.null-device]") {
    const double h = 2.0;
    const Document doc = drop_scene(h, {0, 0, 10}, "click", 1.0, "hum");
    auto timeline = physics_test::timeline_of(doc);
    timeline->bake(bounce_time(h, 1) + 0.1);
    std::vector<std::string> said;
    AssetPaths sounds({generated_assets()});
    const int before = audio::LivePlayer::device_open_attempts();
    audio::LivePlayer player(sounds, [&](const std::string &line) { said.push_back(line); });
    player.set_document(doc);
    // Up to just before the first bounce: only the hum (the falling ball) plays.
    const double t0 = bounce_time(h, 0);
    player.advance(*timeline, 0.0, t0 - 0.01);
    REQUIRE(player.has_device());
    CHECK(said.empty());
    CHECK(audio::LivePlayer::device_open_attempts() == before + 1);
    CHECK(player.stats().started == 1);
    // The window (t0 - 0.01, t0 + 0.01] holds the bounce: the click starts.
    player.advance(*timeline, t0 - 0.01, t0 + 0.01);
    CHECK(player.stats().started == 2);
    // An empty window starts nothing more.
    player.advance(*timeline, t0 + 0.01, t0 + 0.02);
    CHECK(player.stats().started == 2);
    player.stop_all();
}
