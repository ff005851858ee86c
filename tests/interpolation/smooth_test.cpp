// interpolation.smooth: cubic Hermite segments with Catmull-Rom tangents for non-uniform times,
// m[i] = (1 - tension) (p[i+1] - p[i-1]) / (t[i+1] - t[i-1]), one-sided at the ends; `ease`
// makes every tangent 0.
#include "interp_support.hpp"

#include "hermite.hpp"
#include "smooth.hpp"

#include <cmath>
#include <random>

using namespace interp_test;

namespace {

// x: 0, 2, 2, 5 at t = 0, 1, 3, 4; y: 1, 0.5, 3, 0; z: constant 7. (All valid angles too.)
const std::vector<ani_key> kKeys = {
    key(0.0, {0, 1, 7, 0}),
    key(1.0, {2, 0.5, 7, 0}),
    key(3.0, {2, 3, 7, 0}),
    key(4.0, {5, 0, 7, 0}),
};

const ani_channel_kind kVectorKinds[] = {ANI_CHANNEL_POSITION, ANI_CHANNEL_SCALE,
                                         ANI_CHANNEL_CAMERA_POSITION, ANI_CHANNEL_ANGLES};

const double kPi = std::acos(-1.0);

std::array<double, 4> about_y(double degrees) {
    const double half = degrees * kPi / 360.0;
    return {std::cos(half), 0.0, std::sin(half), 0.0};
}

} // namespace

TEST_CASE("catmull_rom_tangents for non-uniform times, with tension and ease") {
    // x at t = 0, 1, 3, 4: m0 = (2 - 0) / 1 = 2; m1 = (2 - 0) / (3 - 0) = 2/3;
    // m2 = (5 - 2) / (4 - 1) = 1; m3 = (5 - 2) / (4 - 3) = 3.
    const std::vector<double> t = {0, 1, 3, 4}, x = {0, 2, 2, 5};
    auto m = interp::catmull_rom_tangents(t, x, 0.0, false);
    REQUIRE(m.size() == 4);
    CHECK(m[0] == close(2.0));
    CHECK(m[1] == close(2.0 / 3.0));
    CHECK(m[2] == close(1.0));
    CHECK(m[3] == close(3.0));
    // Tension 0.25 scales each by 0.75.
    m = interp::catmull_rom_tangents(t, x, 0.25, false);
    CHECK(m[0] == close(1.5));
    CHECK(m[1] == close(0.5));
    CHECK(m[2] == close(0.75));
    CHECK(m[3] == close(2.25));
    for (double mi : interp::catmull_rom_tangents(t, x, 1.0, false)) CHECK(mi == 0.0);
    for (double mi : interp::catmull_rom_tangents(t, x, 0.0, true)) CHECK(mi == 0.0);
    CHECK(interp::catmull_rom_tangents({2}, {5}, 0.0, false) == std::vector<double>{0.0});
}

TEST_CASE("hermite gives the cubic's value and derivative") {
    // p0 = 0, p1 = 2, m0 = 2, m1 = 2/3, dt = 1, s = 0.5:
    // h01 = -2/8 + 3/4 = 1/2, h10 = 1/8 - 2/4 + 1/2 = 1/8, h11 = 1/8 - 1/4 = -1/8:
    // value = 0 + 2/2 + (2/8 - (2/3)/8) = 1 + 1/4 - 1/12 = 7/6.
    // h01' = -6/4 + 3 = 3/2, h10' = 3/4 - 2 + 1 = -1/4, h11' = 3/4 - 1 = -1/4:
    // rate = 3/2 * 2 / 1 - 2/4 - (2/3)/4 = 3 - 1/2 - 1/6 = 7/3.
    const interp::ValueRate h = interp::hermite(0, 2, 2, 2.0 / 3.0, 1, 0.5);
    CHECK(h.value == close(7.0 / 6.0));
    CHECK(h.rate == close(7.0 / 3.0));
    // Ends: the values and tangents themselves; the same segment stretched to dt = 2 at tau = 1.
    CHECK(interp::hermite(3, 5, -1, 4, 2, 0).value == 3.0);
    CHECK(interp::hermite(3, 5, -1, 4, 2, 0).rate == close(-1.0));
    CHECK(interp::hermite(3, 5, -1, 4, 2, 2).value == close(5.0));
    CHECK(interp::hermite(3, 5, -1, 4, 2, 2).rate == close(4.0));
    // Blend: m = 1 is s itself; m = 0 is smoothstep: s = 0.25 -> 3/16 - 2/64 = 0.15625,
    // derivative 6 s (1 - s) = 1.125.
    CHECK(interp::hermite_blend(0.3, 1.0).value == 0.3);
    CHECK(interp::hermite_blend(0.25, 0.0).value == close(0.15625));
    CHECK(interp::hermite_blend(0.25, 0.0).rate == close(1.125));
}

TEST_CASE("smooth matches the hand-computed cubic between keys") {
    Interpolator smooth("interpolation.smooth");
    // Segment 0 of x (0 -> 2, tangents 2 and 2/3, dt = 1) at t = 0.5: 7/6, rate 7/3 (above).
    // y at t = 0.5: tangents m0 = (0.5 - 1) / 1 = -1/2, m1 = (3 - 1) / 3 = 2/3:
    // 1 + 1/2 (-1/2) + (1/8 (-1/2) - 1/8 (2/3)) = 1 - 1/4 - 1/16 - 1/12 = 29/48;
    // rate = 3/2 (-1/2) - 1/4 (-1/2) - 1/4 (2/3) = -3/4 + 1/8 - 1/6 = -19/24.
    const Evaluation e = smooth.evaluate(channel(ANI_CHANNEL_POSITION, kKeys), {0.5});
    REQUIRE(e.code == ANI_OK);
    CHECK(e.value(0, 0) == close(7.0 / 6.0));
    CHECK(e.rate(0, 0) == close(7.0 / 3.0));
    CHECK(e.value(0, 1) == close(29.0 / 48.0));
    CHECK(e.rate(0, 1) == close(-19.0 / 24.0));
    CHECK(e.value(0, 2) == close(7.0)); // a constant stays constant
    CHECK(e.rate(0, 2) == close(0.0));
}

TEST_CASE("smooth passes through every key exactly and is C1 at interior keys") {
    Interpolator smooth("interpolation.smooth");
    for (double tension : {0.0, 0.3}) {
        smooth.set_param("tension", tension);
        for (ani_channel_kind kind : kVectorKinds) {
            CAPTURE(kind, tension);
            const ani_channel ch = channel(kind, kKeys);
            for (size_t k = 0; k < kKeys.size(); ++k) {
                const Evaluation at = smooth.at(ch, kKeys[k].time);
                REQUIRE(at.code == ANI_OK);
                for (int c = 0; c < 3; ++c) CHECK(at.value(0, c) == kKeys[k].value[c]);
                if (k == 0 || k + 1 == kKeys.size()) continue;
                // Left and right derivatives agree: both are the key's tangent. The cubic's
                // second derivative is bounded here, so 1e-9 away they differ by < 1e-7.
                const Evaluation near = smooth.evaluate(ch, {kKeys[k].time - 1e-9, kKeys[k].time + 1e-9});
                for (int c = 0; c < 3; ++c) {
                    CHECK(near.rate(0, c) == close(near.rate(1, c), 1e-7));
                    CHECK(near.rate(1, c) == close(at.rate(0, c), 1e-7));
                }
            }
        }
    }
    // Analytically: segment k ends with tangent m[k+1], which segment k+1 starts with.
    const std::vector<double> t = {0, 1, 3, 4}, x = {0, 2, 2, 5};
    const auto m = interp::catmull_rom_tangents(t, x, 0.0, false);
    for (size_t k = 0; k + 2 < t.size(); ++k) {
        const double left = interp::hermite(x[k], x[k + 1], m[k], m[k + 1], t[k + 1] - t[k], t[k + 1] - t[k]).rate;
        const double right = interp::hermite(x[k + 1], x[k + 2], m[k + 1], m[k + 2], t[k + 2] - t[k + 1], 0.0).rate;
        CHECK(left == close(right, 1e-9));
    }
}

TEST_CASE("smooth with ease or full tension stops at every key") {
    for (const char *setting : {"ease", "tension"}) {
        CAPTURE(setting);
        Interpolator smooth("interpolation.smooth");
        smooth.set_param(setting, 1.0);
        for (ani_channel_kind kind : kVectorKinds) {
            const ani_channel ch = channel(kind, kKeys);
            for (const ani_key &k : kKeys) {
                const Evaluation at = smooth.at(ch, k.time);
                REQUIRE(at.code == ANI_OK);
                for (int c = 0; c < 3; ++c) {
                    CHECK(at.value(0, c) == k.value[c]);
                    CHECK(at.rate(0, c) == close(0.0));
                }
            }
            // Segment 1 of x (2 -> 2) stays at 2; segment 2 (2 -> 5, dt = 1) at s = 0.25 is
            // 2 + 3 * smoothstep(0.25) = 2 + 3 * 0.15625 = 2.46875, rate 3 * 1.125 = 3.375.
            const Evaluation e = smooth.evaluate(ch, {2.0, 3.25, 10.0});
            CHECK(e.value(0, 0) == close(2.0));
            CHECK(e.value(1, 0) == close(2.46875));
            CHECK(e.rate(1, 0) == close(3.375));
            CHECK(e.rate(2, 0) == close(0.0)); // after the last key: it arrived at rest
        }
    }
}

TEST_CASE("smooth reproduces keys on a straight line") {
    Interpolator smooth("interpolation.smooth");
    // x = 1 + 2 t, y = 5 - t, z = 0.5 t at t = 0, 1, 2, 3: every tangent is the line's slope.
    std::vector<ani_key> keys;
    for (int k = 0; k < 4; ++k) keys.push_back(key(k, {1.0 + 2.0 * k, 5.0 - k, 0.5 * k, 0}));
    const std::vector<double> times = linspace(0.0, 3.0, 300);
    const Evaluation e = smooth.evaluate(channel(ANI_CHANNEL_POSITION, keys), times);
    REQUIRE(e.code == ANI_OK);
    for (size_t i = 0; i < times.size(); ++i) {
        const double t = times[i];
        CAPTURE(t);
        CHECK(e.value(i, 0) == close(1.0 + 2.0 * t));
        CHECK(e.value(i, 1) == close(5.0 - t));
        CHECK(e.value(i, 2) == close(0.5 * t));
        CHECK(e.rate(i, 0) == close(2.0));
        CHECK(e.rate(i, 1) == close(-1.0));
        CHECK(e.rate(i, 2) == close(0.5));
    }
}

TEST_CASE("smooth angles are unwrapped by the direction rule, then wrapped") {
    Interpolator smooth("interpolation.smooth");
    // 350, 10, 30 at t = 0, 1, 2, the shorter way: unwrapped 350, 370, 390, a straight line of
    // 20 deg/s, so t = 0.25 -> 355, t = 0.5 -> 360 -> 0, t = 1.5 -> 380 -> 20.
    const std::vector<ani_key> keys = {key(0, {350, 0, 0, 0}), key(1, {10, 0, 0, 0}), key(2, {30, 0, 0, 0})};
    const Evaluation e = smooth.evaluate(channel(ANI_CHANNEL_ANGLES, keys), {0.25, 0.5, 1.5});
    REQUIRE(e.code == ANI_OK);
    CHECK(e.value(0, 0) == close(355.0));
    // 360 - tiny or 0 + tiny: compare on the circle.
    CHECK(std::fmod(e.value(1, 0) + 180.0, 360.0) == close(180.0));
    CHECK(e.value(2, 0) == close(20.0));
    for (size_t i = 0; i < 3; ++i) CHECK(e.rate(i, 0) == close(20.0));
    // Counter-clockwise to key 1: 350 -> 10 is +20 either way; clockwise it is -340.
    const std::vector<ani_key> cw = {key(0, {350, 0, 0, 0}), key(1, {10, 0, 0, 0}, {1, 0, 0, 0})};
    // Two keys: both tangents are the chord -340 deg/s, so the curve is the line:
    // t = 0.5 -> 350 - 170 = 180.
    const Evaluation f = smooth.evaluate(channel(ANI_CHANNEL_ANGLES, cw), {0.5});
    CHECK(f.value(0, 0) == close(180.0));
    CHECK(f.rate(0, 0) == close(-340.0));
}

TEST_CASE("smooth camera rotation is slerp with the Hermite blend of 0 and 1") {
    Interpolator smooth("interpolation.smooth");
    const std::vector<ani_key> keys = {key(0, {1, 0, 0, 0}), key(2, about_y(90)), key(4, about_y(90))};
    const ani_channel ch = channel(ANI_CHANNEL_CAMERA_ROTATION, keys);
    // Default: the blend is s itself, plain slerp: t = 1 -> 45 degrees about Y, (pi/2) / 2 rad/s.
    Evaluation e = smooth.evaluate(ch, {1.0});
    REQUIRE(e.code == ANI_OK);
    const auto at45 = about_y(45);
    for (int c = 0; c < 4; ++c) CHECK(e.value(0, c) == close(at45[static_cast<size_t>(c)]));
    CHECK(e.rate(0, 1) == close(kPi / 4));
    // Ease: smoothstep. t = 0.5 (s = 0.25): 90 * 0.15625 = 14.0625 degrees, rate
    // (pi/2) * 1.125 / 2 s; t = 1 (s = 0.5): 45 degrees, rate (pi/2) * 1.5 / 2; at keys 0.
    smooth.set_param("ease", 1.0);
    e = smooth.evaluate(ch, {0.0, 0.5, 1.0, 2.0, 3.0, 4.0});
    REQUIRE(e.code == ANI_OK);
    const auto at14 = about_y(14.0625);
    for (int c = 0; c < 4; ++c) {
        CHECK(e.value(1, c) == close(at14[static_cast<size_t>(c)]));
        CHECK(e.value(2, c) == close(at45[static_cast<size_t>(c)]));
    }
    CHECK(e.rate(1, 1) == close(kPi / 2 * 1.125 / 2));
    CHECK(e.rate(2, 1) == close(kPi / 2 * 1.5 / 2));
    for (size_t i : {size_t{0}, size_t{3}, size_t{5}})
        for (int c = 0; c < 3; ++c) CHECK(e.rate(i, c) == close(0.0));
    for (int c = 0; c < 4; ++c) CHECK(e.value(4, c) == close(keys[1].value[c])); // holds still
}

TEST_CASE("smooth has tension and ease parameters the host checks") {
    Interpolator smooth("interpolation.smooth");
    CHECK(smooth.instance().get_param("tension")[0] == 0.0);
    CHECK(smooth.instance().get_param("ease")[0] == 0.0);
    smooth.set_param("tension", 0.5);
    CHECK(smooth.instance().get_param("tension")[0] == 0.5);
    CHECK_THROWS(smooth.set_param("tension", 1.5));
    CHECK_THROWS(smooth.set_param("ease", 0.5));
    CHECK_THROWS(smooth.set_param("speed", 1.0));
    CHECK(smooth.instance().get_param("tension")[0] == 0.5);
    // Linear and kinematic have none.
    Interpolator linear("interpolation.linear");
    CHECK_THROWS(linear.set_param("tension", 0.0));
}
