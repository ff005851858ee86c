// interpolation.kinematic (seed, "Keyframe Interpolation with Kinematic Equations"): per segment
// a = 2 (d - v0 dt) / dt^2, v0 of the next segment = v0 + a dt, starting from initial_rate.
#include "interp_support.hpp"

#include "kinematic.hpp"

#include <cmath>
#include <random>

using namespace interp_test;

namespace {

// t = 0, 2, 3. x: 0, 4, 4 from v0 = 1; y: constant 1 from v0 = 0; z: 0, -2, 1 from v0 = -1.
const std::vector<ani_key> kKeys = {
    key(0.0, {0, 1, 0, 0}),
    key(2.0, {4, 1, -2, 0}),
    key(3.0, {4, 1, 1, 0}),
};
const std::array<double, 4> kInitial = {1, 0, -1, 0};

} // namespace

TEST_CASE("kinematic_segments follow the seed's equations") {
    // x: segment 0: dt = 2, d = 4, a = 2 (4 - 1 * 2) / 4 = 1, v1 = 1 + 1 * 2 = 3.
    //    segment 1: dt = 1, d = 0, a = 2 (0 - 3 * 1) / 1 = -6.
    const auto x = interp::kinematic_segments({0, 2, 3}, {0, 4, 4}, 1.0);
    REQUIRE(x.size() == 2);
    CHECK(x[0].v0 == 1.0);
    CHECK(x[0].a == 1.0);
    CHECK(x[1].v0 == 3.0);
    CHECK(x[1].a == -6.0);
    // z: segment 0: d = -2, a = 2 (-2 - (-1) 2) / 4 = 0, v1 = -1;
    //    segment 1: d = 3, a = 2 (3 - (-1) 1) / 1 = 8.
    const auto z = interp::kinematic_segments({0, 2, 3}, {0, -2, 1}, -1.0);
    REQUIRE(z.size() == 2);
    CHECK(z[0].a == 0.0);
    CHECK(z[1].v0 == -1.0);
    CHECK(z[1].a == 8.0);
    // One key: no segment.
    CHECK(interp::kinematic_segments({5}, {1}, 2.0).empty());
    // kinematic_at: 4 + 3 * 0.5 - 6 * 0.25 / 2 = 4.75, velocity 3 - 6 * 0.5 = 0.
    const interp::ValueRate p = interp::kinematic_at(4.0, x[1], 0.5);
    CHECK(p.value == 4.75);
    CHECK(p.rate == 0.0);
}

TEST_CASE("kinematic positions match the closed forms for three keys with an initial velocity") {
    Interpolator kinematic("interpolation.kinematic");
    const Evaluation e = kinematic.evaluate(channel(ANI_CHANNEL_POSITION, kKeys, kInitial),
                                            {-1.0, 0.0, 1.0, 2.0, 2.5, 3.0, 10.0});
    REQUIRE(e.code == ANI_OK);
    // Before the first key: the first key, moving with the initial velocity.
    CHECK(e.value(0, 0) == 0.0);
    CHECK(e.rate(0, 0) == 1.0);
    CHECK(e.rate(0, 2) == -1.0);
    // t = 0: key 0, rate v0 = (1, 0, -1).
    CHECK(e.rate(1, 0) == close(1.0));
    CHECK(e.rate(1, 2) == close(-1.0));
    // t = 1 (tau 1 in segment 0): x = 0 + 1 + 1/2 = 1.5, rate 1 + 1 = 2; z = 0 - 1 + 0 = -1.
    CHECK(e.value(2, 0) == close(1.5));
    CHECK(e.rate(2, 0) == close(2.0));
    CHECK(e.value(2, 1) == close(1.0));
    CHECK(e.rate(2, 1) == close(0.0));
    CHECK(e.value(2, 2) == close(-1.0));
    CHECK(e.rate(2, 2) == close(-1.0));
    // t = 2: key 1 exactly; rate v1 = (3, 0, -1).
    CHECK(e.value(3, 0) == 4.0);
    CHECK(e.value(3, 2) == -2.0);
    CHECK(e.rate(3, 0) == close(3.0));
    CHECK(e.rate(3, 2) == close(-1.0));
    // t = 2.5 (tau 0.5 in segment 1): x = 4 + 1.5 - 0.75 = 4.75, rate 3 - 3 = 0;
    // z = -2 - 0.5 + 8 * 0.25 / 2 = -1.5, rate -1 + 8 * 0.5 = 3.
    CHECK(e.value(4, 0) == close(4.75));
    CHECK(e.rate(4, 0) == close(0.0));
    CHECK(e.value(4, 2) == close(-1.5));
    CHECK(e.rate(4, 2) == close(3.0));
    // t = 3 and after: key 2; rate = the velocity the last segment ends with:
    // x: 3 - 6 * 1 = -3; z: -1 + 8 * 1 = 7.
    for (size_t i = 5; i < 7; ++i) {
        CHECK(e.value(i, 0) == 4.0);
        CHECK(e.value(i, 1) == 1.0);
        CHECK(e.value(i, 2) == 1.0);
        CHECK(e.rate(i, 0) == close(-3.0));
        CHECK(e.rate(i, 1) == close(0.0));
        CHECK(e.rate(i, 2) == close(7.0));
    }
}

TEST_CASE("kinematic reaches every key on time with continuous velocity, for uneven keys") {
    Interpolator kinematic("interpolation.kinematic");
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> gap(0.2, 3.0), pos(-10.0, 10.0);
    std::vector<ani_key> keys;
    double t = 0.5;
    for (int k = 0; k < 12; ++k) {
        keys.push_back(key(t, {pos(rng), pos(rng), pos(rng), 0}));
        t += gap(rng);
    }
    const std::array<double, 4> v0 = {0.5, -2.0, 0.0, 0};
    const ani_channel ch = channel(ANI_CHANNEL_POSITION, keys, v0);

    // Analytically: each segment ends at the next key, with the velocity the next one starts with.
    std::vector<double> times;
    for (const ani_key &k : keys) times.push_back(k.time);
    for (int c = 0; c < 3; ++c) {
        std::vector<double> p;
        for (const ani_key &k : keys) p.push_back(k.value[c]);
        const auto segments = interp::kinematic_segments(times, p, v0[static_cast<size_t>(c)]);
        for (size_t i = 0; i + 1 < keys.size(); ++i) {
            const interp::ValueRate end = interp::kinematic_at(p[i], segments[i], times[i + 1] - times[i]);
            CAPTURE(c, i);
            CHECK(end.value == close(p[i + 1], 1e-9));
            if (i + 2 < keys.size()) CHECK(end.rate == close(segments[i + 1].v0, 1e-9));
        }
    }

    // Through the plugin: exact keys, and rates just before and just after each interior key
    // differ only by |a| * 2e-9 (at most a few 1e-6 here).
    for (size_t k = 0; k < keys.size(); ++k) {
        const Evaluation at = kinematic.at(ch, keys[k].time);
        REQUIRE(at.code == ANI_OK);
        for (int c = 0; c < 3; ++c) CHECK(at.value(0, c) == keys[k].value[c]);
        if (k == 0 || k + 1 == keys.size()) continue;
        const Evaluation near = kinematic.evaluate(ch, {keys[k].time - 1e-9, keys[k].time + 1e-9});
        for (int c = 0; c < 3; ++c) {
            CAPTURE(k, c);
            CHECK(near.rate(0, c) == close(near.rate(1, c), 1e-5));
            CHECK(near.rate(0, c) == close(at.rate(0, c), 1e-5));
            CHECK(near.value(0, c) == close(keys[k].value[c], 1e-6));
        }
    }
}

TEST_CASE("kinematic with one key holds it and moves with the initial velocity") {
    Interpolator kinematic("interpolation.kinematic");
    const std::vector<ani_key> keys = {key(1.0, {2, 3, 4, 0})};
    const Evaluation e = kinematic.evaluate(channel(ANI_CHANNEL_POSITION, keys, {1, -1, 0.5, 0}),
                                            {0.0, 1.0, 5.0});
    REQUIRE(e.code == ANI_OK);
    for (size_t i = 0; i < 3; ++i) {
        CHECK(e.value(i, 0) == 2.0);
        CHECK(e.value(i, 1) == 3.0);
        CHECK(e.value(i, 2) == 4.0);
        CHECK(e.rate(i, 0) == 1.0);
        CHECK(e.rate(i, 1) == -1.0);
        CHECK(e.rate(i, 2) == 0.5);
        CHECK(e.rate(i, 3) == 0.0);
    }
}

TEST_CASE("kinematic overshoots after an uneven key, as the seed's scheme does") {
    Interpolator kinematic("interpolation.kinematic");
    // 0 at t = 0, 1 at t = 1, 1 at t = 2, from rest: a0 = 2 (1 - 0) / 1 = 2, v1 = 2;
    // a1 = 2 (0 - 2) / 1 = -4: at t = 1.5, x = 1 + 2 * 0.5 - 4 * 0.25 / 2 = 1.5 > 1.
    const std::vector<ani_key> keys = {key(0, {0, 0, 0, 0}), key(1, {1, 0, 0, 0}), key(2, {1, 0, 0, 0})};
    const Evaluation e = kinematic.evaluate(channel(ANI_CHANNEL_POSITION, keys), {1.5, 2.0});
    REQUIRE(e.code == ANI_OK);
    CHECK(e.value(0, 0) == close(1.5));
    CHECK(e.rate(0, 0) == close(0.0)); // 2 - 4 * 0.5
    CHECK(e.value(1, 0) == 1.0);
    CHECK(e.rate(1, 0) == close(-2.0)); // it arrives moving backwards: 2 - 4 * 1
}
