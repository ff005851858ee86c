// physics.bullet with the per-model rigid-body settings of SDK 1.3 (restitution, friction,
// Rotates, angular velocity at t = 0) against closed forms, at the steps 1/60, 1/240 and
// 1/1000 s: each error must shrink with the step (docs/physics-bullet.md, "Per-model settings").
#include "box_drop.hpp"
#include "io/document_io.hpp"
#include "bullet_support.hpp"
#include "material.hpp"
#include "track.hpp"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <animator/plugin_cpp.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <vector>

using namespace animator;
using namespace animator::bullet_test;

namespace {

// The orientation the rotation segments of `model` give at t (the segment covering t, turned by
// its constant angular velocity), and whether one covers it.
bool orientation_at(const Timeline &t, int model, double time, glm::dquat *q) {
    for (const ani_rotation_segment &s : t.rotations(model)) {
        if (time < s.t0 || time > s.t1) continue;
        const glm::dquat q0(s.q0.w, s.q0.x, s.q0.y, s.q0.z);
        *q = physics_bullet::turned(q0, glm::dvec3(s.w.x, s.w.y, s.w.z), time - s.t0);
        return true;
    }
    return false;
}

double quat_distance(const glm::dquat &a, const glm::dquat &b) {
    return std::min(glm::length(glm::dvec4(a.x - b.x, a.y - b.y, a.z - b.z, a.w - b.w)),
                    glm::length(glm::dvec4(a.x + b.x, a.y + b.y, a.z + b.z, a.w + b.w)));
}

// A ball (r = 0.5) dropped from about 3 m on a floor, restitution e_ball on the ball and e_floor on
// the floor. The apexes of its first three bounces, centre height above r, in time order.
std::vector<double> bounce_apexes(double dt, double e_ball, double e_floor, double phase,
                                  double *h_minus_r) {
    // About 3 m, placed so the ball reaches the floor `phase` of a step later.
    const double r = 0.5 * unit_sphere_radius();
    const double first = std::sqrt(2.0 * (3.0 - r) / G) + phase * dt;
    const double h = r + 0.5 * G * first * first;
    *h_minus_r = h - r;
    Document doc;
    Model floor = model("floor", "plane", false, false);
    floor.restitution = e_floor;
    doc.add_model(floor, placed({0, 0, 0}, glm::dvec3(10.0)));
    Model ball = model("ball", "sphere", true, true);
    ball.restitution = e_ball;
    doc.add_model(ball, placed({0.3, h, 0.2}, glm::dvec3(0.5)));
    auto t = timeline_of(with_param(doc, "step", dt));
    // Falling time sqrt(2 (h - r) / G) = 0.74 s, then bounces of 2 e^k of it: the third apex is
    // at 3.25 s.
    t->bake(4.0);
    std::vector<double> apexes;
    for (const ani_motion_segment &s : t->segments(1)) {
        if (s.motion != ANI_MOTION_FREE || s.a.y == 0.0) continue;
        const double at = -s.v0.y / s.a.y;
        if (at <= 1e-9 || at > s.t1 - s.t0) continue;
        apexes.push_back(s.p0.y + s.v0.y * at + 0.5 * s.a.y * at * at - r);
    }
    return apexes;
}

// Two spheres (r = 0.5, masses 1 and 3, at 2 and -1 m/s) head-on without gravity, restitution
// e_a and e_b on each: their velocities (along x) well after the contact.
glm::dvec2 head_on(double dt, double e_a, double e_b, double e_param = 1.0) {
    Document doc = no_gravity();
    Model a = model("a", "sphere", true, false), b = model("b", "sphere", true, false);
    a.mass = 1.0;
    b.mass = 3.0;
    a.initial_velocity = {2, 0, 0};
    b.initial_velocity = {-1, 0, 0};
    a.restitution = e_a;
    b.restitution = e_b;
    doc.add_model(a, placed({-1.0, 0, 0}, glm::dvec3(0.5)));
    doc.add_model(b, placed({1.0, 0, 0}, glm::dvec3(0.5)));
    auto t = timeline_of(with_param(with_param(doc, "step", dt), "restitution", e_param));
    t->bake(1.5); // contact at (2 - 2 r) / 3 = 0.33 s
    const Frame f = t->evaluate(1.5);
    CHECK(t->events().size() == 1);
    return {f.models[0].velocity.x, f.models[1].velocity.x};
}

// A ball (r = 0.5) sliding at v0 = 2 m/s along x on a floor, friction mu_ball on the ball and
// mu_floor on the floor, Rotates on. Its velocity along x and angular velocity about z at the
// times `at`.
struct Rolling {
    std::vector<double> v, wz;
};
Rolling sliding_ball(double dt, double mu_ball, double mu_floor, const std::vector<double> &at) {
    const double r = 0.5 * unit_sphere_radius();
    Document doc;
    Model floor = model("floor", "plane", false, false);
    floor.friction = mu_floor;
    doc.add_model(floor, placed({0, 0, 0}, glm::dvec3(20.0)));
    Model ball = model("ball", "sphere", true, true);
    ball.initial_velocity = {2, 0, 0};
    ball.friction = mu_ball;
    ball.rotates = true;
    doc.add_model(ball, placed({-5, r, 0}, glm::dvec3(0.5)));
    auto t = timeline_of(with_param(doc, "step", dt));
    t->bake(at.back());
    Rolling out;
    for (double time : at) {
        out.v.push_back(t->evaluate(time).models[1].velocity.x);
        double wz = 0.0;
        for (const ani_rotation_segment &s : t->rotations(1))
            if (time >= s.t0 && time <= s.t1) wz = s.w.z;
        out.wz.push_back(wz);
    }
    return out;
}

} // namespace

TEST_CASE("per-model restitution: a ball with e = 0.8 on an elastic floor bounces to e^(2k) of "
          "its drop height (the lower restitution), closer as the step shrinks") {
    const double e = 0.8;
    double error[3];
    for (int k = 0; k < 3; ++k) {
        error[k] = 0.0;
        // Where Bullet's steps fall against the contact matters: four phases, the worst counts.
        for (double phase : {0.0, 0.29, 0.58, 0.87}) {
            double h_minus_r = 0.0;
            const std::vector<double> apexes = bounce_apexes(kSteps[k], e, 1.0, phase, &h_minus_r);
            CAPTURE(kSteps[k], phase);
            REQUIRE(apexes.size() >= 3);
            // Each bounce keeps e of the speed, so e^2 of the height: apex k = e^(2k) (h - r).
            for (int j = 0; j < 3; ++j)
                error[k] = std::max(error[k], std::abs(apexes[static_cast<size_t>(j)] -
                                                       std::pow(e, 2.0 * (j + 1)) * h_minus_r) /
                                                  h_minus_r);
        }
    }
    // Bullet's first-order step: a bounce is found up to a step late and its restitution is
    // applied to the speed the ball had then (measured 0.22, 0.26 and 0.26 dt, relative).
    const double bounds[3] = {0.4 * kSteps[0], 0.4 * kSteps[1], 0.4 * kSteps[2]};
    check_converges("apexes e^(2k) (h - r)", error, bounds);
}

TEST_CASE("per-model restitution: two spheres of unequal mass, e = 0.5, head-on leave with "
          "Newton's law of restitution") {
    const double e = 0.5, m1 = 1.0, m2 = 3.0, u1 = 2.0, u2 = -1.0;
    // Momentum kept and the relative velocity reversed and scaled by e:
    // v1' = ((m1 - e m2) u1 + (1 + e) m2 u2) / (m1 + m2), v2' likewise.
    const double v1 = ((m1 - e * m2) * u1 + (1.0 + e) * m2 * u2) / (m1 + m2);
    const double v2 = ((m2 - e * m1) * u2 + (1.0 + e) * m1 * u1) / (m1 + m2);
    double error[3];
    for (int k = 0; k < 3; ++k) {
        const glm::dvec2 v = head_on(kSteps[k], e, 1.0);
        error[k] = std::max(std::abs(v.x - v1), std::abs(v.y - v2)) / (u1 - u2);
    }
    // Head-on, Bullet's exchange is exact but for rounding (as at e = 1).
    const double bounds[3] = {1e-12, 1e-12, 1e-12};
    check_converges("velocities after", error, bounds, 1e-12);
}

TEST_CASE("the combination rule: a contact takes the lower restitution and the higher friction, "
          "whichever body carries it") {
    for (double dt : {kSteps[0], kSteps[1]}) {
        CAPTURE(dt);
        // Restitution on either sphere, or on both (the product, Bullet's default, would be
        // 0.25 there): the same exchange.
        const glm::dvec2 on_a = head_on(dt, 0.5, 1.0), on_b = head_on(dt, 1.0, 0.5),
                         on_both = head_on(dt, 0.5, 0.5);
        CHECK(on_a == on_b);
        CHECK(on_a == on_both);
        // Lower of 0.5 and 0.9: 0.5.
        CHECK(head_on(dt, 0.9, 0.5) == on_a);
        // An earlier document's parameter bounds every contact: the same as on a model.
        CHECK(head_on(dt, 1.0, 1.0, 0.5) == on_a);
        CHECK(head_on(dt, 0.9, 1.0, 0.5) == on_a);
        // Friction on the ball or on the floor, or the higher of two: the same rolling.
        const std::vector<double> at = {0.1, 0.2, 0.4, 1.0};
        const Rolling ball = sliding_ball(dt, 0.3, 0.0, at), floor = sliding_ball(dt, 0.0, 0.3, at),
                      both = sliding_ball(dt, 0.1, 0.3, at);
        CHECK(ball.v == floor.v);
        CHECK(ball.v == both.v);
        CHECK(ball.wz == floor.wz);
        // And not the same as without it (the test can tell them apart).
        CHECK(sliding_ball(dt, 0.0, 0.0, at).v != ball.v);
    }
}

TEST_CASE("per-model friction with Rotates: a sliding ball skids, then rolls at 5/7 v0 from "
          "t* = 2 v0 / (7 mu g)") {
    const double mu = 0.3, v0 = 2.0, r = 0.5 * unit_sphere_radius();
    // Sliding: friction mu m g slows it, v = v0 - mu g t, and its torque mu m g r spins it up
    // against the inertia 2/5 m r^2, w r = 5/2 mu g t. They meet at v0 - mu g t = 5/2 mu g t:
    // t* = 2 v0 / (7 mu g), v = 5/7 v0; then it rolls without friction.
    const double t_star = 2.0 * v0 / (7.0 * mu * G);
    std::vector<double> at;
    for (int j = 1; j <= 60; ++j) at.push_back(2.0 * t_star * j / 60.0);
    double error[3], spin[3];
    for (int k = 0; k < 3; ++k) {
        const Rolling ball = sliding_ball(kSteps[k], mu, 0.0, at);
        error[k] = spin[k] = 0.0;
        for (size_t j = 0; j < at.size(); ++j) {
            const double exact = at[j] < t_star ? v0 - mu * G * at[j] : 5.0 / 7.0 * v0;
            error[k] = std::max(error[k], std::abs(ball.v[j] - exact) / v0);
            // Rolling along +x turns about -z: w = -v / r once it rolls.
            if (at[j] > t_star + 2.0 * kSteps[k])
                spin[k] = std::max(spin[k], std::abs(ball.wz[j] * r + exact) / v0);
        }
    }
    // First order. A ball resting on a floor at e = 1 hops by about G dt^2 (docs/physics-bullet.md,
    // "On a support") and friction acts only in the steps it touches: the skid loses its speed
    // in bursts of a few steps' worth, mu G n dt, with n up to about 5 (measured 9.2, 9.1 and
    // 7.8 dt of v0 at the three steps, at the samples just before a burst).
    const double bounds[3] = {12.0 * kSteps[0], 12.0 * kSteps[1], 12.0 * kSteps[2]};
    check_converges("velocity against v0 - mu g t, then 5/7 v0", error, bounds);
    check_converges("rolling: w r = -v", spin, bounds, 1e-9);
}

TEST_CASE("a sphere spinning in free flight with Rotates turns at its angular velocity at t = 0") {
    const glm::dvec3 w(1.0, -2.0, 3.0); // rad/s, world axes
    double error[3];
    for (int k = 0; k < 3; ++k) {
        Document doc = no_gravity();
        Model ball = model("ball", "sphere", true, false);
        ball.rotates = true;
        ball.angular_velocity = w;
        ball.initial_velocity = {0.5, 0, 0};
        doc.add_model(ball, placed({0, 0, 0}, glm::dvec3(0.5)));
        Model still = model("still", "sphere", true, false); // the seed's: angular velocity unused
        still.angular_velocity = w;
        doc.add_model(still, placed({0, 5, 0}, glm::dvec3(0.5)));
        auto t = timeline_of(with_param(doc, "step", kSteps[k]));
        t->bake(10.0);
        CHECK(t->rotations(1).empty());
        CHECK(t->evaluate(10.0).models[1].angles == glm::dvec3(0.0));
        // Torque-free with three equal moments: constant w, q(t) = exp(t w / 2) q(0).
        error[k] = 0.0;
        for (int j = 0; j <= 100; ++j) {
            const double time = 0.1 * j;
            glm::dquat q;
            REQUIRE(orientation_at(*t, 0, time, &q));
            const glm::dquat exact =
                glm::angleAxis(glm::length(w) * time, glm::normalize(w)) * glm::dquat(1, 0, 0, 0);
            error[k] = std::max(error[k], quat_distance(q, exact));
        }
        CHECK(t->rotations(0).size() <= 2); // one segment, not one per step
    }
    // Without a contact Bullet turns by exactly w h at each step and the track reports that as
    // one segment: exact but for rounding over 37 turns.
    const double bounds[3] = {1e-9, 1e-9, 1e-9};
    check_converges("orientation", error, bounds, 1e-9);
}

TEST_CASE("a box spinning in free flight with Rotates turns as Euler's equations say, its "
          "angular velocity changing, closer as the step shrinks") {
    // Three unequal moments: w changes as it turns, so Bullet's gyroscopic term must be on
    // (without it Bullet keeps w, as for a spherical top). The truth: Euler's equations
    // integrated independently (tests/box_drop.hpp).
    const glm::dvec3 w(1.0, 3.0, 0.5), half(0.2, 0.5, 0.8);
    const box_drop::Box reference(half, 1.0);
    double error[3];
    for (int k = 0; k < 3; ++k) {
        Document doc = no_gravity();
        Model box = model("box", "cube", true, false);
        box.rotates = true;
        box.angular_velocity = w;
        doc.add_model(box, placed({0, 0, 0}, half));
        auto t = timeline_of(with_param(with_param(doc, "step", kSteps[k]), "margin", 1e-4));
        t->bake(3.0);
        error[k] = 0.0;
        for (int j = 1; j <= 30; ++j) {
            const double time = 0.1 * j;
            const RotationSegment *r = t->rotation_at(0, time);
            REQUIRE(r);
            const box_drop::Rotation exact = reference.at(glm::dquat(1, 0, 0, 0), w, time);
            error[k] = std::max(error[k], quat_distance(orientation_at(*r, time), exact.q));
        }
        CHECK(t->rotations(0).size() >= static_cast<size_t>(3.0 / kSteps[k])); // one per step
    }
    // Bullet's implicit gyroscopic step is first order: measured 0.086, 0.022 and 0.0053 rad
    // over 3 s (its moments from the hull's box, 1e-4 larger with this margin); without the
    // term the error is O(1) (w does not change).
    const double bounds[3] = {0.15, 0.04, 0.01};
    check_converges("orientation", error, bounds);
}

TEST_CASE("a cone spinning in free flight with Rotates turns about its centre of mass, which "
          "stays where it was, as in physics.custom") {
    // The cone mesh spans y in [-1, 1]: a pyramid's centre of mass is a quarter of its height
    // above its base, y = -1/2, scaled 0.5: -0.25 below its origin.
    const glm::dvec3 w(1.0, 3.0, 0.5), pivot(0.0, -0.25, 0.0);
    for (const char *backend : {"physics.bullet", "physics.custom"}) {
        Document doc = no_gravity();
        Model cone = model("cone", "cone", true, false);
        cone.rotates = true;
        cone.angular_velocity = w;
        doc.add_model(cone, placed({0, 0, 0}, glm::dvec3(0.5)));
        auto t = timeline_of(doc, backend);
        t->bake(2.0);
        double moved = 0.0, swung = 0.0;
        for (int j = 0; j <= 20; ++j) {
            const double time = 0.1 * j;
            const RotationSegment *r = t->rotation_at(0, time);
            REQUIRE(r);
            CHECK(glm::length(r->pivot - pivot) < 1e-12);
            const Frame f = t->evaluate(time);
            const glm::dvec3 centre = f.models[0].center + orientation_at(*r, time) * pivot;
            moved = std::max(moved, glm::length(centre - pivot));
            swung = std::max(swung, glm::length(f.models[0].center));
        }
        CAPTURE(backend, moved, swung);
        CHECK(moved < 1e-9); // thrown with no velocity at its centre of mass
        CHECK(swung > 0.1);  // while its origin swings around it
    }
}

TEST_CASE("the tumbling cone's first impact in Bullet is physics.custom's, but for its margin") {
    Document doc = open_document(env().plugins, std::filesystem::path(ANIMATOR_SOURCE_DIR) /
                                                    "assets/scenes/tumbling_cone.lua")
                       .document;
    auto exact = timeline_of(doc, "physics.custom");
    exact->bake(0.6);
    REQUIRE_FALSE(exact->events().empty());
    auto bullet = timeline_of(with_param(with_param(doc, "step", 2e-4), "margin", 1e-4));
    bullet->bake(0.6);
    REQUIRE_FALSE(bullet->events().empty());
    // Its corner meets the floor at about 5 m/s: a margin of 1e-4 m makes it about 2e-5 s early
    // (measured 2.3e-5 s; turned about its origin instead, it landed 0.031 s late).
    const double early = exact->events()[0].t - bullet->events()[0].t;
    CAPTURE(early);
    CHECK(early > 0.0);
    CHECK(early < 5e-5);
}

TEST_CASE("a model's rigid-body settings are checked, the model named") {
    ani_model_desc d{};
    d.struct_size = sizeof(ani_model_desc);
    d.restitution = 0.5;
    d.friction = 0.2;
    d.rotates = 1;
    d.angular_velocity = {0, 0, 1};
    const physics_bullet::Material m = physics_bullet::material_of(d, "ball", 1.0, 0.0, false);
    CHECK(m.restitution == 0.5);
    CHECK(m.friction == 0.2);
    CHECK(m.rotates);
    CHECK(m.angular_velocity == glm::dvec3(0, 0, 1));
    // The document-wide parameters of earlier documents still bound every contact.
    CHECK(physics_bullet::material_of(d, "ball", 0.3, 0.7, false).restitution == 0.3);
    CHECK(physics_bullet::material_of(d, "ball", 0.3, 0.7, false).friction == 0.7);
    // A description before SDK 1.3: the seed's defaults.
    ani_model_desc old = d;
    old.struct_size = static_cast<uint32_t>(offsetof(ani_model_desc, restitution));
    const physics_bullet::Material seed = physics_bullet::material_of(old, "old", 1.0, 0.0, false);
    CHECK(seed.restitution == 1.0);
    CHECK(seed.friction == 0.0);
    CHECK(!seed.rotates);
    CHECK(seed.angular_velocity == glm::dvec3(0.0));
    ani_model_desc bad = d;
    bad.restitution = 1.5;
    CHECK_THROWS_WITH(physics_bullet::material_of(bad, "ball", 1.0, 0.0, false),
                      Catch::Contains("'ball'") && Catch::Contains("restitution"));
    bad = d;
    bad.friction = std::nan("");
    CHECK_THROWS_WITH(physics_bullet::material_of(bad, "ball", 1.0, 0.0, false),
                      Catch::Contains("'ball'") && Catch::Contains("friction"));
    bad = d;
    bad.angular_velocity.y = INFINITY;
    CHECK_THROWS_WITH(physics_bullet::material_of(bad, "ball", 1.0, 0.0, false),
                      Catch::Contains("'ball'") && Catch::Contains("angular velocity"));
    CHECK(physics_bullet::combined_restitution(0.2, 0.9) == 0.2);
    CHECK(physics_bullet::combined_friction(0.2, 0.9) == 0.9);
}

TEST_CASE("a bake that goes on from a later time starts a turning model from the host's "
          "orientation and angular velocity") {
    // A sphere spinning without gravity, and a cube whose keys an edit changes after what is
    // baked: the next slice builds a new world from 3 s (sliced_bake_test), where the sphere has
    // no keys to say how it is turned, only the host's rotation segments (start_turning).
    const glm::dvec3 w(0.0, 2.0, -1.0);
    Document doc = no_gravity();
    Model ball = model("ball", "sphere", true, false);
    ball.rotates = true;
    ball.angular_velocity = w;
    doc.add_model(ball, placed({0, 0, 0}, glm::dvec3(0.5)));
    doc.add_model(model("cube", "cube", false, false), placed({5, 1, 0}));
    key(doc, 2000, 1, placed({5, 2, 0}));
    key(doc, 5000, 1, placed({5, 3, 0}));
    auto t = timeline_of(doc);
    t->bake(3.0);
    const auto worlds = [&] { return t->stats().backend_counts.at("worlds built"); };
    REQUIRE(worlds() == 1.0);
    Document edited = doc;
    key(edited, 5000, 1, placed({5, 4, 0}));
    t->edit(edited);
    REQUIRE(t->baked_until() == 2.0); // the edited span starts at the key at 2 s
    t->bake(6.0);
    REQUIRE(worlds() == 2.0);
    // Constant w throughout: q(t) = exp(t w / 2), across the two worlds.
    for (double time : {1.0, 1.9, 2.0, 2.1, 4.5, 6.0}) {
        CAPTURE(time);
        glm::dquat q;
        REQUIRE(orientation_at(*t, 0, time, &q));
        const glm::dquat exact = glm::angleAxis(glm::length(w) * time, glm::normalize(w));
        CHECK(quat_distance(q, exact) < 1e-12);
    }
}
