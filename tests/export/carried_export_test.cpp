// The keys of a carried model (ABI 1.8) against where its carrier takes it, by hand
// (tests/timeline/fake/carried_scene.hpp): a box carried by a platform that moves and turns, as a
// test backend (physics.test_carrier) reports it. Its translation and rotation are sampled within
// the export's bounds.
#include "export/export_motion.hpp"

#include "../timeline/fake/carried_scene.hpp"
#include "../timeline/fake/fake_env.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

using namespace animator;

TEST_CASE("a carried model's keys follow its carrier's motion and turn within the export's bounds") {
    Timeline timeline(carried_test::carried_document(0), fake_backends::env().plugins, "physics.test_carrier");
    timeline.bake(2.0);
    MotionKeyOptions options;
    options.until = 2.0;
    const MotionKeys keys = motion_keys_of(timeline, options);
    const NodeKeys &box = keys.models[1];
    CHECK(keys.stats.translation.sampled > 0); // its origin goes round: no single cubic
    double worst_position = 0.0, worst_turn = 0.0;
    for (int k = 0; k <= 1000; ++k) {
        const double t = 2.0 * k / 1000;
        const carried_test::Expected want = carried_test::expected_box(t);
        worst_position = std::max(worst_position, glm::length(motion_keys::hermite_at(box.translation, t) - want.center) /
                                                      (1.0 + glm::length(want.center)));
        worst_turn = std::max(worst_turn, motion_keys::angle_between(motion_keys::slerp_at(box.rotation, t), want.q));
    }
    CHECK(worst_position < 1.5 * options.position_tolerance);
    CHECK(worst_turn < 1.5 * options.rotation_tolerance);
    // The keys' ends are the hand values themselves.
    CHECK(glm::length(box.translation.front().value - carried_test::expected_box(0.0).center) < 1e-12);
    CHECK(glm::length(box.translation.back().value - carried_test::expected_box(2.0).center) < 1e-12);
}
