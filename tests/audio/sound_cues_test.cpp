// sound_cues: the seed's volume formula, the pan, and which model plays what when, against hand
// computations and the closed form of a dropped ball.
#include "audio/sound_cues.hpp"

#include "audio_support.hpp"

#include <catch2/catch.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>

using namespace animator;
using namespace audio_test;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

TEST_CASE("volume is c E / (4 pi r^2) clamped to 0..100") {
    // 10 J at 2 m: 500 * 10 / (4 pi 4) = 99.47...
    CHECK_THAT(audio::volume(10.0, 2.0), WithinRel(5000.0 / (16.0 * kPi), 1e-12));
    CHECK(audio::kVolumeScale == 500.0);
    // Twice the distance, a quarter of the volume; twice the energy, twice.
    CHECK_THAT(audio::volume(10.0, 40.0), WithinRel(audio::volume(10.0, 20.0) / 4.0, 1e-12));
    CHECK_THAT(audio::volume(20.0, 20.0), WithinRel(audio::volume(10.0, 20.0) * 2.0, 1e-12));
    // Clamped: 1000 J at 1 m would be 39789.
    CHECK(audio::volume(1000.0, 1.0) == 100.0);
    CHECK(audio::volume(5.0, 0.0) == 100.0);
    CHECK(audio::volume(0.0, 0.0) == 0.0);
    CHECK(audio::volume(0.0, 3.0) == 0.0);
    CHECK(audio::volume(-1.0, 3.0) == 0.0);
    CHECK(audio::volume(std::nan(""), 3.0) == 0.0);
    CHECK(audio::volume(1.0, std::nan("")) == 0.0);
}

TEST_CASE("pan is the point's camera-space x over its distance, with constant-power gains") {
    CameraState cam; // at the origin looking down -Z, +X to the right
    CHECK_THAT(audio::pan(cam, {0, 0, -5}), WithinAbs(0.0, 1e-15));
    CHECK_THAT(audio::pan(cam, {3, 0, -3}), WithinAbs(1.0 / std::sqrt(2.0), 1e-12));
    CHECK_THAT(audio::pan(cam, {-2, 0, 0}), WithinAbs(-1.0, 1e-15));
    CHECK_THAT(audio::pan(cam, {0, 7, 0}), WithinAbs(0.0, 1e-15)); // straight above
    CHECK(audio::pan(cam, {0, 0, 0}) == 0.0);
    // Moved and turned 90 degrees left (about +Y): it now looks down -X, and its right is -Z.
    cam.position = {10, 0, 0};
    cam.rotation = glm::angleAxis(kPi / 2.0, glm::dvec3(0, 1, 0));
    CHECK_THAT(audio::pan(cam, {10, 0, -4}), WithinAbs(1.0, 1e-12));
    CHECK_THAT(audio::pan(cam, {10, 0, 4}), WithinAbs(-1.0, 1e-12));
    CHECK_THAT(audio::pan(cam, {0, 0, 0}), WithinAbs(0.0, 1e-12)); // ahead

    for (double p : {-1.0, -0.5, 0.0, 0.3, 1.0}) {
        const audio::StereoGain g = audio::pan_gains(p);
        CHECK_THAT(g.left * g.left + g.right * g.right, WithinAbs(1.0, 1e-12));
    }
    CHECK_THAT(audio::pan_gains(0.0).left, WithinAbs(1.0 / std::sqrt(2.0), 1e-12));
    CHECK_THAT(audio::pan_gains(0.0).right, WithinAbs(1.0 / std::sqrt(2.0), 1e-12));
    CHECK_THAT(audio::pan_gains(-1.0).left, WithinAbs(1.0, 1e-12));
    CHECK_THAT(audio::pan_gains(-1.0).right, WithinAbs(0.0, 1e-12));
    CHECK_THAT(audio::pan_gains(1.0).right, WithinAbs(1.0, 1e-12));
}

TEST_CASE("each model in a collision plays its own sound once, with its own mass, at the event") {
    const double h = 2.0;
    Document doc = drop_scene(h, {0, 0, 12}, "click", 1.5);
    Model floor = doc.models()[0];
    floor.collision_sound = "thud";
    floor.mass = 4.0;
    doc.set_model(0, floor);
    auto timeline = physics_test::timeline_of(doc);
    timeline->bake(bounce_time(h, 2) + 0.1);
    REQUIRE(timeline->events().size() == 3);

    const double t0 = bounce_time(h, 0), t1 = bounce_time(h, 1);
    const auto cues = audio::collision_cues(*timeline, 0.0, t0 + 0.01);
    REQUIRE(cues.size() == 2);
    const double speed = std::sqrt(2.0 * G * h);
    for (const auto &c : cues) {
        CHECK_THAT(c.time, WithinAbs(t0, 1e-6));
        CHECK_THAT(c.pan, WithinAbs(0.0, 1e-9));
    }
    // The ball (model 1) and the floor (model 0), each with its own sound and mass; the contact
    // point is the origin, 12 m from the camera.
    const auto ball = cues[0].model == 1 ? cues[0] : cues[1];
    const auto fl = cues[0].model == 0 ? cues[0] : cues[1];
    REQUIRE(ball.model == 1);
    REQUIRE(fl.model == 0);
    CHECK(ball.sound == "click");
    CHECK(fl.sound == "thud");
    CHECK_THAT(ball.volume, WithinRel(expected_volume(1.5, speed, 12.0), 1e-5));
    CHECK_THAT(fl.volume, WithinRel(expected_volume(4.0, speed, 12.0), 1e-5));

    SECTION("the window is (from, to]: an event at `to` is in, one at `from` is out") {
        const double e0 = timeline->events()[0].t, e1 = timeline->events()[1].t;
        CHECK(audio::collision_cues(*timeline, 0.0, e0).size() == 2);
        CHECK(audio::collision_cues(*timeline, e0, e1).size() == 2);
        CHECK(audio::collision_cues(*timeline, e0, e1)[0].time == e1);
        CHECK(audio::collision_cues(*timeline, 0.0, std::nextafter(e0, 0.0)).empty());
        CHECK(audio::collision_cues(*timeline, e0, std::nextafter(e1, 0.0)).empty());
        CHECK_THAT(e1, WithinAbs(t1, 1e-6));
        CHECK(audio::collision_cues(*timeline, -1.0, 100.0).size() == 6);
    }
    SECTION("a model without a collision sound plays nothing") {
        floor.collision_sound = "";
        doc.set_model(0, floor);
        auto quiet_floor = physics_test::timeline_of(doc);
        quiet_floor->bake(t0 + 0.1);
        const auto only_ball = audio::collision_cues(*quiet_floor, 0.0, t0 + 0.1);
        REQUIRE(only_ball.size() == 1);
        CHECK(only_ball[0].model == 1);
    }
}

TEST_CASE("a moving sound plays while the speed is above the threshold, louder when faster") {
    Document doc;
    CameraState cam;
    cam.position = {0, 0, 10};
    doc.set_camera(0, cam);
    Settings s = doc.settings();
    s.max_time_ms = 5000;
    doc.set_settings(s);
    // Gliding balls (Dynamics on, gravity off) at known speeds, and one at rest.
    const double speeds[] = {3.0, 2.0 * audio::kMovingThreshold, audio::kMovingThreshold / 2.0,
                             0.0};
    for (int i = 0; i < 4; ++i) {
        Model m = physics_test::model("ball" + std::to_string(i), "", true, false);
        m.mass = 2.0;
        m.initial_velocity = {speeds[i], 0, 0};
        m.moving_sound = "hum";
        doc.add_model(m, physics_test::placed({0, 0, 0}));
    }
    auto timeline = physics_test::timeline_of(doc);
    timeline->bake(2.0);
    const double t = 1.0;
    const auto states = audio::moving_states(*timeline, t);
    REQUIRE(states.size() == 4);
    // Ball 0 is at (3, 0, 0) at t = 1: sqrt(9 + 100) m from the camera, on its right.
    CHECK(states[0].moving);
    const double r0 = std::sqrt(9.0 + 100.0);
    CHECK_THAT(states[0].volume, WithinRel(expected_volume(2.0, 3.0, r0), 1e-9));
    CHECK_THAT(states[0].pan, WithinAbs(3.0 / r0, 1e-9));
    CHECK(states[1].moving);
    CHECK(states[1].volume > 0.0);
    CHECK(states[1].volume < states[0].volume);
    CHECK_FALSE(states[2].moving);
    CHECK_FALSE(states[3].moving);
    CHECK(states[3].volume == 0.0);
    CHECK(audio::moving_state(*timeline, 0, t).moving);
    CHECK_FALSE(audio::moving_state(*timeline, 3, t).moving);
}

TEST_CASE("has_sounds is true only when a model names a sound") {
    Document doc;
    CHECK_FALSE(audio::has_sounds(doc));
    doc.add_model(physics_test::model("a", "sphere", false, false),
                  physics_test::placed({0, 0, 0}));
    CHECK_FALSE(audio::has_sounds(doc));
    Model m = doc.models()[0];
    m.moving_sound = "hum";
    doc.set_model(0, m);
    CHECK(audio::has_sounds(doc));
}
