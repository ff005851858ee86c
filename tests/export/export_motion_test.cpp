// The keys of a baked timeline (export_motion.hpp) against the timeline itself, in double: the
// exact parts to rounding, the sampled ones within their bounds, a key at every event.
#include "export/export_motion.hpp"

#include "io/document_io.hpp"
#include "physics/scene_support.hpp"

#include <catch2/catch.hpp>

#include <glm/geometric.hpp>

using namespace animator;
using physics_test::env;

namespace {

struct Baked {
    Document doc;
    std::unique_ptr<Timeline> timeline;
};

Baked baked(const std::string &relative, double until) {
    Baked b;
    b.doc = open_document(env().plugins, test::source_dir() / relative).document;
    b.timeline = std::make_unique<Timeline>(b.doc, env().plugins);
    std::vector<std::string> ids, warnings;
    for (const Model &m : b.doc.models()) ids.push_back(m.mesh);
    b.timeline->set_meshes(load_meshes(ids, env().assets, test::source_dir() / relative, warnings));
    b.timeline->bake(until);
    return b;
}

// The largest distance between the keys' curve and the timeline's position of model m.
double worst_translation(const Timeline &t, const NodeKeys &keys, int m, double until,
                         int samples = 2000) {
    double worst = 0.0;
    for (int k = 0; k <= samples; ++k) {
        const double time = until * k / samples;
        const glm::dvec3 want = t.evaluate(time).models[static_cast<size_t>(m)].center;
        worst =
            std::max(worst, glm::length(motion_keys::hermite_at(keys.translation, time) - want) /
                                (1.0 + glm::length(want)));
    }
    return worst;
}

double worst_rotation(const Timeline &t, const NodeKeys &keys, int m, double until,
                      int samples = 2000) {
    double worst = 0.0;
    for (int k = 0; k <= samples; ++k) {
        const double time = until * k / samples;
        const glm::dquat want =
            euler_rotation(t.evaluate(time).models[static_cast<size_t>(m)].angles);
        worst = std::max(
            worst, motion_keys::angle_between(motion_keys::slerp_at(keys.rotation, time), want));
    }
    return worst;
}

} // namespace

TEST_CASE(
    "export: free flight and bounces are cubic keys exact to rounding, with a key at every event") {
    const double until = 10.0;
    Baked b = baked("assets/animations/drop.ani", until);
    MotionKeyOptions options;
    options.until = until;
    const MotionKeys keys = motion_keys_of(*b.timeline, options);
    const int ball = b.doc.find_model("ball");
    REQUIRE(ball >= 0);
    CHECK(keys.stats.translation.sampled == 0);
    CHECK(worst_translation(*b.timeline, keys.models[static_cast<size_t>(ball)], ball, until) <
          1e-13);
    // Every bounce of the ball is a key, where the velocity turns round.
    size_t bounces = 0;
    for (const ani_collision_event &e : b.timeline->events()) {
        if (e.a != static_cast<uint32_t>(ball) && e.b != static_cast<uint32_t>(ball)) continue;
        ++bounces;
        const auto &k = keys.models[static_cast<size_t>(ball)].translation;
        const auto at = std::find_if(k.begin(), k.end(),
                                     [&](const motion_keys::VecKey &x) { return x.t == e.t; });
        REQUIRE(at != k.end());
        CHECK(at->in.y < 0.0);
        CHECK(at->out.y > 0.0);
    }
    CHECK(bounces >= 5);
}

TEST_CASE("a gas of bouncing balls is exact for every ball") {
    const double until = 5.0;
    Baked b = baked("assets/animations/gas.ani", until);
    MotionKeyOptions options;
    options.until = until;
    const MotionKeys keys = motion_keys_of(*b.timeline, options);
    CHECK(keys.stats.translation.sampled == 0);
    double worst = 0.0;
    for (int m = 0; m < static_cast<int>(b.doc.models().size()); m += 7)
        worst = std::max(worst, worst_translation(*b.timeline, keys.models[static_cast<size_t>(m)],
                                                  m, until, 500));
    CHECK(worst < 1e-12);
}

TEST_CASE(
    "export: keyed motion of each interpolator is exact, and linear keys are told as linear") {
    for (const char *interpolation : {"interpolation.linear", "interpolation.smooth"}) {
        CAPTURE(interpolation);
        Document doc;
        doc.add_model(physics_test::model("box", "cube", false, false),
                      physics_test::placed({0, 0, 0}));
        doc.add_model(physics_test::model("thrown", "sphere", true, false),
                      physics_test::placed({0, 1, 0}));
        physics_test::key(doc, 1000, 0,
                          physics_test::placed({2, 1, 0}, glm::dvec3(1.0, 2.0, 1.0), {0, 90, 0}));
        physics_test::key(doc, 2500, 0,
                          physics_test::placed({3, -1, 4}, glm::dvec3(0.5), {30, 90, 45}));
        physics_test::key(doc, 4000, 0, physics_test::placed({0, 0, 1}));
        physics_test::key(doc, 1500, 1, physics_test::placed({3, 2, 0}));
        physics_test::key(doc, 3000, 1, physics_test::placed({5, 1, 1}));
        Settings s = doc.settings();
        s.interpolation = interpolation;
        s.max_time_ms = 5000;
        doc.set_settings(s);
        auto timeline = physics_test::timeline_of(doc);
        timeline->bake(5.0);
        MotionKeyOptions options;
        options.until = 5.0;
        const MotionKeys keys = motion_keys_of(*timeline, options);
        CHECK(keys.stats.translation.sampled == 0);
        CHECK(keys.stats.scale.sampled == 0);
        for (int m = 0; m < 2; ++m) {
            CAPTURE(m);
            const NodeKeys &k = keys.models[static_cast<size_t>(m)];
            CHECK(worst_translation(*timeline, k, m, 5.0) < 1e-12);
            CHECK(worst_rotation(*timeline, k, m, 5.0) < 1.5 * options.rotation_tolerance);
            double scale = 0.0;
            for (int i = 0; i <= 500; ++i) {
                const double t = 5.0 * i / 500;
                scale = std::max(
                    scale, glm::length(motion_keys::hermite_at(k.scale, t) -
                                       timeline->evaluate(t).models[static_cast<size_t>(m)].scale));
            }
            CHECK(scale < 1e-12);
        }
        // The box's keyed path: straight lines under the linear interpolator, curves under smooth.
        const bool linear = std::string(interpolation) == "interpolation.linear";
        CHECK(motion_keys::is_linear(keys.models[0].translation, 1e-9) == linear);
        // The thrown ball (Dynamics on) is kinematic whatever the choice: a parabola per span.
        CHECK_FALSE(motion_keys::is_linear(keys.models[1].translation, 1e-9));
    }
}

TEST_CASE("rigid-body turning is within the bound, and a model turned about its centre of "
          "mass is too") {
    for (const char *scene : {"assets/scenes/tumbling_cube.lua", "assets/scenes/tumbling_cone.lua",
                              "assets/scenes/rolling_ball.lua", "assets/scenes/tipping_cube.lua"}) {
        CAPTURE(scene);
        const double until = 3.0;
        Baked b = baked(scene, until);
        MotionKeyOptions options;
        options.until = until;
        const MotionKeys keys = motion_keys_of(*b.timeline, options);
        for (int m = 0; m < static_cast<int>(b.doc.models().size()); ++m) {
            CAPTURE(b.doc.models()[static_cast<size_t>(m)].name);
            const NodeKeys &k = keys.models[static_cast<size_t>(m)];
            CHECK(worst_rotation(*b.timeline, k, m, until) < 1.5 * options.rotation_tolerance);
            CHECK(worst_translation(*b.timeline, k, m, until) < 2.0 * options.position_tolerance);
            for (size_t i = 1; i < k.rotation.size(); ++i)
                CHECK(motion_keys::angle_between(k.rotation[i - 1].q, k.rotation[i].q) <=
                      motion_keys::kMaxKeyTurn + 1e-12);
        }
    }
}

TEST_CASE("with --fps a key per frame is linear and with the timeline's values") {
    const double until = 2.0;
    Baked b = baked("assets/animations/drop.ani", until);
    MotionKeyOptions options;
    options.until = until;
    options.fps = 24.0;
    const MotionKeys keys = motion_keys_of(*b.timeline, options);
    const int ball = b.doc.find_model("ball");
    const auto &k = keys.models[static_cast<size_t>(ball)].translation;
    REQUIRE(k.size() == 49);
    CHECK(motion_keys::is_linear(k, 1e-12));
    for (size_t i = 0; i < k.size(); ++i) {
        CHECK(k[i].t == Approx(static_cast<double>(i) / 24.0).margin(1e-15));
        CHECK(k[i].value == b.timeline->evaluate(k[i].t).models[static_cast<size_t>(ball)].center);
    }
}
