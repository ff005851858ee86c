// Keyed models as moving walls (physics.md): conservative advancement on its own against
// closed forms, then through the real timeline: a free ball reflects off a keyed model with the
// relative velocity of the point it touches, and the keyed model is released from its keys at
// the contact and takes them up again at its next key.
#include "assets/asset_paths.hpp"
#include "io/environment.hpp"
#include "keyed_contact.hpp"
#include "timeline/timeline.hpp"

#include "scene_support.hpp"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <cmath>

using namespace animator;
using namespace physics_test;
using physics_custom::advance_to_contact;
using physics_custom::Approach;
using physics_custom::ApproachOutcome;

namespace {

const double kPi = 3.14159265358979323846;

const ani_motion_segment *segment_at(const Timeline &t, int model, double time) {
    for (const auto &s : t.segments(model))
        if (s.t0 <= time && time < s.t1) return &s;
    return nullptr;
}

} // namespace

TEST_CASE("conservative advancement finds the first contact of a closing gap") {
    Approach linear;
    linear.gap = [](double t) { return 5.0 - 2.0 * t; };
    SECTION("with an exact bound") {
        linear.closing_speed = [](double, double) { return 2.0; };
        const auto out = advance_to_contact(linear, 0.0, 10.0, 1e-13);
        REQUIRE(out.kind == ApproachOutcome::kContact);
        CHECK(out.t == Approx(2.5).epsilon(1e-12));
    }
    SECTION("with a bound ten times too large") {
        linear.closing_speed = [](double, double) { return 20.0; };
        const auto out = advance_to_contact(linear, 0.0, 10.0, 1e-13);
        REQUIRE(out.kind == ApproachOutcome::kContact);
        CHECK(out.t == Approx(2.5).epsilon(1e-12));
    }
    SECTION("with a bound three times too small: the overshoot is bisected back") {
        linear.closing_speed = [](double, double) { return 2.0 / 3.0; };
        const auto out = advance_to_contact(linear, 0.0, 10.0, 1e-13);
        REQUIRE(out.kind == ApproachOutcome::kContact);
        CHECK(out.t == Approx(2.5).epsilon(1e-12));
    }
    SECTION("not within the window") {
        linear.closing_speed = [](double, double) { return 2.0; };
        CHECK(advance_to_contact(linear, 0.0, 2.4, 1e-13).kind == ApproachOutcome::kNone);
    }
}

TEST_CASE(
    "conservative advancement: a turning bar reaches a point at the angle the geometry says") {
    // A bar through the origin turning at w rad/s; a ball of radius r at distance d and polar
    // angle a0: the gap is d sin(a0 - w t) - r while the bar has not passed it.
    const double w = 2.0, d = 1.5, a0 = 1.0, r = 0.2, half_length = 2.0;
    Approach bar;
    bar.gap = [&](double t) { return d * std::sin(a0 - w * t) - r; };
    bar.closing_speed = [&](double, double) { return w * half_length; };
    const auto out = advance_to_contact(bar, 0.0, 1.0, 1e-13);
    REQUIRE(out.kind == ApproachOutcome::kContact);
    CHECK(out.t == Approx((a0 - std::asin(r / d)) / w).epsilon(1e-12));
}

TEST_CASE(
    "conservative advancement: touching and moving apart is no contact, overlapping is said") {
    Approach leaving;
    leaving.gap = [](double t) { return 3.0 * t; };
    leaving.closing_speed = [](double, double) { return 3.0; };
    CHECK(advance_to_contact(leaving, 0.0, 5.0, 1e-13).kind == ApproachOutcome::kNone);
    Approach inside;
    inside.gap = [](double t) { return -1.0 + t; };
    inside.closing_speed = [](double, double) { return 1.0; };
    CHECK(advance_to_contact(inside, 0.0, 5.0, 1e-13).kind == ApproachOutcome::kOverlapping);
}

TEST_CASE("a ball reflects off a keyed paddle with the relative velocity, and the paddle rests "
          "until its next key") {
    // The paddle: a cube 0.2 wide (scale 0.1), keyed from x = -3 to x = 1 over 2 s (2 m/s,
    // linear: Dynamics off), then to x = 3 at 4 s. The ball, at rest at x = 0.
    const double r = unit_radius() * 0.5, u = 2.0;
    Document doc;
    Settings s = doc.settings();
    s.gravity = 0.0;
    doc.set_settings(s);
    doc.add_model(model("paddle", "cube", false, false), placed({-3, 0, 0}, {0.1, 1, 1}));
    doc.add_model(model("ball", "sphere", true, false), placed({0, 0, 0}, glm::dvec3(0.5)));
    key(doc, 2000, 0, placed({1, 0, 0}, {0.1, 1, 1}));
    key(doc, 4000, 0, placed({3, 0, 0}, {0.1, 1, 1}));
    auto timeline = timeline_of(doc);
    timeline->bake(6.0);
    // The paddle's face (x = center + 0.1) reaches the ball's surface at x = -r.
    const double contact = (-r - 0.1 + 3.0) / u;
    const auto &events = timeline->events();
    REQUIRE(events.size() == 1);
    CHECK(events[0].t == Approx(contact).epsilon(1e-11));
    CHECK(std::abs(std::abs(events[0].normal.x) - 1.0) < 1e-12);
    CHECK(events[0].speed == Approx(u).epsilon(1e-9));
    // The ball leaves at 2u (v1 = v0 - 2 ((v0 - vB) . n) n with v0 = 0); the paddle rests
    // where it touched until its next key at 2 s, then follows its keys again.
    const Frame after = timeline->evaluate(contact + 0.5);
    CHECK(after.models[1].velocity.x == Approx(2.0 * u).epsilon(1e-9));
    CHECK(after.models[1].center.x == Approx(0.5 * 2.0 * u).epsilon(1e-9));
    const auto *rest = segment_at(*timeline, 0, 1.9);
    REQUIRE(rest);
    CHECK(rest->motion == ANI_MOTION_REST);
    CHECK(rest->t0 == Approx(contact).epsilon(1e-11));
    CHECK(rest->p0.x == Approx(-r - 0.1).epsilon(1e-11));
    const auto *resumed = segment_at(*timeline, 0, 3.0);
    REQUIRE(resumed);
    CHECK(resumed->motion == ANI_MOTION_KEYED);
    CHECK(resumed->t0 == 2.0);
    CHECK(timeline->evaluate(3.0).models[0].center.x == Approx(2.0).epsilon(1e-12));
    CHECK(timeline->evaluate(5.0).models[0].center.x ==
          Approx(3.0).epsilon(1e-12)); // held after its last key
}

TEST_CASE("a turning bar strikes a ball with the velocity of the point that touches it") {
    // A bar 4 long and 0.2 thick (cube scaled 2 x 0.1 x 1) turning about Z through its center,
    // from 0 to 90 degrees in 1 s (linear: w = pi/2 rad/s). A ball of radius r at rest at
    // distance d, polar angle a0: the bar's face touches it when d sin(a0 - phi) = r + 0.1, and
    // the point of contact, sqrt(d^2 - (r + 0.1)^2) along the bar, moves at w times that.
    const double r = unit_radius() * 0.2, d = 1.4, a0 = 60.0 * kPi / 180.0, w = 0.5 * kPi;
    Document doc;
    Settings s = doc.settings();
    s.gravity = 0.0;
    doc.set_settings(s);
    doc.add_model(model("bar", "cube", false, false), placed({0, 0, 0}, {2, 0.1, 1}));
    doc.add_model(model("ball", "sphere", true, false),
                  placed({d * std::cos(a0), d * std::sin(a0), 0}, glm::dvec3(0.2)));
    key(doc, 1000, 0, placed({0, 0, 0}, {2, 0.1, 1}, {0, 0, 90}));
    auto timeline = timeline_of(doc);
    timeline->bake(2.0);
    const double phi = a0 - std::asin((r + 0.1) / d), contact = phi / w;
    const auto &events = timeline->events();
    REQUIRE(events.size() >= 1);
    CHECK(events[0].t == Approx(contact).epsilon(1e-9));
    const glm::dvec3 n(-std::sin(phi), std::cos(phi), 0.0); // the bar's upper face, at angle phi
    const double lever = std::sqrt(d * d - (r + 0.1) * (r + 0.1));
    const glm::dvec3 v = timeline->evaluate(contact + 0.01).models[1].velocity;
    CHECK(glm::length(v - 2.0 * w * lever * n) < 1e-6 * w * lever);
}

TEST_CASE("a keyed ball released at a floor bounces, flies to its next key, and its keys take it "
          "back there") {
    // Dynamics on: kinematic keys from y = 5 at 0 s (initial velocity -2 m/s) to y = 0.25 at
    // 3 s, so y(t) = 5 - 2 t + a t^2 / 2 with a = 5/18; then y = 4 at 4 s. Gravity off. The
    // floor at y = 0 is met when y(t) = r, before 3 s.
    const double r = unit_radius() * 0.5, a = 5.0 / 18.0;
    Document doc;
    Settings s = doc.settings();
    s.gravity = 0.0;
    doc.set_settings(s);
    doc.add_model(model("floor", "plane", false, false), placed({0, 0, 0}, glm::dvec3(10.0)));
    Model ball = model("ball", "sphere", true, false);
    ball.initial_velocity = {0, -2, 0};
    doc.add_model(ball, placed({0, 5, 0}, glm::dvec3(0.5)));
    key(doc, 3000, 1, placed({0, 0.25, 0}, glm::dvec3(0.5)));
    key(doc, 4000, 1, placed({0, 4, 0}, glm::dvec3(0.5)));
    auto timeline = timeline_of(doc);
    timeline->bake(5.0);
    // 0.5 a t^2 - 2 t + (5 - r) = 0, the smaller root.
    const double contact = (2.0 - std::sqrt(4.0 - 2.0 * a * (5.0 - r))) / a;
    const double v_in = -2.0 + a * contact;
    REQUIRE(timeline->events().size() >= 1);
    CHECK(timeline->events()[0].t == Approx(contact).epsilon(1e-10));
    CHECK(timeline->events()[0].speed == Approx(-v_in).epsilon(1e-8));
    const auto *flight = segment_at(*timeline, 1, 0.5 * (contact + 3.0));
    REQUIRE(flight);
    CHECK(flight->motion == ANI_MOTION_FREE);
    CHECK(flight->v0.y == Approx(-v_in).epsilon(1e-8));
    // At 3 s its keys take it back (into the floor, which is then ignored until they are apart),
    // and after its last key at 4 s it is free.
    CHECK(timeline->evaluate(3.0).models[1].center.y == Approx(0.25).epsilon(1e-12));
    CHECK(timeline->evaluate(3.5).motion[1] == ANI_MOTION_KEYED);
    CHECK(timeline->evaluate(4.5).motion[1] == ANI_MOTION_FREE);
}

TEST_CASE("a bake resumed after a release continues exactly as one bake") {
    const double r = unit_radius() * 0.5;
    (void)r;
    Document doc;
    Settings s = doc.settings();
    s.gravity = 0.0;
    doc.set_settings(s);
    doc.add_model(model("paddle", "cube", false, false), placed({-3, 0, 0}, {0.1, 1, 1}));
    doc.add_model(model("ball", "sphere", true, false), placed({0, 0, 0}, glm::dvec3(0.5)));
    key(doc, 2000, 0, placed({1, 0, 0}, {0.1, 1, 1}));
    key(doc, 4000, 0, placed({3, 0, 0}, {0.1, 1, 1}));
    auto whole = timeline_of(doc), parts = timeline_of(doc);
    whole->bake(6.0);
    parts->bake(1.7); // after the contact, before the paddle's next key
    parts->bake(6.0);
    for (double t : {1.0, 1.8, 2.5, 3.9, 5.5})
        for (int m = 0; m < 2; ++m) {
            CAPTURE(t, m);
            CHECK(glm::length(whole->evaluate(t).models[static_cast<size_t>(m)].center -
                              parts->evaluate(t).models[static_cast<size_t>(m)].center) < 1e-12);
            CHECK(whole->evaluate(t).motion[static_cast<size_t>(m)] ==
                  parts->evaluate(t).motion[static_cast<size_t>(m)]);
        }
}

TEST_CASE("a ball placed on a floor under gravity rests there, and one struck by a keyed paddle "
          "slides on it") {
    // Meshes are single precision, so a ball of scale 0.5 placed at y = 0.5 is in the floor by
    // ~2e-8: touching, not overlapping. Resting on the floor holds it up.
    const double r = unit_radius() * 0.5, u = 1.5;
    Document doc;
    doc.add_model(model("floor", "plane", false, false), placed({0, 0, 0}, glm::dvec3(20.0)));
    doc.add_model(model("ball", "sphere", true, true), placed({0, 0.5, 0}, glm::dvec3(0.5)));
    // A paddle (0.2 wide) keyed at 1.5 m/s along x, from x = -4 at 0 s to x = 2 at 4 s.
    doc.add_model(model("paddle", "cube", false, false), placed({-4, 0.5, 0}, {0.1, 0.4, 1}));
    key(doc, 4000, 2, placed({2, 0.5, 0}, {0.1, 0.4, 1}));
    auto timeline = timeline_of(doc);
    timeline->bake(10.0);
    const auto &events = timeline->events();
    REQUIRE(events.size() == 1); // the paddle, nothing from the floor
    const double contact = (-r - 0.1 + 4.0) / u;
    CHECK(events[0].t == Approx(contact).epsilon(1e-10));
    for (double t : {0.5, 1.0, contact - 1e-3}) {
        const ModelPose ball = timeline->evaluate(t).models[1];
        CHECK(ball.center == glm::dvec3(0.0, ball.center.y, 0.0));
        CHECK(std::abs(ball.center.y - 0.5) < 1e-7);
        CHECK(ball.velocity == glm::dvec3(0.0));
    }
    for (double t : {contact + 0.1, 4.0, 6.0}) { // it reaches the rim at x = 20 after 9 s
        CAPTURE(t);
        const ModelPose ball = timeline->evaluate(t).models[1];
        CHECK(ball.velocity.x == Approx(2.0 * u).epsilon(1e-9));
        CHECK(ball.velocity.y == 0.0);
        CHECK(std::abs(ball.center.y - 0.5) < 1e-7);
    }
}

TEST_CASE("a sphere sliding across a finely tessellated floor never bumps on its inner edges, and "
          "leaves it at its rim") {
    // physics.md scene 6: floor_fine (8192 triangles) scaled 10 spans x in [-10, 10]. The ball
    // slides at 1 m/s along x under gravity; its point of contact passes the rim at x = 10.
    Document doc;
    Settings s = doc.settings();
    s.max_time_ms = 12000;
    doc.set_settings(s);
    doc.add_model(model("floor", "floor_fine", false, false), placed({0, 0, 0}, {10, 1, 10}));
    Model ball = model("ball", "sphere", true, true);
    ball.initial_velocity = {1.0, 0.0, 0.3};
    doc.add_model(ball, placed({0.123, 0.5, 0.456}, glm::dvec3(0.5)));
    auto timeline = timeline_of(doc);
    timeline->bake(12.0);
    const double leave = 10.0 - 0.123;
    for (double t = 0.0; t < leave; t += 0.37) {
        CAPTURE(t);
        const ModelPose p = timeline->evaluate(t).models[1];
        CHECK(p.velocity.y == 0.0);
        CHECK(std::abs(p.center.y - 0.5) < 1e-7);
        CHECK(p.center.x == Approx(0.123 + t).epsilon(1e-12));
    }
    CHECK(timeline->events().empty());
    // Then it falls: half a second after the rim, it is G t^2 / 2 lower.
    const ModelPose later = timeline->evaluate(leave + 0.5).models[1];
    CHECK(later.velocity.y == Approx(-9.81 * 0.5).epsilon(1e-9));
}
