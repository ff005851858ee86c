// `animator soundtrack` and `animator render --video` as a user runs them: the real program,
// its WAV read back with the tests' own reader, its messages and exit codes.
#include "audio_support.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace animator;
using namespace audio_test;
namespace fs = std::filesystem;

namespace {
std::string example(const std::string &name) {
    return (test::source_dir() / "assets" / name).string();
}
} // namespace

TEST_CASE("animator soundtrack writes drop.ani's bounces at their times into 16-bit stereo") {
    const fs::path out = test::fresh_dir("soundtrack_drop") / "drop.wav";
    const auto r = test::run_animator("soundtrack " + example("animations/drop.ani") + " --out " +
                                      out.string() + " --until 3");
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Contains("wrote " + out.string()));
    const Wav wav = read_wav(out);
    CHECK(wav.channels == 2);
    CHECK(wav.bits == 16);
    CHECK(wav.rate == 44100);
    CHECK(wav.frames() == 3 * 44100);
    // drop.ani: the ball's center starts at 5 and its radius is 1, so it falls 4 m onto the
    // floor; bounces at sqrt(8 / g) and three times that.
    const auto found = onsets(wav, 0, 33, 44100 / 20);
    REQUIRE(found.size() == 2);
    CHECK(std::abs(found[0] - bounce_time(4.0, 0)) < 0.002);
    CHECK(std::abs(found[1] - bounce_time(4.0, 1)) < 0.002);

    SECTION("--rate sets the frames per second") {
        const auto r2 = test::run_animator("soundtrack " + example("animations/drop.ani") +
                                           " --out " + out.string() + " --until 1 --rate 22050");
        REQUIRE(r2.exit_code == 0);
        const Wav half = read_wav(out);
        CHECK(half.rate == 22050);
        CHECK(half.frames() == 22050);
        const auto first = onsets(half, 0, 33, 22050 / 20);
        REQUIRE(first.size() == 1);
        CHECK(std::abs(first[0] - bounce_time(4.0, 0)) < 0.002);
    }
}

TEST_CASE("every example's soundtrack is neither silent nor clipped") {
    int examples = 0;
    for (const char *name : {"animations/cradle.ani", "animations/drop.ani", "animations/gas.ani",
                             "animations/orbs.ani", "animations/stairs.ani", "scenes/simple.lua"}) {
        CAPTURE(name);
        ++examples;
        const fs::path out = test::fresh_dir("soundtrack_examples") / "out.wav";
        const auto r = test::run_animator("soundtrack " + example(name) + " --out " + out.string());
        INFO(r.out);
        REQUIRE(r.exit_code == 0);
        CHECK_THAT(r.out, !Catch::Contains("clipped"));
        const Wav wav = read_wav(out);
        const int loudest = std::max(peak(wav, 0, 0, wav.frames()), peak(wav, 1, 0, wav.frames()));
        if (std::string(name) == "animations/orbs.ani") {
            CHECK(loudest == 0); // no model has a sound
        } else {
            CHECK(loudest > 300);   // above -41 dBFS
            CHECK(loudest < 32767); // below full scale
        }
    }
    CHECK(examples == 6);
}

TEST_CASE("animator soundtrack reports bad input naming the file, and keeps an old WAV") {
    const fs::path dir = test::fresh_dir("soundtrack_bad");
    const fs::path out = dir / "out.wav";
    test::write_file(out, "the old soundtrack");

    auto r = test::run_animator("soundtrack " + (dir / "missing.ani").string() + " --out " +
                                out.string());
    CHECK(r.exit_code == 1);
    CHECK_THAT(r.out, Catch::Contains("missing.ani"));

    // A sound that does not exist: the message names the file, the model and the sound.
    const fs::path scene = dir / "bad_sound.ani";
    std::string text = test::read_file(example("animations/drop.ani"));
    text.replace(text.find("collision_sound \"click\""), 23, "collision_sound \"boing\"");
    test::write_file(scene, text);
    r = test::run_animator("soundtrack " + scene.string() + " --out " + out.string());
    INFO(r.out);
    CHECK(r.exit_code == 1);
    CHECK_THAT(r.out, Catch::Contains("bad_sound.ani") && Catch::Contains("model 'ball'") &&
                          Catch::Contains("sound 'boing' not found"));
    CHECK(test::read_file(out) == "the old soundtrack");

    // A time past the animation's end.
    r = test::run_animator("soundtrack " + example("animations/drop.ani") + " --out " +
                           out.string() + " --until 99");
    CHECK(r.exit_code == 1);
    CHECK_THAT(r.out, Catch::Contains("drop.ani"));
    CHECK(test::read_file(out) == "the old soundtrack");

    // A folder that does not exist for the output.
    r = test::run_animator("soundtrack " + example("animations/drop.ani") + " --out " +
                           (dir / "no" / "such" / "out.wav").string() + " --until 1");
    CHECK(r.exit_code == 1);
    CHECK_THAT(r.out, Catch::Contains((dir / "no" / "such" / "out.wav").string()));

    // Usage errors exit 2.
    CHECK(test::run_animator("soundtrack " + example("animations/drop.ani") + " --out " +
                             out.string() + " --rate 5")
              .exit_code == 2);
    CHECK(test::run_animator("soundtrack " + example("animations/drop.ani")).exit_code == 2);
    int files = 0;
    for ([[maybe_unused]] const auto &e : fs::directory_iterator(dir)) ++files;
    CHECK(files == 2); // out.wav and bad_sound.ani: no temporary file left behind
}

TEST_CASE("render --video without ffmpeg says how to install it, writes the frames and exits 1") {
    const fs::path dir = test::fresh_dir("render_video_no_ffmpeg");
    const fs::path empty = dir / "bin"; // a PATH with no ffmpeg on it
    fs::create_directories(empty);
    const fs::path frames = dir / "frames";
    const auto r = test::run_animator(
        "render " + example("animations/drop.ani") + " --out " + frames.string() +
            " --to 0.2 --fps 10 --size 32x24 --video " + (dir / "drop.mp4").string(),
        "env -u DISPLAY -u WAYLAND_DISPLAY PATH=" + empty.string());
    INFO(r.out);
    CHECK(r.exit_code == 1);
    CHECK_THAT(r.out, Catch::Contains("ffmpeg") && Catch::Contains("apt-get install ffmpeg"));
    CHECK(fs::exists(frames / "frame_00000.png"));
    CHECK(fs::exists(frames / "frame_00002.png"));
    CHECK_FALSE(fs::exists(dir / "drop.mp4"));
}
