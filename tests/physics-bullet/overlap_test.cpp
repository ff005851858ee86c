// physics.bullet: models that overlap at the start are touching (physics.md, "Models that start
// overlapping"): nothing sinks deeper into what it starts inside (within what a step of Bullet
// can move, G dt^2); approaching, a pair collides at once; moving apart, it is let go and lands
// as the closed form says. Said once per bake, however the bake is sliced.
#include "bullet_support.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace animator;
using namespace animator::bullet_test;

namespace {

constexpr double kStep = 1.0 / 240.0; // physics.bullet's default step

size_t said(const std::vector<std::string> &lines, const std::string &text) {
    return static_cast<size_t>(std::count_if(lines.begin(), lines.end(), [&](const std::string &l) {
        return l.find(text) != std::string::npos;
    }));
}

// A floor (the plane, 20 m wide, at y = 0) and a ball of radius r = 0.5 whose center starts at y0.
Document ball_in_floor(double y0, glm::dvec3 velocity) {
    Document doc;
    doc.add_model(model("floor", "plane", false, false), placed({0, 0, 0}, glm::dvec3(10.0)));
    Model ball = model("ball", "sphere", true, true);
    ball.initial_velocity = velocity;
    doc.add_model(ball, placed({0.3, y0, 0.2}, glm::dvec3(0.5)));
    return doc;
}

double lowest(const Timeline &t, int model, double until) {
    double low = 1e300;
    for (int k = 0; k <= 20000; ++k)
        low = std::min(low,
                       t.evaluate(until * k / 20000.0).models[static_cast<size_t>(model)].center.y);
    return low;
}

} // namespace

TEST_CASE("a ball sunk into a floor never goes deeper, and bounces at once when moving down") {
    const double y0 = 0.3; // sunk by 0.2 of its 0.5 radius
    for (const double v : {0.0, 1.0}) {
        CAPTURE(v);
        take_log();
        auto t = timeline_of(ball_in_floor(y0, {0, -v, 0}));
        t->bake(10.0);
        // Within the band Bullet's steps move a resting ball in: G dt^2.
        CHECK(lowest(*t, 1, 10.0) >= y0 - G * kStep * kStep);
        if (v > 0.0) {
            REQUIRE_FALSE(t->events().empty());
            CHECK(t->events()[0].t == Approx(0.0).margin(kStep));
            CHECK(t->events()[0].speed == Approx(v).margin(2.0 * G * kStep));
            CHECK(t->evaluate(2.0 * kStep).models[1].velocity.y > 0.0); // on its way up
        }
        CHECK(said(take_log(),
                   "'floor' and 'ball' overlap at t = 0 s by 0.2 m: treated as touching") == 1);
    }
}

TEST_CASE("a ball sunk into a floor and moving up is let go, and lands on the floor's surface") {
    const double r = 0.5 * unit_sphere_radius(), y0 = 0.3, v = 5.0;
    auto t = timeline_of(ball_in_floor(y0, {0, v, 0}));
    t->bake(2.0);
    const double land = (v + std::sqrt(v * v - 2.0 * G * (r - y0))) / G;
    REQUIRE_FALSE(t->events().empty());
    CHECK(t->events()[0].t == Approx(land).margin(2.0 * kStep));
    CHECK(t->events()[0].speed == Approx(std::sqrt(v * v - 2.0 * G * (r - y0))).epsilon(1e-2));
    // Free on its way up: the parabola, to Bullet's first-order error.
    CHECK(t->evaluate(0.4).models[1].center.y ==
          Approx(y0 + v * 0.4 - 0.5 * G * 0.16).margin(G * kStep));
}

TEST_CASE("an overlap, and each shape, is said once over a bake made of many slices") {
    take_log();
    auto t = timeline_of(ball_in_floor(0.3, {0, -1, 0}));
    for (int k = 1; k <= 80; ++k) t->bake(0.05 * k); // as the editor does
    const auto log = take_log();
    CHECK(said(log, "'floor' and 'ball' overlap") == 1);
    CHECK(said(log, "model 'ball': sphere shape") == 1); // the shapes too, once per bake
    CHECK(lowest(*t, 1, 4.0) >= 0.3 - G * kStep * kStep);
}

TEST_CASE("a cube sunk into a floor with Gravity and without Dynamics stays where it is") {
    // The demo scene's cube (issue 16): its mesh spans -1..1, its center 0.5 above the floor.
    take_log();
    Document doc;
    doc.add_model(model("floor", "plane", false, false), placed({0, 0, 0}, glm::dvec3(12.0)));
    doc.add_model(model("cube", "cube", false, true),
                  placed({-1.5, 0.5, 0}, glm::dvec3(1.0), {0, 30, 0}));
    auto t = timeline_of(doc);
    for (int k = 1; k <= 40; ++k) t->bake(0.1 * k);
    CHECK(lowest(*t, 1, 4.0) >= 0.5 - G * kStep * kStep);
    CHECK(said(take_log(), "'floor' and 'cube' overlap") == 1);
    // Reported to the host once too, as Bullet measured it: moving the cube up by the depth
    // (0.5 m, less Bullet's contact slop) parts them.
    REQUIRE(t->overlaps().size() == 1);
    const ani_overlap &o = t->overlaps()[0];
    const bool cube_first = o.a == 1;
    CHECK((cube_first ? o.b : o.a) == 0u);
    CHECK(o.t == 0.0);
    const glm::dvec3 n = glm::dvec3(o.normal.x, o.normal.y, o.normal.z) * (cube_first ? 1.0 : -1.0);
    CHECK(glm::length(n - glm::dvec3(0, 1, 0)) < 1e-6);
    CHECK(o.depth == Approx(0.5).margin(0.01));
}

TEST_CASE("a ball its keys hold sunk into a floor does not sink once its keys end") {
    // Keyed at y0 at 0 s and at 1 s (inside the floor, left alone while keyed), then free under
    // gravity from rest: Bullet's contact holds it (and pushes it out), it never goes deeper.
    const double y0 = 0.3;
    Document doc = ball_in_floor(y0, {0, 0, 0});
    key(doc, 1000, 1, placed({0.3, y0, 0.2}, glm::dvec3(0.5)));
    auto t = timeline_of(doc);
    for (int k = 1; k <= 60; ++k) t->bake(0.05 * k);
    CHECK(lowest(*t, 1, 3.0) >= y0 - G * kStep * kStep);
    CHECK(t->evaluate(3.0).models[1].center.y >= y0 - G * kStep * kStep);
}
