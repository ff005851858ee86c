// The timeline and the bake, through the real plugins (interpolation, physics.custom), against
// hand-computed values and the seed's closed forms.
#include "timeline/bake_job.hpp"

#include "support.hpp"

#include <catch2/catch.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>

using namespace animator;

namespace {

PluginRegistry &plugins() {
    static PluginRegistry r({test::bin_dir()}, [](ani_log_level, const std::string &, const std::string &) {});
    return r;
}

ModelState at(double x, double y = 0.0, double z = 0.0) {
    ModelState s;
    s.center = {x, y, z};
    return s;
}

// Adds a model keyed at (0,0,0) at t = 0 and at (2,0,0) at t = 1 s.
int add_mover(Document &doc, const std::string &name, bool dynamics, bool gravity) {
    Model m;
    m.name = name;
    m.mesh = "sphere";
    m.dynamics = dynamics;
    m.gravity = gravity;
    doc.add_model(m, at(0.0));
    const int index = static_cast<int>(doc.models().size()) - 1;
    if (doc.find_keyframe(1000) < 0) {
        Keyframe k;
        k.time_ms = 1000;
        k.states.assign(doc.models().size(), std::nullopt);
        doc.insert_keyframe(k);
    }
    doc.set_state(1000, index, at(2.0));
    return index;
}

Document four_cases(Axis down) {
    Document doc;
    Settings s = doc.settings();
    s.down_axis = down;
    s.max_time_ms = 10000;
    doc.set_settings(s);
    add_mover(doc, "stops", false, false);
    add_mover(doc, "drops", false, true);
    add_mover(doc, "glides", true, false);
    add_mover(doc, "flies", true, true);
    return doc;
}

} // namespace

TEST_CASE("after the last keyframe: stop, fall, constant velocity, projectile (down axis y, x, z)") {
    const double G = 9.81;
    for (Axis down : {Axis::Y, Axis::X, Axis::Z}) {
        CAPTURE(static_cast<int>(down));
        Timeline timeline(four_cases(down), plugins());
        timeline.bake(10.0);
        const int d = static_cast<int>(down);
        for (double t : {1.0, 1.5, 2.0, 4.25, 10.0}) {
            CAPTURE(t);
            const double tau = t - 1.0;
            const Frame f = timeline.evaluate(t);
            // Kinematic key from (0,0,0) at rest to (2,0,0) in 1 s: a = 2 d / dt^2 = 4, so it
            // leaves its last key at 4 m/s along x (seed, "Keyframe Interpolation with
            // Kinematic Equations").
            glm::dvec3 stops(2, 0, 0), drops(2, 0, 0), glides(2 + 4 * tau, 0, 0), flies(2 + 4 * tau, 0, 0);
            drops[d] -= G * tau * tau / 2;
            flies[d] -= G * tau * tau / 2;
            glm::dvec3 drop_v(0.0), fly_v(4, 0, 0);
            drop_v[d] -= G * tau;
            fly_v[d] -= G * tau;
            for (int c = 0; c < 3; ++c) {
                CHECK(f.models[0].center[c] == Approx(stops[c]).margin(1e-12));
                CHECK(f.models[1].center[c] == Approx(drops[c]).margin(1e-12));
                CHECK(f.models[2].center[c] == Approx(glides[c]).margin(1e-12));
                CHECK(f.models[3].center[c] == Approx(flies[c]).margin(1e-12));
                CHECK(f.models[1].velocity[c] == Approx(drop_v[c]).margin(1e-12));
                CHECK(f.models[3].velocity[c] == Approx(fly_v[c]).margin(1e-12));
            }
            CHECK(f.models[0].velocity == glm::dvec3(0.0));
        }
    }
}

TEST_CASE("between keys: linear for Dynamics off, kinematic for Dynamics on, keys reached on time") {
    Document doc = four_cases(Axis::Y);
    Keyframe k;
    k.time_ms = 3000;
    k.states.assign(4, std::nullopt);
    k.states[0] = at(2.0, 4.0);
    k.states[2] = at(0.0);
    doc.insert_keyframe(k);
    Timeline timeline(doc, plugins());
    timeline.bake(10.0);
    // Linear: (0,0,0) -> (2,0,0) over [0, 1], then -> (2,4,0) over [1, 3].
    CHECK(timeline.evaluate(0.25).models[0].center.x == Approx(0.5));
    CHECK(timeline.evaluate(2.0).models[0].center.y == Approx(2.0));
    CHECK(timeline.evaluate(2.0).models[0].velocity.y == Approx(2.0)); // 4 m over 2 s
    // Kinematic, "glides": segment 1 from x=0 at rest to x=2 in 1 s: a = 4, x(t) = 2 t^2, so
    // x(0.5) = 0.5; it reaches x=2 at 4 m/s. Segment 2 from x=2 at 4 m/s to x=0 in 2 s:
    // a = 2 (d - v0 dt) / dt^2 = 2 (-2 - 8) / 4 = -5, so x(2) = 2 + 4 - 2.5 = 3.5.
    CHECK(timeline.evaluate(0.5).models[2].center.x == Approx(0.5));
    CHECK(timeline.evaluate(2.0).models[2].center.x == Approx(3.5));
    for (double key : {1.0, 3.0}) {
        CHECK(timeline.evaluate(key).models[2].center.x == Approx(key == 1.0 ? 2.0 : 0.0).margin(1e-12));
        const double left = timeline.evaluate(key - 1e-7).models[2].velocity.x;
        const double right = timeline.evaluate(key + 1e-7).models[2].velocity.x;
        CHECK(left == Approx(right).margin(1e-5)); // velocity is continuous across keys
    }
    // After its last key (3 s) it leaves at v = 4 + (-5)(2) = -6 m/s.
    CHECK(timeline.evaluate(4.0).models[2].center.x == Approx(-6.0));
}

TEST_CASE("angles wrap the seed's way: 20 to 350 degrees goes through 0") {
    Document doc;
    Model m;
    m.name = "spinner";
    m.mesh = "cube";
    ModelState s;
    s.angles = {20.0, 0.0, 0.0};
    doc.add_model(m, s);
    Keyframe k;
    k.time_ms = 1000;
    ModelState e;
    e.angles = {350.0, 0.0, 0.0};
    k.states = {e};
    doc.insert_keyframe(k);
    Timeline timeline(doc, plugins());
    timeline.bake(2.0);
    CHECK(timeline.evaluate(0.5).models[0].angles.x == Approx(5.0));   // 20 - 15
    CHECK(timeline.evaluate(0.75).models[0].angles.x == Approx(357.5)); // 20 - 22.5 + 360
    CHECK(timeline.evaluate(1.5).models[0].angles.x == Approx(350.0));  // held after the last key
}

TEST_CASE("the camera's rotation stays orthonormal between keys") {
    Document doc;
    CameraState c1, c2;
    c1.rotation = glm::angleAxis(glm::radians(10.0), glm::normalize(glm::dvec3(1, 2, 3)));
    c2.rotation = glm::angleAxis(glm::radians(170.0), glm::normalize(glm::dvec3(-3, 1, 0.5)));
    c2.position = {4, 5, 6};
    c2.fov_degrees = 80.0;
    doc.set_camera(0, c1);
    Keyframe k;
    k.time_ms = 2000;
    k.camera = c2;
    doc.insert_keyframe(k);
    Timeline timeline(doc, plugins());
    timeline.bake(2.0);
    for (int i = 0; i <= 100; ++i) {
        const double t = 2.0 * i / 100.0;
        const CameraState c = timeline.evaluate(t).camera;
        const glm::dmat3 r = glm::mat3_cast(c.rotation);
        const glm::dmat3 should_be_identity = glm::transpose(r) * r;
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) CHECK(should_be_identity[a][b] == Approx(a == b ? 1.0 : 0.0).margin(1e-12));
        CHECK(glm::determinant(r) == Approx(1.0).margin(1e-12));
        CHECK(c.position.x == Approx(2.0 * t));     // linear from 0 to 4 over 2 s
        CHECK(c.fov_degrees == Approx(50.0 + 15.0 * t)); // 50 -> 80
    }
}

TEST_CASE("scrubbing forward then back gives identical states") {
    Timeline timeline(four_cases(Axis::Y), plugins());
    timeline.bake(10.0);
    std::vector<Frame> forward;
    for (int i = 0; i <= 200; ++i) forward.push_back(timeline.evaluate(i * 0.05));
    for (int i = 200; i >= 0; --i) {
        const Frame back = timeline.evaluate(i * 0.05);
        for (size_t m = 0; m < back.models.size(); ++m) {
            CHECK(back.models[m].center == forward[static_cast<size_t>(i)].models[m].center);
            CHECK(back.models[m].velocity == forward[static_cast<size_t>(i)].models[m].velocity);
        }
    }
}

TEST_CASE("an edit re-bakes only from the earliest time it can change") {
    Document doc = four_cases(Axis::Y);
    for (std::int64_t t : {4000, 6000}) {
        Keyframe k;
        k.time_ms = t;
        k.states.assign(4, std::nullopt);
        k.states[1] = at(static_cast<double>(t) / 1000.0);
        doc.insert_keyframe(k);
    }
    Timeline timeline(doc, plugins());
    timeline.bake(10.0);
    CHECK(timeline.stats().bake_calls == 1);
    CHECK(timeline.stats().seconds_baked == 10.0);
    const Frame before_edit = timeline.evaluate(3.0);

    // Moving "drops" at its 6 s key changes its motion from its previous key, at 4 s.
    Document edited = timeline.document();
    edited.set_state(6000, 1, at(9.0));
    CHECK(Timeline::affected_from(timeline.document(), edited) == 4.0);
    timeline.set_document(edited);
    CHECK(timeline.stats().bake_calls == 2);
    CHECK(timeline.stats().seconds_baked == Approx(10.0 + 6.0)); // [4, 10] again, not [0, 10]
    CHECK(timeline.evaluate(3.0).models[1].center == before_edit.models[1].center);
    CHECK(timeline.evaluate(6.0).models[1].center.x == Approx(9.0));

    // The result is the same as baking the edited document from scratch, to rounding: a free
    // flight that the re-bake split at 4 s is the same parabola, evaluated from another origin.
    Timeline fresh(edited, plugins());
    fresh.bake(10.0);
    for (double t : {0.5, 3.0, 4.5, 6.0, 7.25, 10.0})
        for (size_t m = 0; m < 4; ++m)
            for (int c = 0; c < 3; ++c)
                CHECK(timeline.evaluate(t).models[m].center[c] ==
                      Approx(fresh.evaluate(t).models[m].center[c]).epsilon(1e-14).margin(1e-12));

    // A colour or a camera key moves nothing: no bake at all.
    Document recoloured = timeline.document();
    Model m0 = recoloured.models()[0];
    m0.material.kd = {0.1, 0.2, 0.3};
    recoloured.set_model(0, m0);
    CameraState cam;
    cam.position = {1, 2, 3};
    recoloured.set_camera(0, cam);
    timeline.set_document(recoloured);
    CHECK(timeline.stats().bake_calls == 2);
    CHECK(timeline.evaluate(0.0).camera.position == glm::dvec3(1, 2, 3));

    // Gravity changes every fall: from 0.
    Document heavier = timeline.document();
    Settings s = heavier.settings();
    s.gravity = 20.0;
    heavier.set_settings(s);
    CHECK(Timeline::affected_from(timeline.document(), heavier) == 0.0);
}

TEST_CASE("a long bake holds a few segments, not one sample per frame") {
    Document doc = four_cases(Axis::Y);
    Settings s = doc.settings();
    s.max_time_ms = 300000000; // 300000 s, the longest animation
    doc.set_settings(s);
    Timeline timeline(doc, plugins());
    timeline.bake(300000.0);
    for (int m = 0; m < 4; ++m) CHECK(timeline.segments(m).size() <= 3);
    // ... and is still exact at the end: the glider moved 4 m/s for 299999 s.
    CHECK(timeline.evaluate(300000.0).models[2].center.x == Approx(2.0 + 4.0 * 299999.0));
}

TEST_CASE("a bake can be cancelled and what was baked before stays") {
    Timeline timeline(four_cases(Axis::Y), plugins());
    timeline.bake(5.0);
    int calls = 0;
    CHECK_THROWS_AS(timeline.bake(10.0, [&](double) { return ++calls < 2; }), BakeCancelled);
    CHECK(timeline.baked_until() == 5.0);
    CHECK(timeline.evaluate(5.0).models[1].center.y == Approx(-9.81 * 16.0 / 2.0));
    timeline.bake(10.0);
    CHECK(timeline.baked_until() == 10.0);
}

TEST_CASE("an unknown physics backend is a clear error") {
    CHECK_THROWS_WITH(Timeline(four_cases(Axis::Y), plugins(), "physics.nope"),
                      Catch::Contains("no physics backend 'physics.nope'") && Catch::Contains("physics.custom"));
}

TEST_CASE("an animation can choose the smooth interpolator: through every key, with no kinks") {
    Document doc;
    Model m;
    m.name = "ship";
    m.mesh = "cube";
    doc.add_model(m, at(0.0));
    const double xs[] = {0.0, 1.0, 4.0, 2.0};
    for (int i = 1; i < 4; ++i) {
        Keyframe k;
        k.time_ms = 1000 * i;
        k.states = {at(xs[i])};
        doc.insert_keyframe(k);
    }
    Settings s = doc.settings();
    s.interpolation = "interpolation.smooth";
    doc.set_settings(s);
    Timeline smooth(doc, plugins());
    smooth.bake(3.0);
    for (int i = 0; i < 4; ++i) CHECK(smooth.evaluate(i).models[0].center.x == Approx(xs[i]).margin(1e-12));
    for (double key : {1.0, 2.0}) // C1: the velocity has no jump at interior keys
        CHECK(smooth.evaluate(key - 1e-7).models[0].velocity.x == Approx(smooth.evaluate(key + 1e-7).models[0].velocity.x).margin(1e-5));
    // Catmull-Rom at key 1: tangent (4 - 0) / (2 - 0) = 2 m/s, where linear would jump from 1 to 3.
    CHECK(smooth.evaluate(1.0).models[0].velocity.x == Approx(2.0));

    s.interpolation = "interpolation.linear";
    doc.set_settings(s);
    CHECK(Timeline::affected_from(smooth.document(), doc) == 0.0);
    smooth.set_document(doc);
    CHECK(smooth.evaluate(1.5).models[0].center.x == Approx(2.5)); // halfway from 1 to 4
    Settings missing = doc.settings();
    missing.interpolation = "interpolation.cubic";
    doc.set_settings(missing);
    CHECK_THROWS_WITH(Timeline(doc, plugins()), Catch::Contains("no interpolator plugin 'interpolation.cubic'"));
}

TEST_CASE("a bake runs on a worker thread, reports progress, and hands the timeline back") {
    auto timeline = std::make_unique<Timeline>(four_cases(Axis::Y), plugins());
    BakeJob job(std::move(timeline), 10.0);
    job.start();
    BakeJob::Result result = job.wait();
    CHECK(job.done());
    CHECK(job.progress() == 1.0);
    CHECK_FALSE(result.cancelled);
    CHECK(result.error.empty());
    REQUIRE(result.timeline);
    CHECK(result.timeline->baked_until() == 10.0);
    CHECK(result.timeline->evaluate(3.0).models[3].center.x == Approx(2.0 + 4.0 * 2.0));
}

TEST_CASE("a bake on a worker thread can be cancelled, keeping what was baked before") {
    Document doc;
    Model m;
    m.mesh = "sphere";
    m.gravity = true;
    for (int i = 0; i < 200; ++i) {
        m.name = "ball" + std::to_string(i);
        doc.add_model(m, at(static_cast<double>(i)));
    }
    auto timeline = std::make_unique<Timeline>(doc, plugins());
    timeline->bake(1.0);
    BakeJob job(std::move(timeline), 30.0);
    job.cancel(); // before it starts: the first progress report stops it
    job.start();
    BakeJob::Result result = job.wait();
    CHECK(result.cancelled);
    REQUIRE(result.timeline);
    CHECK(result.timeline->baked_until() == 1.0);
    CHECK(result.timeline->evaluate(1.0).models[7].center.y == Approx(-9.81 / 2.0));
}

TEST_CASE("a bake of thousands of models starts each one from its own keys") {
    // 5,000 balls keyed once at t = 0, each where no other is, all gliding with the same initial
    // velocity (so none meets another): their starts are found in two halves at once
    // (Timeline::run_bake), and each must fly on from its own key.
    Document doc;
    const int n = 5000;
    const glm::dvec3 v(1.0, 0.5, -0.25);
    const auto key_of = [](int m) { return glm::dvec3(3.0 * (m % 100), 3.0 * (m / 100), 0.001 * m); };
    for (int m = 0; m < n; ++m) {
        Model ball;
        ball.name = "ball " + std::to_string(m);
        ball.mesh = "sphere";
        ball.dynamics = true;
        ball.gravity = false;
        ball.initial_velocity = v;
        const glm::dvec3 p = key_of(m);
        doc.add_model(ball, at(p.x, p.y, p.z));
    }
    Timeline timeline(doc, plugins());
    timeline.bake(2.0);
    const Frame f = timeline.evaluate(1.5);
    int wrong = 0, first_wrong = -1;
    for (int m = 0; m < n; ++m) {
        const glm::dvec3 expected = key_of(m) + 1.5 * v;
        if (glm::length(f.models[static_cast<size_t>(m)].center - expected) > 1e-12 ||
            f.models[static_cast<size_t>(m)].velocity != v) {
            ++wrong;
            if (first_wrong < 0) first_wrong = m;
        }
    }
    CAPTURE(first_wrong);
    CHECK(wrong == 0);
}
