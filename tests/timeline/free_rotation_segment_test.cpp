// The host's reading of ABI 1.4 free-rotation segments, apart from any real backend: a test
// backend (fake/free_rotation_backend.cpp) reports a model at rest at the origin turning at
// w = (0, 0, 2) rad/s about its pivot (0, 1, 0), and the host must place the model's origin at
// c - R(t) pivot, moving at -w x R(t) pivot, or refuse a segment it cannot evaluate; and of ABI
// 1.6 hinge segments, the same model swinging about its pivot as a pendulum.
#include "io/environment.hpp"
#include "timeline/timeline.hpp"
#include "timeline/world_turning.hpp"

#include "fake/fake_env.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <cmath>

using namespace animator;
using fake_backends::env;

namespace {

Document one_model(bool bad, bool hinge = false) {
    Document doc;
    Model top;
    top.name = "top";
    top.mesh = "cube";
    top.dynamics = true;
    doc.add_model(top, ModelState{});
    Settings s = doc.settings();
    s.params["physics.test_free_rotation"]["bad"] = {bad ? 1.0 : 0.0, 0.0, 0.0, 0.0};
    s.params["physics.test_free_rotation"]["hinge"] = {hinge ? 1.0 : 0.0, 0.0, 0.0, 0.0};
    doc.set_settings(s);
    return doc;
}

} // namespace

TEST_CASE("a free-rotation segment about a pivot places the model's origin around the pivot") {
    Timeline timeline(one_model(false), env().plugins, "physics.test_free_rotation");
    timeline.bake(2.0);
    REQUIRE(timeline.rotations(0).size() == 1);
    // By hand: after t the model has turned 2 t about z, so its pivot (0, 1, 0) points to
    // (-sin 2t, cos 2t, 0) from its origin, and the origin, the pivot being at 0, is the
    // opposite; it moves at -w x R pivot = 2 (cos 2t, sin 2t, 0).
    for (double t : {0.0, 0.3, std::acos(-1.0) / 4.0, 1.7}) {
        const Frame f = timeline.evaluate(t);
        CAPTURE(t);
        const glm::dvec3 origin(std::sin(2 * t), -std::cos(2 * t), 0.0),
            velocity(2 * std::cos(2 * t), 2 * std::sin(2 * t), 0.0);
        CHECK(glm::length(f.models[0].center - origin) < 1e-12);
        CHECK(glm::length(f.models[0].velocity - velocity) < 1e-12);
        const Turning turning = world_turnings(timeline, f, t)[0];
        CHECK(glm::length(turning.w - glm::dvec3(0, 0, 2)) < 1e-12);
        CHECK(glm::length(turning.q * glm::dvec3(1, 0, 0) -
                          glm::dvec3(std::cos(2 * t), std::sin(2 * t), 0)) < 1e-12);
    }
}

TEST_CASE("a free-rotation segment the host cannot evaluate fails the bake, naming the model") {
    Timeline timeline(one_model(true), env().plugins, "physics.test_free_rotation");
    try {
        timeline.bake(1.0);
        FAIL("the bake took moments that are not ascending");
    } catch (const PluginError &e) {
        CHECK_THAT(e.what(), Catch::Contains("model 0's free-rotation segment at t = 0") &&
                                 Catch::Contains("not in ascending order"));
    }
    CHECK(timeline.rotations(0).empty());
}

TEST_CASE("a hinge segment swings the model about its pivot as the pendulum equation says") {
    Timeline timeline(one_model(false, true), env().plugins, "physics.test_free_rotation");
    timeline.bake(3.0);
    REQUIRE(timeline.rotations(0).size() == 1);
    // psi'' = -9 sin psi from 0.5 at rest, by Runge-Kutta in steps of 1e-5 s; the model turns by
    // d = psi - 0.5 about z, so its pivot (0, 1, 0) points to (-sin d, cos d, 0) from its origin,
    // which is the opposite (the pivot is at 0), moving at -psi' z x R pivot.
    double psi = 0.5, rate = 0.0, t = 0.0;
    const double h = 1e-5;
    for (double at : {0.2, 0.9, 2.5}) {
        while (t < at - 0.5 * h) {
            const double k1p = rate, k1r = -9.0 * std::sin(psi);
            const double k2p = rate + 0.5 * h * k1r, k2r = -9.0 * std::sin(psi + 0.5 * h * k1p);
            const double k3p = rate + 0.5 * h * k2r, k3r = -9.0 * std::sin(psi + 0.5 * h * k2p);
            const double k4p = rate + h * k3r, k4r = -9.0 * std::sin(psi + h * k3p);
            psi += h / 6.0 * (k1p + 2.0 * k2p + 2.0 * k3p + k4p);
            rate += h / 6.0 * (k1r + 2.0 * k2r + 2.0 * k3r + k4r);
            t += h;
        }
        CAPTURE(at);
        const double d = psi - 0.5;
        const Frame f = timeline.evaluate(at);
        const glm::dvec3 origin(std::sin(d), -std::cos(d), 0.0),
            velocity(rate * std::cos(d), rate * std::sin(d), 0.0);
        CHECK(glm::length(f.models[0].center - origin) < 1e-9);
        CHECK(glm::length(f.models[0].velocity - velocity) < 1e-8);
        const Turning turning = world_turnings(timeline, f, at)[0];
        CHECK(glm::length(turning.w - glm::dvec3(0, 0, rate)) < 1e-8);
    }
}

TEST_CASE("a hinge segment the host cannot evaluate fails the bake, naming the model") {
    Timeline timeline(one_model(true, true), env().plugins, "physics.test_free_rotation");
    try {
        timeline.bake(1.0);
        FAIL("the bake took a pendulum with w^2 < 0");
    } catch (const PluginError &e) {
        CHECK_THAT(e.what(), Catch::Contains("model 0's hinge segment at t = 0") &&
                                 Catch::Contains("w^2 is not positive"));
    }
    CHECK(timeline.rotations(0).empty());
}
