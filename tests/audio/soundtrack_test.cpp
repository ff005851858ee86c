// The offline soundtrack of scenes with collisions at known times, read back with the tests' own
// WAV reader: onsets at the closed-form bounce times, loudness by the seed's formula, a quarter
// of the amplitude at twice the distance, the pan, and silence for a scene without sounds.
#include "audio/live_player.hpp"
#include "audio/mixer.hpp"
#include "audio/sound_cues.hpp"
#include "io/document_io.hpp"

#include "audio_support.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace animator;
using namespace audio_test;
namespace fs = std::filesystem;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

// The soundtrack of `doc` over [0, until] at `rate`, written to a WAV file and read back.
Wav soundtrack(const Document &doc, double until, const std::string &name, int rate = 44100,
               audio::MixStats *stats = nullptr) {
    auto timeline = physics_test::timeline_of(doc);
    timeline->bake(until);
    AssetPaths sounds({test_sound_root(), generated_assets()});
    audio::SoundBank bank(sounds);
    audio::MixOptions o;
    o.rate = rate;
    o.until = until;
    const fs::path path = test::fresh_dir("soundtrack_" + name) / "out.wav";
    const audio::MixStats s = audio::write_soundtrack(*timeline, bank, o, path);
    if (stats) *stats = s;
    return read_wav(path);
}

// A 16-bit sample's full scale, as the writer maps 1.0.
constexpr double kFull = 32767.0;

} // namespace

TEST_CASE("each bounce's sound starts in the WAV within 2 ms of the collision") {
    const double h = 2.0;
    // The generated click, as a user's scene would play it.
    const Document doc = drop_scene(h, {0, 1, 10}, "click");
    const double until = bounce_time(h, 2) + 0.2;
    for (int rate : {44100, 48000, 22050}) {
        CAPTURE(rate);
        const Wav wav = soundtrack(doc, until, "onsets" + std::to_string(rate), rate);
        REQUIRE(wav.format == 1);
        REQUIRE(wav.channels == 2);
        REQUIRE(wav.bits == 16);
        REQUIRE(wav.rate == rate);
        CHECK(wav.frames() == static_cast<std::size_t>(std::llround(until * rate)));
        for (int channel : {0, 1}) {
            // Anything above 1/1000 of full scale after 50 ms of silence starts a sound.
            const auto found = onsets(wav, channel, 33, static_cast<std::size_t>(rate / 20));
            REQUIRE(found.size() == 3);
            for (int k = 0; k < 3; ++k)
                CHECK_THAT(found[static_cast<std::size_t>(k)], WithinAbs(bounce_time(h, k), 0.002));
        }
    }
}

TEST_CASE("a faster impact is louder by the ratio of the kinetic energies") {
    // Drops of 1 m and 3.5 m: impact speeds sqrt(2 g h), so E and the volume grow 3.5 times.
    const glm::dvec3 camera{0, 0, 4};
    const double low = 1.0, high = 3.5;
    const Wav quiet =
        soundtrack(drop_scene(low, camera, "step"), bounce_time(low, 0) + 0.1, "slow");
    const Wav loud =
        soundtrack(drop_scene(high, camera, "step"), bounce_time(high, 0) + 0.1, "fast");
    const double v_low = expected_volume(1.0, std::sqrt(2 * G * low), 4.0);
    const double v_high = expected_volume(1.0, std::sqrt(2 * G * high), 4.0);
    REQUIRE(v_high < 100.0); // not clamped, so the ratio is the formula's
    CHECK_THAT(v_high / v_low, WithinRel(high / low, 1e-12));
    for (int channel : {0, 1}) {
        const int p_low = peak(quiet, channel, 0, quiet.frames());
        const int p_high = peak(loud, channel, 0, loud.frames());
        // Each peak is the step's level times volume / 100 times the centre's gain 1/sqrt(2).
        CHECK(std::abs(p_low - kStepLevel * v_low / 100.0 / std::sqrt(2.0) * kFull) <= 2.0);
        CHECK(std::abs(p_high - kStepLevel * v_high / 100.0 / std::sqrt(2.0) * kFull) <= 2.0);
        CHECK_THAT(static_cast<double>(p_high) / p_low, WithinRel(high / low, 0.002));
    }
}

TEST_CASE("twice the distance to the camera gives a quarter of the amplitude") {
    const double h = 2.0, until = bounce_time(h, 0) + 0.1;
    const Wav near = soundtrack(drop_scene(h, {0, 0, 3}, "step"), until, "near");
    const Wav far = soundtrack(drop_scene(h, {0, 0, 6}, "step"), until, "far");
    REQUIRE(expected_volume(1.0, std::sqrt(2 * G * h), 3.0) < 100.0);
    for (int channel : {0, 1}) {
        const double p_near = peak(near, channel, 0, near.frames());
        const double p_far = peak(far, channel, 0, far.frames());
        CHECK(p_far > 100.0);
        CHECK_THAT(p_near / p_far, WithinRel(4.0, 0.003));
    }
}

TEST_CASE("a sound on the camera's right is louder on the right by the constant-power pan") {
    // The contact point (the origin) is at camera-space (5, 0, -5) from a camera at (-5, 0, 5):
    // pan 1/sqrt(2), so left and right are cos and sin of (1 + 1/sqrt(2)) pi / 4.
    const double h = 2.0, until = bounce_time(h, 0) + 0.1;
    const Wav wav = soundtrack(drop_scene(h, {-5, 0, 5}, "step"), until, "pan");
    const double angle = (1.0 + 1.0 / std::sqrt(2.0)) * kPi / 4.0;
    const double volume = expected_volume(1.0, std::sqrt(2 * G * h), std::sqrt(50.0));
    REQUIRE(volume < 100.0);
    const int left = peak(wav, 0, 0, wav.frames()), right = peak(wav, 1, 0, wav.frames());
    CHECK(std::abs(left - kStepLevel * volume / 100.0 * std::cos(angle) * kFull) <= 2.0);
    CHECK(std::abs(right - kStepLevel * volume / 100.0 * std::sin(angle) * kFull) <= 2.0);
    CHECK(right > left);
}

TEST_CASE("a scene without sounds gives silence and never opens the audio device") {
    const double h = 2.0, until = bounce_time(h, 1) + 0.1;
    const Document doc = drop_scene(h, {0, 0, 10}, "");
    const Wav wav = soundtrack(doc, until, "silent");
    CHECK(wav.frames() == static_cast<std::size_t>(std::llround(until * 44100)));
    CHECK(peak(wav, 0, 0, wav.frames()) == 0);
    CHECK(peak(wav, 1, 0, wav.frames()) == 0);

    // Live playback of the same scene, frame by frame, never touches the device.
    const int before = audio::LivePlayer::device_open_attempts();
    std::vector<std::string> said;
    AssetPaths sounds({generated_assets()});
    audio::LivePlayer player(sounds, [&](const std::string &line) { said.push_back(line); });
    player.set_document(doc);
    auto timeline = physics_test::timeline_of(doc);
    timeline->bake(until);
    for (double t = 0.0; t + 1.0 / 60.0 <= until; t += 1.0 / 60.0)
        player.advance(*timeline, t, t + 1.0 / 60.0);
    player.stop_all();
    CHECK(audio::LivePlayer::device_open_attempts() == before);
    CHECK_FALSE(player.has_device());
    CHECK(said.empty());
}

TEST_CASE("a moving sound follows the speed by the formula and stops when the model rests") {
    // A model without Dynamics falls from rest under gravity and stops where it lands
    // (docs/timeline.md). Its moving sound is the step sound looped: a constant 0.5, so the WAV
    // shows the gain itself. Every 10 ms the gain ramps to the volume of that moment, reaching it
    // 10 ms later, exactly at the next sample's frame.
    const double h = 3.0, landing = bounce_time(h, 0), until = landing + 0.3;
    Document doc = drop_scene(h, {0, 0, 5}, "", 1.0, "step");
    Model ball = doc.models()[1];
    ball.dynamics = false;
    doc.set_model(1, ball);
    const int rate = 44100;
    const Wav wav = soundtrack(doc, until, "moving", rate);
    const double y0 = h + physics_test::unit_radius();
    for (double tk : {0.1, 0.3, 0.5, 0.7}) {
        CAPTURE(tk);
        const double speed = G * tk, y = y0 - G * tk * tk / 2.0;
        const double r = std::sqrt(y * y + 25.0);
        const double expected =
            kStepLevel * expected_volume(1.0, speed, r) / 100.0 / std::sqrt(2.0) * kFull;
        const auto frame = static_cast<std::size_t>(std::llround(tk * rate)) + 440;
        for (int channel : {0, 1}) CHECK(std::abs(wav.at(frame, channel) - expected) <= 1.5);
    }
    // Loud just before it lands; silent from 5 ms (the fade) after the first 10 ms sample that
    // finds it at rest.
    CHECK(peak(wav, 0, static_cast<std::size_t>((landing - 0.05) * rate),
               static_cast<std::size_t>(landing * rate)) > 1000);
    const auto silent_from =
        static_cast<std::size_t>((std::ceil(landing / 0.01) * 0.01 + 0.006) * rate);
    CHECK(peak(wav, 0, silent_from, wav.frames()) == 0);
    CHECK(peak(wav, 1, silent_from, wav.frames()) == 0);
}

TEST_CASE("the voice limit holds in a gas of 125 balls") {
    Environment &env = physics_test::env();
    OpenedDocument gas =
        open_document(env.plugins, test::source_dir() / "assets/animations/gas.ani");
    audio::MixStats stats;
    const Wav wav = soundtrack(gas.document, 2.0, "gas", 44100, &stats);
    CHECK(stats.collision_cues > 0);
    CHECK(stats.voices.peak <= audio::kVoiceLimit);
    CHECK(peak(wav, 0, 0, wav.frames()) > 0);
}

TEST_CASE("a failed write leaves the old file intact and no temporary file behind") {
    const fs::path dir = test::fresh_dir("soundtrack_atomic");
    const fs::path path = dir / "out.wav";
    test::write_file(path, "the old soundtrack");
    const double h = 2.0, until = bounce_time(h, 0) + 0.5;
    auto timeline = physics_test::timeline_of(drop_scene(h, {0, 0, 10}, "step"));
    timeline->bake(until);
    AssetPaths sounds({test_sound_root()});
    audio::SoundBank bank(sounds);
    audio::MixOptions o;
    o.until = until;
    // Cancelled half way through the mix.
    CHECK_THROWS_AS(
        audio::write_soundtrack(*timeline, bank, o, path, [](double f) { return f < 0.5; }),
        BakeCancelled);
    CHECK(test::read_file(path) == "the old soundtrack");
    int files = 0;
    for ([[maybe_unused]] const auto &e : fs::directory_iterator(dir)) ++files;
    CHECK(files == 1);
    // A complete write replaces it.
    audio::write_soundtrack(*timeline, bank, o, path);
    CHECK(read_wav(path).frames() == static_cast<std::size_t>(std::llround(until * 44100)));
}

TEST_CASE("sounds are read once per id and a missing or broken one is named") {
    const fs::path root = test::fresh_dir("audio_bad_sounds");
    fs::create_directories(root / "sounds");
    test::write_file(root / "sounds" / "broken.wav", "RIFF....WAVEjunk");
    AssetPaths sounds({root, generated_assets()});
    audio::SoundBank bank(sounds);
    const auto a = bank.get("click");
    const auto b = bank.get("click");
    CHECK(a == b);
    CHECK(bank.files_read() == 1);
    CHECK(a->samples.size() == 662); // docs/assets.md
    CHECK_THROWS_WITH(bank.get("nope"), Catch::Contains("sound 'nope' not found") &&
                                            Catch::Contains("sounds/nope.wav"));
    CHECK_THROWS_WITH(bank.get("broken"),
                      Catch::Contains("broken.wav") && Catch::Contains("expected"));

    Document doc = drop_scene(1.0, {0, 0, 10}, "click", 1.0, "nope");
    CHECK_THROWS_WITH(audio::load_document_sounds(doc, bank),
                      Catch::Contains("model 'ball'") && Catch::Contains("moving sound 'nope'"));
}
