// The host's reading of ABI 1.8 carried segments, apart from any real backend: a test backend
// (fake/carrier_backend.cpp) says a box is carried by a keyed platform that moves and turns, and
// the host must place the box where the platform takes it (fake/carried_scene.hpp has it by
// hand), give it to the next slice of the bake as free in that state, keep it in a bake file,
// and refuse a carried segment it cannot evaluate.
#include "io/environment.hpp"
#include "timeline/bake_file.hpp"
#include "timeline/timeline.hpp"
#include "timeline/world_turning.hpp"

#include "fake/carried_scene.hpp"
#include "fake/fake_env.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <cmath>

using namespace animator;
using fake_backends::env;
using carried_test::carried_document;
using carried_test::expected_box;

namespace {

// The angle between two orientations (q and -q are one).
double apart(const glm::dquat &a, const glm::dquat &b) {
    return 2.0 * std::acos(std::min(1.0, std::abs(glm::dot(glm::normalize(a), glm::normalize(b)))));
}

void check_box(const Timeline &timeline, double t) {
    CAPTURE(t);
    const carried_test::Expected want = expected_box(t);
    const Frame f = timeline.evaluate(t);
    CHECK(f.motion[1] == ANI_MOTION_CARRIED);
    CHECK(glm::length(f.models[1].center - want.center) < 1e-12);
    CHECK(glm::length(f.models[1].velocity - want.velocity) < 1e-12);
    CHECK(f.models[1].scale == glm::dvec3(1.0));
    const Turning turning = world_turnings(timeline, f, t)[1];
    CHECK(apart(turning.q, want.q) < 1e-7);
    CHECK(glm::length(turning.w - want.w) < 1e-12);
    // The frame's Euler angles say the same orientation (X-Y-Z about the model's own axes).
    ModelPose angles_only;
    angles_only.angles = f.models[1].angles;
    glm::dquat q;
    glm::dvec3 w;
    keyed_turning(angles_only, q, w);
    CHECK(apart(q, want.q) < 1e-7);
}

} // namespace

TEST_CASE("a carried segment places the model where its moving, turning carrier takes it") {
    Timeline timeline(carried_document(0), env().plugins, "physics.test_carrier");
    timeline.bake(2.0);
    REQUIRE(timeline.carried(1).size() == 1);
    // The platform's keys are what the hand computation assumes.
    const ModelPose platform = timeline.keyed().model(0, 0.8);
    REQUIRE(glm::length(platform.center - glm::dvec3(1.6, 0.4, 0.0)) < 1e-12);
    REQUIRE(std::abs(platform.angles.y - 36.0) < 1e-9);
    for (double t : {0.0, 0.3, 0.8, 1.37, 2.0}) check_box(timeline, t);
}

TEST_CASE("a model carried where a bake slice ends starts the next one free, turning with its carrier") {
    // The backend fails the second slice unless model 1 starts free at its carried place and
    // velocity, turning at its carrier's angular velocity (carrier_backend.cpp, check_start).
    Timeline timeline(carried_document(0), env().plugins, "physics.test_carrier");
    timeline.bake(0.7);
    REQUIRE_NOTHROW(timeline.bake(1.5));
    REQUIRE_NOTHROW(timeline.bake(2.0));
    CHECK(timeline.carried(1).size() == 3);
    for (double t : {0.35, 0.7, 1.1, 1.5, 1.9}) check_box(timeline, t);
}

TEST_CASE("a bake file keeps carried segments, and the loaded timeline places the model bit for bit") {
    Timeline baked(carried_document(0), env().plugins, "physics.test_carrier");
    baked.bake(2.0);
    const std::filesystem::path file = test::fresh_dir("carried_segment") / "carried.bake";
    save_bake(baked, file);
    Timeline loaded(carried_document(0), env().plugins, "physics.test_carrier");
    load_bake(loaded, file, 2.0);
    REQUIRE(loaded.carried(1).size() == 1);
    for (double t : {0.0, 0.45, 1.3, 2.0}) {
        const ModelPose a = baked.evaluate(t).models[1], b = loaded.evaluate(t).models[1];
        CHECK(a.center == b.center);
        CHECK(a.velocity == b.velocity);
        CHECK(a.angles == b.angles);
    }
    check_box(loaded, 1.3);
}

TEST_CASE("a carried segment the host cannot evaluate fails the bake, naming the model") {
    const std::pair<int, const char *> cases[] = {
        {1, "its carrier 1 is not another model"},
        {2, "its chain of carriers comes back to model"},
        {3, "its carrier 2 is not another model"},
    };
    for (const auto &[mode, why] : cases) {
        CAPTURE(mode);
        Timeline timeline(carried_document(mode), env().plugins, "physics.test_carrier");
        try {
            timeline.bake(1.0);
            FAIL("the bake took a carried segment it cannot evaluate");
        } catch (const PluginError &e) {
            CHECK_THAT(e.what(), Catch::Contains("carried segment at t = 0") && Catch::Contains(why));
        }
        CHECK(timeline.carried(1).empty());
        CHECK(timeline.segments(1).empty());
    }
}
