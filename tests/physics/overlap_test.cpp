// physics.custom: models that overlap when they start to collide are touching (physics.md,
// "Models that start overlapping"): nothing sinks deeper into what it starts inside; approaching,
// a pair collides at once (elastically: checked against the closed form of a ball bouncing on a
// floor at its starting depth); moving apart, it is let go. Said once per bake, however the
// bake is sliced.
#include "scene_support.hpp"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

using namespace animator;
using namespace physics_test;

namespace {

// The build's plugins with a log of their own, to count what they say.
struct LoggedEnvironment {
    std::vector<std::string> lines;
    Environment environment{
        {test::bin_dir().parent_path() / "assets"},
        {test::bin_dir()},
        [this](ani_log_level, const std::string &, const std::string &m) { lines.push_back(m); }};

    std::unique_ptr<Timeline> timeline(const Document &doc) {
        auto t = std::make_unique<Timeline>(doc, environment.plugins);
        std::vector<std::string> ids, warnings;
        for (const Model &m : doc.models()) ids.push_back(m.mesh);
        t->set_meshes(load_meshes(ids, environment.assets, {}, warnings));
        REQUIRE(warnings.empty());
        return t;
    }

    size_t count(const std::string &text) const {
        return static_cast<size_t>(
            std::count_if(lines.begin(), lines.end(),
                          [&](const std::string &l) { return l.find(text) != std::string::npos; }));
    }
};

// A floor (the plane, 20 m wide, at y = 0) and a ball of radius r whose center starts at y0.
Document ball_in_floor(double y0, glm::dvec3 velocity, bool dynamics = true) {
    Document doc;
    Settings s = doc.settings();
    s.max_time_ms = 100000;
    doc.set_settings(s);
    doc.add_model(model("floor", "plane", false, false), placed({0, 0, 0}, 10.0));
    Model ball = model("ball", "sphere", dynamics, true);
    ball.initial_velocity = velocity;
    doc.add_model(ball, placed({0.3, y0, 0.2}));
    return doc;
}

// The timeline holds one overlap, of `moved` and `other`, and moving `moved` by depth * normal
// parts them (the pair may come either way round, the normal then the other way).
void check_one_overlap(const Timeline &t, uint32_t moved, uint32_t other, glm::dvec3 normal,
                       double depth, double tolerance) {
    REQUIRE(t.overlaps().size() == 1);
    const ani_overlap &o = t.overlaps()[0];
    CHECK(o.t == 0.0);
    const bool same = o.a == moved;
    CHECK((same ? o.b : o.a) == other);
    CHECK((same ? o.a : o.b) == moved);
    const glm::dvec3 n = glm::dvec3(o.normal.x, o.normal.y, o.normal.z) * (same ? 1.0 : -1.0);
    CHECK(glm::length(n - normal) < tolerance);
    CHECK(o.depth == Approx(depth).margin(tolerance));
}

// The lowest the ball's center goes over [0, until], sampled densely and at every event.
double lowest(const Timeline &t, double until) {
    double low = 1e300;
    for (int k = 0; k <= 20000; ++k)
        low = std::min(low, t.evaluate(until * k / 20000.0).models[1].center.y);
    for (const ani_collision_event &e : t.events())
        low = std::min(low, t.evaluate(e.t).models[1].center.y);
    return low;
}

} // namespace

TEST_CASE("a ball sunk into a floor and moving down bounces at once, elastically, at that depth") {
    // Sunk by 0.4 r at 1 m/s down: it bounces at t = 0 and then forever at y0, every period
    // 2 v / G, along the parabola y0 + v tau - G tau^2 / 2 (its apex, y0 + v^2 / 2 G, stays
    // below r: it never gets clear of the floor, so it never reaches the floor's surface again).
    const double r = unit_radius(), y0 = 0.6, v = 1.0, period = 2.0 * v / G;
    REQUIRE(y0 + v * v / (2.0 * G) < r);
    LoggedEnvironment logged;
    auto t = logged.timeline(ball_in_floor(y0, {0, -v, 0}));
    t->bake(10.0);
    const auto &events = t->events();
    REQUIRE(events.size() == static_cast<size_t>(std::floor(10.0 / period)) + 1);
    for (size_t k = 0; k < events.size(); ++k) {
        CAPTURE(k);
        CHECK(events[k].t == Approx(static_cast<double>(k) * period).margin(1e-9));
        CHECK(events[k].normal.y == Approx(1.0));
        CHECK(events[k].speed == Approx(v).epsilon(1e-9));
    }
    for (double time : {0.05, 0.77, 3.3, 9.99}) {
        const double tau = std::fmod(time, period);
        CHECK(t->evaluate(time).models[1].center.y ==
              Approx(y0 + v * tau - 0.5 * G * tau * tau).margin(1e-9));
    }
    CHECK(lowest(*t, 10.0) >= y0 - 1e-12);
    CHECK(logged.count("'ball' and 'floor' overlap at t = 0 s by 0.4 m: treated as touching") == 1);
}

TEST_CASE("a ball sunk into a floor at rest under gravity stays where it is") {
    const double y0 = 0.6;
    LoggedEnvironment logged;
    auto t = logged.timeline(ball_in_floor(y0, {0, 0, 0}));
    t->bake(20.0);
    CHECK(t->events().empty());
    CHECK(lowest(*t, 20.0) >= y0 - 1e-12);
    CHECK(t->evaluate(20.0).models[1].center.y == Approx(y0).margin(1e-12));
    CHECK(logged.count("'ball' and 'floor' overlap") == 1);
}

TEST_CASE("a ball sunk into a floor and moving up is let go, and lands on the floor's surface") {
    // Free from the start: y0 + v t - G t^2 / 2 until it comes down to y = r, where it bounces
    // as any ball would, with the speed the parabola has there.
    const double r = unit_radius(), y0 = 0.6, v = 5.0;
    auto t = timeline_of(ball_in_floor(y0, {0, v, 0}));
    t->bake(2.0);
    const double land = (v + std::sqrt(v * v - 2.0 * G * (r - y0))) / G;
    CHECK(t->evaluate(0.4).models[1].center.y ==
          Approx(y0 + v * 0.4 - 0.5 * G * 0.16).margin(1e-12));
    REQUIRE(t->events().size() >= 1);
    CHECK(t->events()[0].t == Approx(land).epsilon(1e-12));
    CHECK(t->events()[0].speed == Approx(std::sqrt(v * v - 2.0 * G * (r - y0))).epsilon(1e-9));
    CHECK(t->evaluate(t->events()[0].t).models[1].center.y == Approx(r).epsilon(1e-12));
}

TEST_CASE("an overlap is said once over a bake made of many slices, and the slices bake as one") {
    const double y0 = 0.6;
    const Document doc = ball_in_floor(y0, {0, -1, 0});
    LoggedEnvironment sliced_log, whole_log;
    auto sliced = sliced_log.timeline(doc);
    for (int k = 1; k <= 200; ++k) sliced->bake(0.05 * k); // as the editor does
    auto whole = whole_log.timeline(doc);
    whole->bake(10.0);
    CHECK(sliced_log.count("'ball' and 'floor' overlap") == 1);
    CHECK(whole_log.count("'ball' and 'floor' overlap") == 1);
    // Reported to the host once too (the editor highlights the pair): the ball (radius 1) is
    // 1 - y0 into the floor, and moving it up by that parts them.
    check_one_overlap(*sliced, 1, 0, {0, 1, 0}, 1.0 - y0, 1e-12);
    check_one_overlap(*whole, 1, 0, {0, 1, 0}, 1.0 - y0, 1e-12);
    REQUIRE(sliced->events().size() == whole->events().size());
    for (size_t k = 0; k < whole->events().size(); ++k)
        CHECK(sliced->events()[k].t == Approx(whole->events()[k].t).margin(1e-12));
    CHECK(lowest(*sliced, 10.0) >= y0 - 1e-12);
}

TEST_CASE("a cube sunk into a floor never sinks deeper, with or without Dynamics") {
    // The demo scene's cube (issue 16): its mesh spans -1..1, its center 0.5 above the floor.
    for (const bool dynamics : {false, true}) {
        CAPTURE(dynamics);
        Document doc;
        doc.add_model(model("floor", "plane", false, false), placed({0, 0, 0}, 12.0));
        doc.add_model(model("cube", "cube", dynamics, true),
                      placed({-1.5, 0.5, 0}, glm::dvec3(1.0), {0, 30, 0}));
        LoggedEnvironment logged;
        auto t = logged.timeline(doc);
        for (int k = 1; k <= 40; ++k) t->bake(0.1 * k);
        CHECK(lowest(*t, 4.0) >= 0.5 - 1e-9);
        CHECK(t->evaluate(4.0).models[1].center.y == Approx(0.5).margin(1e-9));
        CHECK(logged.count("'cube' and 'floor' overlap at t = 0 s by 0.5 m: treated as touching") ==
              1);
        check_one_overlap(*t, 1, 0, {0, 1, 0}, 0.5, 1e-9);
    }
}

TEST_CASE("two balls overlapping and approaching collide at once, elastically") {
    // Centers 1.5 r apart on x, meeting head on at 1 m/s each, equal masses: they exchange
    // velocities at t = 0 and then part, free.
    const double r = unit_radius();
    Document doc;
    Settings s = doc.settings();
    s.gravity = 0.0;
    doc.set_settings(s);
    Model a = model("a", "sphere", true, false), b = model("b", "sphere", true, false);
    a.initial_velocity = {1, 0, 0};
    b.initial_velocity = {-1, 0, 0};
    doc.add_model(a, placed({-0.75 * r, 0, 0}));
    doc.add_model(b, placed({0.75 * r, 0, 0}));
    auto t = timeline_of(doc);
    t->bake(3.0);
    REQUIRE(t->events().size() == 1);
    CHECK(t->events()[0].t == 0.0);
    CHECK(t->events()[0].speed == Approx(2.0).epsilon(1e-12));
    CHECK(t->evaluate(3.0).models[0].center.x == Approx(-0.75 * r - 3.0).epsilon(1e-12));
    CHECK(t->evaluate(3.0).models[1].center.x == Approx(0.75 * r + 3.0).epsilon(1e-12));
}

TEST_CASE("a ball its keys hold sunk into a floor rests there once its keys end") {
    // Keyed at y0 at 0 s and at 1 s (inside the floor, left alone while keyed), then free under
    // gravity from rest: pressed into the floor, it rests where its keys left it.
    const double y0 = 0.6;
    Document doc = ball_in_floor(y0, {0, 0, 0});
    key(doc, 1000, 1, placed({0.3, y0, 0.2}));
    LoggedEnvironment logged;
    auto t = logged.timeline(doc);
    for (int k = 1; k <= 60; ++k) t->bake(0.05 * k);
    CHECK(lowest(*t, 3.0) >= y0 - 1e-12);
    CHECK(t->evaluate(3.0).models[1].center.y == Approx(y0).margin(1e-12));
    CHECK(logged.count("'ball' and 'floor' overlap") == 1);
}
