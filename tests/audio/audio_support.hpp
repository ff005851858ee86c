// What the audio tests share: drop scenes with collisions at known times (a ball dropped from
// height h above a floor hits it after sqrt(2 h / g), at speed sqrt(2 g h)), a folder of test
// sounds with known samples, and the volume formula written out again from the seed.
#pragma once

#include "physics/scene_support.hpp"
#include "wav_file.hpp"

#include <cmath>
#include <filesystem>
#include <string>

namespace audio_test {

using namespace animator;
using physics_test::G;

inline constexpr double kPi = 3.14159265358979323846;

// The seed's formula with the documented constant c = 500 (docs/sound.md), written out here
// rather than taken from the program: c E / (4 pi r^2), without clamping.
inline double expected_volume(double mass, double speed, double distance) {
    return 500.0 * (mass * speed * speed / 2.0) / (4.0 * kPi * distance * distance);
}

// A ball of `mass` with `sound` dropped so that it falls `height` metres onto a static floor
// (the generated plane, at y = 0, contact at the origin), the camera at `camera` looking down -Z.
inline Document drop_scene(double height, const glm::dvec3 &camera, const std::string &sound,
                           double mass = 1.0, const std::string &moving = "") {
    Document doc;
    Settings s = doc.settings();
    s.max_time_ms = 10000;
    doc.set_settings(s);
    doc.add_model(physics_test::model("floor", "plane", false, false),
                  physics_test::placed({0, 0, 0}, 10.0));
    Model ball = physics_test::model("ball", "sphere", true, true);
    ball.mass = mass;
    ball.collision_sound = sound;
    ball.moving_sound = moving;
    doc.add_model(ball, physics_test::placed({0, height + physics_test::unit_radius(), 0}));
    CameraState cam;
    cam.position = camera;
    doc.set_camera(0, cam);
    return doc;
}

// The time of the k-th bounce (k = 0, 1, ...) of a ball dropped `height` metres.
inline double bounce_time(double height, int k) {
    const double first = std::sqrt(2.0 * height / G);
    return first * (1.0 + 2.0 * k);
}

// A folder holding sounds/step.wav: 0.5 of full scale for 20 ms, starting at its first sample,
// so a voice's onset and peak gain can be read off exactly.
inline std::filesystem::path test_sound_root() {
    static const std::filesystem::path root = [] {
        const std::filesystem::path dir = test::fresh_dir("audio_sounds");
        std::filesystem::create_directories(dir / "sounds");
        write_mono_wav(dir / "sounds" / "step.wav", std::vector<double>(882, 0.5), 44100);
        return dir;
    }();
    return root;
}

// The step sound's level as a 16-bit sample.
inline constexpr double kStepLevel = 0.5;

// The build's generated assets.
inline std::filesystem::path generated_assets() {
    return test::bin_dir().parent_path() / "assets";
}

} // namespace audio_test
