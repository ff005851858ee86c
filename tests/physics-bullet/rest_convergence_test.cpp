// Bullet on the contacts that last (issue 19): as its step shrinks, it converges towards the closed
// forms physics.custom meets, on the shipped scenes ramp_boxes.lua (a box sliding down a ramp and
// one stuck on another), box_stack.lua (a ball dropped on a stack of three boxes) and
// stack_knock.lua (the same stack, elastic and frictionless, knocked at its edge). Each at
// 1/250, 1/1000 and 1/4000 s, its solver iterated to convergence (1000 iterations: with the
// default 10 the stack's blow leaks into its boxes and the sliding box's friction is short of its
// limit, at every step); docs/physics-bullet.md, "Contacts that last".
#include "bullet_support.hpp"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>
#include <filesystem>
#include <functional>
#include <tuple>

using namespace animator;
using namespace animator::bullet_test;

namespace {

const double kRestSteps[3] = {1.0 / 250.0, 1.0 / 1000.0, 1.0 / 4000.0};

Document shipped(const std::string &scene) {
    return open_document(env().plugins,
                         std::filesystem::path(ANIMATOR_SOURCE_DIR) / "assets/scenes" / scene)
        .document;
}

glm::dvec3 center(const Timeline &t, int m, double at) {
    return t.evaluate(at).models[static_cast<size_t>(m)].center;
}

std::unique_ptr<Timeline> bullet_bake(const Document &doc, double dt, double until) {
    auto t = timeline_of(with_param(with_param(doc, "step", dt), "solver_iterations", 1000.0));
    t->bake(until);
    return t;
}

} // namespace

TEST_CASE("Bullet converges on the box sliding down a ramp and on the one stuck to its ramp") {
    const Document doc = shipped("ramp_boxes.lua");
    const int sliding = model_named(doc, "sliding"), sticking = model_named(doc, "sticking");
    const double theta = glm::radians(20.0), a = G * (std::sin(theta) - 0.2 * std::cos(theta));
    const glm::dvec3 down(-std::cos(theta), -std::sin(theta), 0.0);
    const glm::dvec3 c0 = start_of(doc, sliding), s0 = start_of(doc, sticking);
    const double until = 2.5;
    double slid[3], crept[3];
    for (int k = 0; k < 3; ++k) {
        const auto t = bullet_bake(doc, kRestSteps[k], until);
        slid[k] = worst(until, [&](double s) {
            return glm::length(center(*t, sliding, s) - (c0 + 0.5 * a * s * s * down));
        });
        crept[k] =
            worst(until, [&](double s) { return glm::length(center(*t, sticking, s) - s0); });
    }
    // Measured: slid 9.1e-4, 1.5e-4, 2.1e-5 m; crept 2.8e-4, 1.7e-5, 7.1e-7 m. Before the box
    // shapes, on a plane of two triangles: 0.16 m at every step.
    CAPTURE(slid[0], slid[1], slid[2], crept[0], crept[1], crept[2]);
    for (int k = 1; k < 3; ++k) {
        CHECK(slid[k] < slid[k - 1] / 3.0);
        CHECK(crept[k] < crept[k - 1] / 3.0);
    }
    CHECK(slid[2] < 1e-4);
    CHECK(crept[2] < 1e-5);
}

TEST_CASE("Bullet converges on the stack a ball is dropped on: the boxes stay, the ball rests on "
          "the top one") {
    const Document doc = shipped("box_stack.lua");
    const int ball = model_named(doc, "ball");
    const double r = 0.3 * unit_sphere_radius(), until = 2.5;
    double moved[3], resting[3];
    for (int k = 0; k < 3; ++k) {
        const auto t = bullet_bake(doc, kRestSteps[k], until);
        moved[k] = 0.0;
        for (const char *name : {"bottom", "middle", "top"}) {
            const int m = model_named(doc, name);
            moved[k] = std::max(moved[k], worst(until, [&](double s) {
                                    return glm::length(center(*t, m, s) - start_of(doc, m));
                                }));
        }
        // At rest on the top face (y = 3) from the bounces' accumulation time, 1.766 s.
        resting[k] = worst(until, [&](double s) {
            return s < 2.0 ? 0.0 : std::abs(center(*t, ball, s).y - (3.0 + r));
        });
    }
    // Measured: the boxes 2.3e-3, 1.4e-4, 3.2e-6 m, the ball 2.1e-4, 1.9e-5, 1.0e-6 m; before
    // the box shapes and the contacts held, the boxes 0.16, 0.097, 0.075 m (to 3 s).
    CAPTURE(moved[0], moved[1], moved[2], resting[0], resting[1], resting[2]);
    for (int k = 1; k < 3; ++k) {
        CHECK(moved[k] < moved[k - 1] / 3.0);
        CHECK(resting[k] < resting[k - 1] / 3.0);
    }
    CHECK(moved[2] < 1e-4);
}

TEST_CASE("Bullet converges on the energy of the elastic stack a ball knocks at its edge") {
    const Document doc = shipped("stack_knock.lua");
    // Mass and moment of inertia about every axis through the centre: the ball 2 kg of radius
    // 0.3 m (2/5 m r^2), the boxes 1 kg of side 1 m (m / 6).
    const std::vector<std::tuple<std::string, double, double>> bodies = {
        {"ball", 2.0, 0.4 * 2.0 * 0.09},
        {"top", 1.0, 1.0 / 6.0},
        {"middle", 1.0, 1.0 / 6.0},
        {"bottom", 1.0, 1.0 / 6.0}};
    const double until = 2.0;
    double drift[3];
    for (int k = 0; k < 3; ++k) {
        const auto t = bullet_bake(doc, kRestSteps[k], until);
        const double e0 = energy(*t, doc, 0.0, bodies);
        drift[k] =
            worst(until, [&](double s) { return std::abs(energy(*t, doc, s, bodies) - e0) / e0; });
    }
    // Measured: 6.7e-3 at 1/250 s, 1.6e-4 at 1/1000, 2.2e-5 at 1/4000 (0.126 at 1/60); with the
    // default 10 iterations 6 to 8% at every step.
    CAPTURE(drift[0], drift[1], drift[2]);
    for (int k = 1; k < 3; ++k) CHECK(drift[k] < drift[k - 1] / 3.0);
    CHECK(drift[2] < 1e-4);
}
