// Angles in degrees in [0, 360) and the direction rule (seed, "Linear Interpolation between
// Keyframes"): per axis, delta = next - prev, adjusted by the next key's turn: 0 the shorter way,
// < 0 counter-clockwise (increasing), > 0 clockwise (decreasing).
#include "interp_support.hpp"

#include "angles.hpp"
#include "linear.hpp"

#include <algorithm>
#include <cmath>
#include <random>

using namespace interp_test;

namespace {

// One axis (x) from `from` to `to` over t in [0, 1], turning `turn`; y and z stay 0.
std::vector<ani_key> one_axis(double from, double to, double turn) {
    return {key(0.0, {from, 0, 0, 0}), key(1.0, {to, 0, 0, 0}, {turn, 0, 0, 0})};
}

// x at t = 0.25, 0.5, 0.75, and its rate.
struct Quarters {
    double q1, q2, q3, rate;
};

Quarters quarters(const Interpolator &plugin, double from, double to, double turn) {
    const std::vector<ani_key> keys = one_axis(from, to, turn);
    const Evaluation e = plugin.evaluate(channel(ANI_CHANNEL_ANGLES, keys), {0.25, 0.5, 0.75});
    REQUIRE(e.code == ANI_OK);
    CHECK(e.rate(0, 0) == e.rate(2, 0));
    return {e.value(0, 0), e.value(1, 0), e.value(2, 0), e.rate(0, 0)};
}

} // namespace

TEST_CASE("wrap_degrees maps every angle into 0 to 360, never 360 and never minus zero") {
    CHECK(interp::wrap_degrees(0.0) == 0.0);
    CHECK(interp::wrap_degrees(359.5) == 359.5);
    CHECK(interp::wrap_degrees(360.0) == 0.0);
    CHECK(interp::wrap_degrees(365.0) == 5.0);
    CHECK(interp::wrap_degrees(-2.5) == 357.5);  // -2.5 + 360
    CHECK(interp::wrap_degrees(-725.0) == 355.0); // -725 + 3 * 360
    CHECK(interp::wrap_degrees(1080.0) == 0.0);
    // -1e-17 + 360 rounds to 360.0 exactly: that angle is 0.
    CHECK(interp::wrap_degrees(-1e-17) == 0.0);
    CHECK_FALSE(std::signbit(interp::wrap_degrees(-0.0)));
    CHECK_FALSE(std::signbit(interp::wrap_degrees(-360.0)));
}

TEST_CASE("turn_delta follows the shorter way, counter-clockwise or clockwise") {
    // Shorter way: 350 - 20 = 330 > 180 -> 330 - 360 = -30; 20 - 350 = -330 -> +30.
    CHECK(interp::turn_delta(20, 350, 0) == -30.0);
    CHECK(interp::turn_delta(350, 20, 0) == 30.0);
    CHECK(interp::turn_delta(10, 100, 0) == 90.0);
    // A half turn keeps the raw difference's direction.
    CHECK(interp::turn_delta(90, 270, 0) == 180.0);
    CHECK(interp::turn_delta(270, 90, 0) == -180.0);
    // Counter-clockwise (< 0) only increases: -330 + 360 = 30; 330 stays; 290 stays.
    CHECK(interp::turn_delta(350, 20, -1) == 30.0);
    CHECK(interp::turn_delta(20, 350, -1) == 330.0);
    CHECK(interp::turn_delta(10, 300, -0.5) == 290.0);
    // Clockwise (> 0) only decreases: 330 - 360 = -30; -330 stays.
    CHECK(interp::turn_delta(20, 350, 2) == -30.0);
    CHECK(interp::turn_delta(350, 20, 2) == -330.0);
    // No movement stays no movement whichever way the user turned.
    CHECK(interp::turn_delta(40, 40, -1) == 0.0);
    CHECK(interp::turn_delta(40, 40, 1) == 0.0);
}

TEST_CASE("lerp_angle and unwrap_angles apply the rule") {
    CHECK(interp::lerp_angle(20, 350, 0, 0.5) == 5.0);   // 20 + 0.5 * -30
    CHECK(interp::lerp_angle(20, 350, 0, 0.75) == 357.5); // 20 - 22.5 = -2.5 -> 357.5
    CHECK(interp::lerp_angle(10, 300, -1, 0.5) == 155.0); // 10 + 0.5 * 290
    // 350 -> 10 (+20, shorter) -> 30 (+20) -> 20 (clockwise: -10) -> 20 + 350 ccw.
    const std::vector<double> unwrapped =
        interp::unwrap_angles({350, 10, 30, 20, 10}, {99, 0, 0, 1, -1});
    REQUIRE(unwrapped.size() == 5);
    CHECK(unwrapped[0] == 350.0);
    CHECK(unwrapped[1] == 370.0);
    CHECK(unwrapped[2] == 390.0);
    CHECK(unwrapped[3] == 380.0);
    CHECK(unwrapped[4] == 730.0); // 380 + (10 - 20 + 360)
}

TEST_CASE("linear angles from 20 to 350 go the shorter way through 0") {
    Interpolator linear("interpolation.linear");
    // delta = -30: 20 - 7.5 = 12.5, 20 - 15 = 5, 20 - 22.5 = -2.5 -> 357.5; rate -30 deg/s.
    const Quarters q = quarters(linear, 20, 350, 0);
    CHECK(q.q1 == close(12.5));
    CHECK(q.q2 == close(5.0));
    CHECK(q.q3 == close(357.5));
    CHECK(q.rate == close(-30.0));
}

TEST_CASE("linear angles from 350 to 20 go the shorter way through 0") {
    Interpolator linear("interpolation.linear");
    // delta = +30: 357.5, 365 -> 5, 372.5 -> 12.5; rate +30 deg/s.
    const Quarters q = quarters(linear, 350, 20, 0);
    CHECK(q.q1 == close(357.5));
    CHECK(q.q2 == close(5.0));
    CHECK(q.q3 == close(12.5));
    CHECK(q.rate == close(30.0));
}

TEST_CASE("linear angles turning counter-clockwise always increase") {
    Interpolator linear("interpolation.linear");
    // 350 -> 20 ccw: delta +30, as the shorter way: 357.5, 5, 12.5.
    Quarters q = quarters(linear, 350, 20, -1);
    CHECK(q.q1 == close(357.5));
    CHECK(q.q2 == close(5.0));
    CHECK(q.q3 == close(12.5));
    CHECK(q.rate == close(30.0));
    // 20 -> 350 ccw: delta +330, the long way through 180: 20 + 82.5, 20 + 165, 20 + 247.5.
    q = quarters(linear, 20, 350, -1);
    CHECK(q.q1 == close(102.5));
    CHECK(q.q2 == close(185.0));
    CHECK(q.q3 == close(267.5));
    CHECK(q.rate == close(330.0));
}

TEST_CASE("linear angles turning clockwise always decrease") {
    Interpolator linear("interpolation.linear");
    // 20 -> 350 cw: delta -30: 12.5, 5, 357.5.
    Quarters q = quarters(linear, 20, 350, 1);
    CHECK(q.q1 == close(12.5));
    CHECK(q.q2 == close(5.0));
    CHECK(q.q3 == close(357.5));
    CHECK(q.rate == close(-30.0));
    // 350 -> 20 cw: delta -330, the long way: 350 - 82.5, 350 - 165, 350 - 247.5.
    q = quarters(linear, 350, 20, 1);
    CHECK(q.q1 == close(267.5));
    CHECK(q.q2 == close(185.0));
    CHECK(q.q3 == close(102.5));
    CHECK(q.rate == close(-330.0));
}

TEST_CASE("linear angles can turn more than half a turn when the user turned that way") {
    Interpolator linear("interpolation.linear");
    // 10 -> 300 ccw: delta +290: 10 + 72.5, 10 + 145, 10 + 217.5.
    Quarters q = quarters(linear, 10, 300, -1);
    CHECK(q.q1 == close(82.5));
    CHECK(q.q2 == close(155.0));
    CHECK(q.q3 == close(227.5));
    CHECK(q.rate == close(290.0));
    // The same keys with no direction go the shorter way: delta 290 - 360 = -70:
    // 10 - 17.5 = -7.5 -> 352.5, 10 - 35 = -25 -> 335, 10 - 52.5 = -42.5 -> 317.5.
    q = quarters(linear, 10, 300, 0);
    CHECK(q.q1 == close(352.5));
    CHECK(q.q2 == close(335.0));
    CHECK(q.q3 == close(317.5));
    CHECK(q.rate == close(-70.0));
}

TEST_CASE("linear angles half a turn apart keep the raw direction") {
    Interpolator linear("interpolation.linear");
    // 90 -> 270: delta +180: 135, 180, 225.
    Quarters q = quarters(linear, 90, 270, 0);
    CHECK(q.q1 == close(135.0));
    CHECK(q.q2 == close(180.0));
    CHECK(q.q3 == close(225.0));
    CHECK(q.rate == close(180.0));
    // 270 -> 90: delta -180: 225, 180, 135.
    q = quarters(linear, 270, 90, 0);
    CHECK(q.q1 == close(225.0));
    CHECK(q.q2 == close(180.0));
    CHECK(q.q3 == close(135.0));
    CHECK(q.rate == close(-180.0));
}

TEST_CASE("the direction of a segment is the one recorded on its next key, per axis") {
    Interpolator linear("interpolation.linear");
    // Key 0's turns (ccw on every axis) do not matter; key 1's do: x shorter way, y ccw, z cw.
    const std::vector<ani_key> keys = {
        key(0.0, {20, 20, 350, 0}, {-1, -1, -1, 0}),
        key(2.0, {350, 350, 20, 0}, {0, -1, 1, 0}),
    };
    const Evaluation e = linear.evaluate(channel(ANI_CHANNEL_ANGLES, keys), {1.0});
    REQUIRE(e.code == ANI_OK);
    CHECK(e.value(0, 0) == close(5.0));   // 20 + 0.5 * -30
    CHECK(e.value(0, 1) == close(185.0)); // 20 + 0.5 * 330
    CHECK(e.value(0, 2) == close(185.0)); // 350 + 0.5 * -330
    CHECK(e.rate(0, 0) == close(-15.0));  // -30 / 2 s
    CHECK(e.rate(0, 1) == close(165.0));  // 330 / 2 s
    CHECK(e.rate(0, 2) == close(-165.0)); // -330 / 2 s
}

TEST_CASE("linear angles outside 0 to 360 in a key are wrapped first") {
    Interpolator linear("interpolation.linear");
    // 370 is 10 and -30 is 330: shorter way from 10 to 330 is -40; at s = 0.5: -10 -> 350.
    const std::vector<ani_key> keys = {key(0.0, {370, 0, 0, 0}), key(1.0, {-30, 0, 0, 0})};
    const Evaluation e = linear.evaluate(channel(ANI_CHANNEL_ANGLES, keys), {0.0, 0.5, 1.0});
    REQUIRE(e.code == ANI_OK);
    CHECK(e.value(0, 0) == 10.0);
    CHECK(e.value(1, 0) == close(350.0));
    CHECK(e.value(2, 0) == 330.0);
}

TEST_CASE("interpolated angles always lie in 0 to 360 and keys are reached exactly") {
    Interpolator linear("interpolation.linear");
    Interpolator smooth("interpolation.smooth");
    std::mt19937 rng(20240601);
    std::uniform_real_distribution<double> angle(0.0, 360.0), gap(0.01, 2.0);
    std::uniform_int_distribution<int> turn(-1, 1);
    for (int trial = 0; trial < 20; ++trial) {
        std::vector<ani_key> keys;
        double t = 0.0;
        for (int k = 0; k < 8; ++k) {
            t += gap(rng);
            keys.push_back(key(t, {angle(rng), angle(rng), angle(rng), 0},
                               {double(turn(rng)), double(turn(rng)), double(turn(rng)), 0}));
        }
        keys[1].value[0] = 0.0; // angles at the very edge
        keys[2].value[1] = std::nextafter(360.0, 0.0);
        std::vector<double> times = linspace(0.0, t + 1.0, 5000);
        for (const ani_key &k : keys) times.push_back(k.time);
        std::sort(times.begin(), times.end());
        const ani_channel ch = channel(ANI_CHANNEL_ANGLES, keys);
        for (const Interpolator *plugin : {&linear, &smooth}) {
            const Evaluation e = plugin->evaluate(ch, times);
            REQUIRE(e.code == ANI_OK);
            for (size_t i = 0; i < times.size(); ++i)
                for (int c = 0; c < 3; ++c) {
                    CAPTURE(trial, i, c);
                    CHECK(e.value(i, c) >= 0.0);
                    CHECK(e.value(i, c) < 360.0);
                }
            for (const ani_key &k : keys) {
                const Evaluation at = plugin->at(ch, k.time);
                for (int c = 0; c < 3; ++c) CHECK(at.value(0, c) == k.value[c]);
            }
        }
    }
}
