// The voice pool's rule (drop the quietest, new or playing) and the engine's mix, checked sample
// by sample against gains computed by hand.
#include "audio/voices.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <vector>

using namespace animator;
using Catch::Matchers::WithinAbs;

namespace {

std::shared_ptr<const audio::SoundData> constant(double level, std::size_t length,
                                                 int rate = 1000) {
    auto s = std::make_shared<audio::SoundData>();
    s->rate = rate;
    s->samples.assign(length, static_cast<float>(level));
    return s;
}

// The left and right output of one frame of the engine.
std::vector<float> render(audio::VoiceEngine &engine, std::size_t frames) {
    std::vector<float> out(2 * frames, 0.0f);
    engine.render(out.data(), frames);
    return out;
}

const double kCentre = 1.0 / std::sqrt(2.0); // each side's gain at pan 0

} // namespace

TEST_CASE("the pool starts a voice while there is room, then drops the quietest, new or playing") {
    using audio::admit_voice;
    auto a = admit_voice({5.0, 1.0}, 0.5, 3);
    CHECK(a.start);
    CHECK_FALSE(a.drop);
    // Full: the new one is louder than the quietest playing voice (index 1), which goes.
    a = admit_voice({5.0, 1.0, 3.0}, 2.0, 3);
    CHECK(a.start);
    REQUIRE(a.drop);
    CHECK(*a.drop == 1);
    // Full: the new one is the quietest, so it is the one dropped.
    a = admit_voice({5.0, 1.0, 3.0}, 0.5, 3);
    CHECK_FALSE(a.start);
    CHECK_FALSE(a.drop);
    // A tie keeps what plays.
    a = admit_voice({5.0, 1.0, 3.0}, 1.0, 3);
    CHECK_FALSE(a.start);
    // Among equally quiet playing voices, the earliest started goes.
    a = admit_voice({2.0, 1.0, 1.0}, 4.0, 3);
    REQUIRE(a.drop);
    CHECK(*a.drop == 1);
    // No room at all.
    CHECK_FALSE(admit_voice({}, 50.0, 0).start);
}

TEST_CASE("the engine mixes voices at volume / 100 times the pan's gain, and keeps the loudest") {
    audio::VoiceEngine engine(1000, 3);
    CHECK(engine.play(constant(0.5, 100), 10.0, 0.0));
    CHECK(engine.play(constant(0.5, 100), 20.0, 0.0));
    CHECK(engine.play(constant(0.5, 100), 30.0, -1.0)); // all left
    // Full: a quieter one is refused, a louder one replaces the quietest (10), which fades out.
    CHECK_FALSE(engine.play(constant(0.5, 100), 5.0, 0.0));
    CHECK(engine.play(constant(0.5, 100), 40.0, 1.0)); // all right
    CHECK(engine.sounding() == 3);
    CHECK(engine.stats().started == 4);
    CHECK(engine.stats().refused == 1);
    CHECK(engine.stats().dropped == 1);
    CHECK(engine.stats().peak == 3);

    // The fade of the dropped voice lasts 5 ms (5 frames at 1000 Hz); after it, exactly the three
    // loudest sound: left 0.5 (0.2 c + 0.3), right 0.5 (0.2 c + 0.4).
    const auto out = render(engine, 20);
    const double left = 0.5 * (0.2 * kCentre + 0.3), right = 0.5 * (0.2 * kCentre + 0.4);
    CHECK_THAT(out[2 * 10], WithinAbs(left, 1e-6));
    CHECK_THAT(out[2 * 10 + 1], WithinAbs(right, 1e-6));
    // In the first frame the dropped one still sounds at full gain.
    CHECK_THAT(out[0], WithinAbs(left + 0.5 * 0.1 * kCentre, 1e-6));
}

TEST_CASE("a one-shot ends with its sound and frees its voice, a loop goes on until stopped") {
    audio::VoiceEngine engine(1000, 1);
    REQUIRE(engine.play(constant(1.0, 10), 50.0, 0.0));
    auto out = render(engine, 15);
    CHECK_THAT(out[2 * 9], WithinAbs(0.5 * kCentre, 1e-6));
    CHECK(out[2 * 10] == 0.0f);
    CHECK(engine.sounding() == 0);
    // The one voice is free again, even for a quiet sound.
    REQUIRE(engine.loop(7, constant(1.0, 10), 1.0, 0.0));
    CHECK(engine.looping(7));
    out = render(engine, 35);
    CHECK_THAT(out[2 * 34], WithinAbs(0.01 * kCentre, 1e-6)); // past three lengths of its sound
    // A louder one-shot takes the only voice from the loop.
    CHECK(engine.play(constant(1.0, 10), 90.0, 0.0));
    CHECK_FALSE(engine.looping(7));
    // The loop asks again later and is refused while the louder one plays.
    CHECK_FALSE(engine.loop(7, constant(1.0, 10), 1.0, 0.0));
    render(engine, 20);
    CHECK(engine.loop(7, constant(1.0, 10), 1.0, 0.0));
    engine.stop_loop(7);
    CHECK_FALSE(engine.looping(7));
    render(engine, 20);
    CHECK(engine.sounding() == 0);
    out = render(engine, 5);
    CHECK(out[0] == 0.0f);
}

TEST_CASE("a loop's volume and pan move to new values over 10 ms, without a step") {
    audio::VoiceEngine engine(1000, 4);
    REQUIRE(engine.loop(1, constant(1.0, 50), 20.0, 0.0));
    render(engine, 5);
    engine.loop(1, nullptr, 60.0, 0.0); // the sound is already playing: only the gains move
    const auto out = render(engine, 20);
    // 10 frames of ramp from 0.2 c to 0.6 c: 0.04 c more each frame.
    CHECK_THAT(out[0], WithinAbs(0.24 * kCentre, 1e-6));
    CHECK_THAT(out[2 * 4], WithinAbs(0.40 * kCentre, 1e-6));
    CHECK_THAT(out[2 * 9], WithinAbs(0.60 * kCentre, 1e-6));
    CHECK_THAT(out[2 * 15], WithinAbs(0.60 * kCentre, 1e-6));
}

TEST_CASE("a sound at another rate is resampled to the output's") {
    // 500 Hz sound into a 1000 Hz mix: each sample lasts two frames, with linear interpolation.
    auto s = std::make_shared<audio::SoundData>();
    s->rate = 500;
    s->samples = {0.0f, 1.0f, 0.0f, -1.0f};
    audio::VoiceEngine engine(1000, 2);
    REQUIRE(engine.play(s, 100.0, -1.0));
    const auto out = render(engine, 10);
    const float expected[] = {0.0f, 0.5f, 1.0f, 0.5f, 0.0f, -0.5f, -1.0f, -0.5f, 0.0f, 0.0f};
    for (int i = 0; i < 10; ++i)
        CHECK_THAT(out[static_cast<std::size_t>(2 * i)], WithinAbs(expected[i], 1e-6));
}
