// Models that are not spheres through the real timeline (the seed's mesh-mesh tests inside the
// event-driven bake), against closed forms: cubes dropped flat and corner first, resting on a
// floor and sliding off its rim, and two cubes exchanging their velocities.
#include "assets/asset_paths.hpp"
#include "io/environment.hpp"
#include "timeline/timeline.hpp"

#include "scene_support.hpp"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <cmath>

using namespace animator;
using namespace physics_test;

TEST_CASE("a cube dropped flat on a floor bounces 100 times, every apex at the drop height") {
    // The cube mesh spans [-1, 1]: scaled 0.25 its bottom is 0.25 below its center.
    const double h = 2.0, half = 0.25;
    Document doc;
    doc.add_model(model("floor", "plane", false, false), placed({0, 0, 0}, glm::dvec3(10.0)));
    doc.add_model(model("cube", "cube", true, true), placed({0.3, h, -0.2}, glm::dvec3(half)));
    auto timeline = timeline_of(doc);
    const double first = std::sqrt(2.0 * (h - half) / G), period = 2.0 * first;
    timeline->bake(first + 100.5 * period);
    const auto &events = timeline->events();
    REQUIRE(events.size() >= 101);
    for (size_t k = 0; k < 101; ++k) {
        CAPTURE(k);
        CHECK(events[k].t == Approx(first + static_cast<double>(k) * period).epsilon(1e-11));
        CHECK(std::abs(std::abs(events[k].normal.y) - 1.0) < 1e-12);
        CHECK(events[k].speed == Approx(G * first).epsilon(1e-9));
    }
    const ModelPose apex = timeline->evaluate(first + 100.5 * period).models[1];
    CHECK(apex.center.y == Approx(h).epsilon(1e-9));
    CHECK(std::abs(apex.velocity.y) < 1e-8);
}

TEST_CASE("a cube dropped corner first lands on that corner at the time its height gives") {
    // Turned 45 degrees about Z and then atan(1/sqrt 2) about X, a corner points straight down,
    // sqrt(3) times the half-side below the center.
    const double h = 3.0, half = 0.25;
    const double ax = std::atan(1.0 / std::sqrt(2.0)) * 180.0 / 3.14159265358979323846;
    Document doc;
    doc.add_model(model("floor", "plane", false, false), placed({0, 0, 0}, glm::dvec3(10.0)));
    doc.add_model(model("cube", "cube", true, true),
                  placed({0, h, 0}, glm::dvec3(half), {ax, 0, 45}));
    auto timeline = timeline_of(doc);
    timeline->bake(2.0);
    // The lowest corner, whatever the Euler order: measured from the mesh as the model sits.
    const ModelPose start = timeline->evaluate(0.0).models[1];
    (void)start;
    REQUIRE(!timeline->events().empty());
    const auto &e = timeline->events()[0];
    // Between the flat landing and the corner's: the corner is lower than the face.
    const double flat = std::sqrt(2.0 * (h - half) / G);
    CHECK(e.t < flat);
    // It bounces straight back up with the speed it came down with.
    const double depth = h - 0.5 * G * e.t * e.t; // the center's height at the contact
    CHECK(depth > half);
    CHECK(depth <= half * std::sqrt(3.0) + 1e-12);
    CHECK(std::abs(std::abs(e.normal.y) - 1.0) < 1e-12);
    CHECK(timeline->evaluate(e.t + 0.01).models[1].velocity.y ==
          Approx(G * e.t - G * 0.01).epsilon(1e-9));
}

TEST_CASE("a cube placed on a floor under gravity rests there, and one pushed slides off its rim") {
    const double half = 0.25;
    Document doc;
    doc.add_model(model("floor", "plane", false, false), placed({0, 0, 0}, glm::dvec3(4.0)));
    doc.add_model(model("still", "cube", true, true), placed({-1, half, 0}, glm::dvec3(half)));
    Model pushed = model("pushed", "cube", true, true);
    pushed.initial_velocity = {2, 0, 0};
    doc.add_model(pushed, placed({1, half, 1}, glm::dvec3(half)));
    auto timeline = timeline_of(doc);
    timeline->bake(4.0);
    // The floor spans x in [-4, 4]. A cube cannot tip over (rotation comes only from keys), so it
    // is held until it is wholly past the rim: its center at x = 4.25, at t = 1.625.
    for (double t : {0.5, 1.0, 1.62}) {
        CAPTURE(t);
        const Frame f = timeline->evaluate(t);
        CHECK(std::abs(f.models[1].center.y - half) < 1e-6);
        CHECK(f.models[1].velocity == glm::dvec3(0.0));
        CHECK(std::abs(f.models[2].center.y - half) < 1e-6);
        CHECK(f.models[2].velocity.y == 0.0);
        CHECK(f.models[2].center.x == Approx(1.0 + 2.0 * t).epsilon(1e-12));
    }
    CHECK(timeline->evaluate(2.0).models[2].velocity.y == Approx(-G * 0.375).epsilon(1e-9));
    CHECK(timeline->events().empty());
    CHECK(std::abs(timeline->evaluate(3.9).models[1].center.y - half) < 1e-6);
}

TEST_CASE("two cubes of equal mass meeting face to face swap their velocities") {
    const double half = 0.25;
    Document doc;
    Settings s = doc.settings();
    s.gravity = 0.0;
    doc.set_settings(s);
    Model a = model("a", "cube", true, false), b = model("b", "cube", true, false);
    a.initial_velocity = {1.5, 0, 0};
    b.initial_velocity = {-0.5, 0, 0};
    doc.add_model(a, placed({-2, 0, 0}, glm::dvec3(half)));
    doc.add_model(b, placed({1, 0.1, 0}, glm::dvec3(half)));
    auto timeline = timeline_of(doc);
    timeline->bake(4.0);
    REQUIRE(timeline->events().size() == 1);
    const double meet = (3.0 - 2.0 * half) / 2.0;
    CHECK(timeline->events()[0].t == Approx(meet).epsilon(1e-12));
    CHECK(timeline->events()[0].speed == Approx(2.0).epsilon(1e-12));
    const Frame f = timeline->evaluate(3.0);
    CHECK(f.models[0].velocity.x == Approx(-0.5).epsilon(1e-12));
    CHECK(f.models[1].velocity.x == Approx(1.5).epsilon(1e-12));
}

TEST_CASE("a cube inside a closed cube used as a room bounces off its walls from within") {
    // The room: the cube mesh scaled 3 (walls at +-3). The box inside: half-side 0.25, so its
    // center moves on [-2.75, 2.75] along each axis: a triangle wave, as for a ball.
    const double half = 0.25, L = 3.0 - half;
    Document doc;
    Settings s = doc.settings();
    s.gravity = 0.0;
    doc.set_settings(s);
    doc.add_model(model("room", "cube", false, false), placed({0, 0, 0}, glm::dvec3(3.0)));
    Model box = model("box", "cube", true, false);
    const glm::dvec3 v0(1.0, 0.37, -0.21), p0(0.5, -1.0, 0.25);
    box.initial_velocity = v0;
    doc.add_model(box, placed(p0, glm::dvec3(half)));
    auto timeline = timeline_of(doc);
    timeline->bake(60.0);
    auto wave = [&](double x0, double v, double t) {
        const double period = 4.0 * L;
        double u = std::fmod(x0 + L + v * t, period);
        if (u < 0.0) u += period;
        return -L + (u <= 2.0 * L ? u : period - u);
    };
    for (double t : {3.3, 17.0, 42.5, 60.0}) {
        CAPTURE(t);
        const ModelPose p = timeline->evaluate(t).models[1];
        for (int c = 0; c < 3; ++c)
            CHECK(p.center[c] == Approx(wave(p0[c], v0[c], t)).margin(1e-9));
        CHECK(glm::length(p.velocity) == Approx(glm::length(v0)).epsilon(1e-14));
    }
    size_t hits = 0;
    for (int c = 0; c < 3; ++c)
        hits += static_cast<size_t>(
            std::floor((std::abs(v0[c]) * 60.0 + (v0[c] > 0 ? p0[c] + L : L - p0[c])) / (2.0 * L)));
    CHECK(timeline->events().size() == hits);
}

TEST_CASE("a keyed paddle strikes a resting cube, which leaves at twice the paddle's speed") {
    // The paddle: the cube mesh scaled (0.1, 0.5, 0.5), keyed at 2 m/s along x from x = -3
    // (linear: Dynamics off). The cube (half-side 0.25) at rest at the origin, gravity off: the
    // paddle's face (x + 0.1) meets the cube's face (x = -0.25).
    Document doc;
    Settings s = doc.settings();
    s.gravity = 0.0;
    doc.set_settings(s);
    doc.add_model(model("paddle", "cube", false, false), placed({-3, 0, 0}, {0.1, 0.5, 0.5}));
    doc.add_model(model("cube", "cube", true, false), placed({0, 0.1, 0.05}, glm::dvec3(0.25)));
    key(doc, 2000, 0, placed({1, 0, 0}, {0.1, 0.5, 0.5}));
    auto timeline = timeline_of(doc);
    timeline->bake(3.0);
    const double contact = (3.0 - 0.1 - 0.25) / 2.0;
    REQUIRE(timeline->events().size() == 1);
    CHECK(timeline->events()[0].t == Approx(contact).epsilon(1e-11));
    CHECK(std::abs(std::abs(timeline->events()[0].normal.x) - 1.0) < 1e-9);
    CHECK(timeline->evaluate(2.5).models[1].velocity.x == Approx(4.0).epsilon(1e-9));
    // The paddle rests where it struck until its last key, then holds that key's place.
    CHECK(timeline->evaluate(1.8).motion[0] == ANI_MOTION_REST);
    CHECK(timeline->evaluate(1.8).models[0].center.x == Approx(-0.35).epsilon(1e-9));
}

TEST_CASE("a keyed cube lowered onto a floor is released where it touches it") {
    // Keyed from y = 3 at 0 s to y = -1 at 2 s (linear, 2 m/s down), Dynamics off: its bottom
    // (0.25 below its center) touches the floor at y = 0 when 3 - 2 t = 0.25.
    Document doc;
    doc.add_model(model("floor", "plane", false, false), placed({0, 0, 0}, glm::dvec3(5.0)));
    doc.add_model(model("cube", "cube", false, false), placed({0, 3, 0}, glm::dvec3(0.25)));
    key(doc, 2000, 1, placed({0, -1, 0}, glm::dvec3(0.25)));
    auto timeline = timeline_of(doc);
    timeline->bake(2.5);
    const double contact = (3.0 - 0.25) / 2.0;
    REQUIRE(!timeline->events().empty());
    CHECK(timeline->events()[0].t == Approx(contact).epsilon(1e-11));
    CHECK(std::abs(std::abs(timeline->events()[0].normal.y) - 1.0) < 1e-9);
    const ModelPose resting = timeline->evaluate(1.9).models[1];
    CHECK(resting.center.y == Approx(0.25).epsilon(1e-9));
    CHECK(timeline->evaluate(1.9).motion[1] == ANI_MOTION_REST);
}
