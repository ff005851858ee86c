// interpolation.linear on POSITION, SCALE and CAMERA_POSITION (seed, "Linear Interpolation
// between Keyframes"): v = prev + s (next - prev), s = (t - t_prev) / (t_next - t_prev).
#include "interp_support.hpp"

#include "linear.hpp"
#include "plugin/descriptor_check.hpp"
#include "support.hpp"

using namespace interp_test;

namespace {

// x, y, z at t = 0, 2, 3.
const std::vector<ani_key> kKeys = {
    key(0.0, {0, 10, -4, 0}),
    key(2.0, {4, 10, 0, 0}),
    key(3.0, {1, 16, 0, 0}),
};

const ani_channel_kind kVectorKinds[] = {ANI_CHANNEL_POSITION, ANI_CHANNEL_SCALE,
                                         ANI_CHANNEL_CAMERA_POSITION};

} // namespace

TEST_CASE("lerp is prev plus s times the difference") {
    CHECK(interp::lerp(2.0, 6.0, 0.0) == 2.0);
    CHECK(interp::lerp(2.0, 6.0, 0.25) == 3.0); // 2 + 0.25 * 4
    CHECK(interp::lerp(2.0, 6.0, 1.0) == 6.0);
    CHECK(interp::lerp(-1.0, -3.0, 0.5) == -2.0); // -1 + 0.5 * -2
}

TEST_CASE("linear positions between keys lie on the straight line with the segment's slope") {
    Interpolator linear("interpolation.linear");
    for (ani_channel_kind kind : kVectorKinds) {
        CAPTURE(kind);
        const ani_channel ch = channel(kind, kKeys);
        const Evaluation e = linear.evaluate(ch, {0.5, 1.0, 1.5, 2.5, 2.75});
        REQUIRE(e.code == ANI_OK);
        // Segment 0 (dt = 2): s = t / 2; x = 0 + s * 4, y = 10, z = -4 + s * 4; rate (2, 0, 2).
        // t = 0.5: s = 0.25 -> (1, 10, -3); t = 1: s = 0.5 -> (2, 10, -2);
        // t = 1.5: s = 0.75 -> (3, 10, -1).
        const double seg0[3][3] = {{1, 10, -3}, {2, 10, -2}, {3, 10, -1}};
        for (size_t i = 0; i < 3; ++i) {
            CAPTURE(i);
            for (int c = 0; c < 3; ++c) CHECK(e.value(i, c) == close(seg0[i][c]));
            CHECK(e.rate(i, 0) == close(2.0)); // (4 - 0) / 2
            CHECK(e.rate(i, 1) == close(0.0));
            CHECK(e.rate(i, 2) == close(2.0)); // (0 - -4) / 2
        }
        // Segment 1 (dt = 1): x = 4 + s * (1 - 4), y = 10 + s * 6, z = 0; rate (-3, 6, 0).
        // t = 2.5: s = 0.5 -> (2.5, 13, 0); t = 2.75: s = 0.75 -> (1.75, 14.5, 0).
        const double seg1[2][3] = {{2.5, 13, 0}, {1.75, 14.5, 0}};
        for (size_t i = 3; i < 5; ++i) {
            CAPTURE(i);
            for (int c = 0; c < 3; ++c) CHECK(e.value(i, c) == close(seg1[i - 3][c]));
            CHECK(e.rate(i, 0) == close(-3.0));
            CHECK(e.rate(i, 1) == close(6.0));
            CHECK(e.rate(i, 2) == close(0.0));
        }
        for (size_t i = 0; i < 5; ++i) {
            CHECK(e.value(i, 3) == 0.0); // three-component channels leave the fourth at 0
            CHECK(e.rate(i, 3) == 0.0);
        }
    }
}

TEST_CASE("linear reaches every key exactly, bit for bit, at its time") {
    Interpolator linear("interpolation.linear");
    // Values and times that do not survive prev + 1 * (next - prev) in binary floating point.
    const std::vector<ani_key> keys = {
        key(0.1, {0.1, 0.7, 1e-3, 0}),
        key(0.3, {0.3, -0.2, 123.456, 0}),
        key(0.7, {1e9 + 0.1, 0.1, 0.3, 0}),
        key(1.1, {-0.9, 3.3, 7.7, 0}),
    };
    for (ani_channel_kind kind : kVectorKinds) {
        CAPTURE(kind);
        const Evaluation e = linear.evaluate(channel(kind, keys), {0.1, 0.3, 0.7, 1.1});
        REQUIRE(e.code == ANI_OK);
        for (size_t k = 0; k < keys.size(); ++k)
            for (int c = 0; c < 3; ++c) CHECK(e.value(k, c) == keys[k].value[c]);
    }
}

TEST_CASE("linear holds the first key before the range and the last key after it") {
    Interpolator linear("interpolation.linear");
    for (ani_channel_kind kind : kVectorKinds) {
        CAPTURE(kind);
        const Evaluation e = linear.evaluate(channel(kind, kKeys), {-5.0, -0.001, 3.0, 3.5, 100.0});
        REQUIRE(e.code == ANI_OK);
        for (size_t i = 0; i < 2; ++i) {
            for (int c = 0; c < 3; ++c) {
                CHECK(e.value(i, c) == kKeys[0].value[c]);
                CHECK(e.rate(i, c) == 0.0); // nothing moves before the first key
            }
        }
        // At and after the last key: its value; the rate is the last segment's slope
        // ((1 - 4) / 1, (16 - 10) / 1, 0) = (-3, 6, 0), which a Dynamics model continues with.
        for (size_t i = 2; i < 5; ++i) {
            for (int c = 0; c < 3; ++c) CHECK(e.value(i, c) == kKeys[2].value[c]);
            CHECK(e.rate(i, 0) == close(-3.0));
            CHECK(e.rate(i, 1) == close(6.0));
            CHECK(e.rate(i, 2) == close(0.0));
        }
    }
}

TEST_CASE("linear rate at an interior key is the slope of the segment it starts") {
    Interpolator linear("interpolation.linear");
    const Evaluation e = linear.evaluate(channel(ANI_CHANNEL_POSITION, kKeys), {0.0, 2.0});
    REQUIRE(e.code == ANI_OK);
    CHECK(e.rate(0, 0) == close(2.0));  // segment 0: (4 - 0) / 2
    CHECK(e.rate(1, 0) == close(-3.0)); // segment 1: (1 - 4) / 1
    CHECK(e.rate(1, 1) == close(6.0));  // (16 - 10) / 1
}

TEST_CASE("linear with one key holds it at every time with rate 0") {
    Interpolator linear("interpolation.linear");
    const std::vector<ani_key> keys = {key(1.0, {3, -2, 5, 0})};
    const Evaluation e =
        linear.evaluate(channel(ANI_CHANNEL_POSITION, keys, {7, 7, 7, 0}), {0.0, 1.0, 2.0});
    REQUIRE(e.code == ANI_OK);
    for (size_t i = 0; i < 3; ++i)
        for (int c = 0; c < 3; ++c) {
            CHECK(e.value(i, c) == keys[0].value[c]);
            CHECK(e.rate(i, c) == 0.0); // linear ignores initial_rate
        }
}

TEST_CASE("the interpolation library provides its three interpolators with their channel kinds") {
    const uint32_t every = (1u << ANI_CHANNEL_POSITION) | (1u << ANI_CHANNEL_ANGLES) |
                           (1u << ANI_CHANNEL_SCALE) | (1u << ANI_CHANNEL_CAMERA_POSITION) |
                           (1u << ANI_CHANNEL_CAMERA_ROTATION);
    CHECK(Interpolator("interpolation.linear").api().channel_mask == every);
    CHECK(Interpolator("interpolation.smooth").api().channel_mask == every);
    CHECK(Interpolator("interpolation.kinematic").api().channel_mask == (1u << ANI_CHANNEL_POSITION));
}

TEST_CASE("the interpolation descriptors pass the host's checks") {
    for (const char *id : {"interpolation.linear", "interpolation.kinematic", "interpolation.smooth"}) {
        CAPTURE(id);
        animator::PluginRegistry registry({animator::test::bin_dir()}, {});
        const animator::PluginInfo *info = registry.find(id);
        REQUIRE(info != nullptr);
        CHECK(animator::check_plugin_descriptor(*info->descriptor).empty());
        CHECK(info->library.filename() == "animator-interpolation.so");
        CHECK(registry.refusals().empty());
    }
}
