// Bad channels and bad calls are refused with ANI_ERR_INVALID_ARGUMENT and a message, never
// answered with NaN or infinity.
#include "interp_support.hpp"

#include <cmath>
#include <limits>

using namespace interp_test;

namespace {

const char *const kPlugins[] = {"interpolation.linear", "interpolation.kinematic",
                                "interpolation.smooth"};
const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

const std::vector<ani_key> kGood = {key(0.0, {0, 0, 0, 0}), key(1.0, {1, 2, 3, 0})};

void check_refused(const Evaluation &e, const std::string &plugin_id, const std::string &about,
                   ani_status_code code = ANI_ERR_INVALID_ARGUMENT) {
    CHECK(e.code == code);
    CHECK_THAT(e.message, Catch::Contains(plugin_id) && Catch::Contains(about));
}

} // namespace

TEST_CASE("a channel without keys is refused") {
    for (const char *id : kPlugins) {
        Interpolator plugin(id);
        const std::vector<ani_key> none;
        check_refused(plugin.at(channel(ANI_CHANNEL_POSITION, none), 0.0), id, "no key");
        ani_channel null_keys = channel(ANI_CHANNEL_POSITION, kGood);
        null_keys.keys = nullptr;
        check_refused(plugin.at(null_keys, 0.0), id, "keys are null");
    }
}

TEST_CASE("key times that do not increase strictly are refused") {
    for (const char *id : kPlugins) {
        Interpolator plugin(id);
        const std::vector<ani_key> equal = {key(1.0, {0, 0, 0, 0}), key(1.0, {1, 1, 1, 0})};
        check_refused(plugin.at(channel(ANI_CHANNEL_POSITION, equal), 0.5), id, "increase strictly");
        const std::vector<ani_key> back = {key(0.0, {0, 0, 0, 0}), key(2.0, {1, 1, 1, 0}),
                                           key(1.0, {2, 2, 2, 0})};
        check_refused(plugin.at(channel(ANI_CHANNEL_POSITION, back), 0.5), id, "key 2");
        const std::vector<ani_key> nan_time = {key(0.0, {0, 0, 0, 0}), key(kNaN, {1, 1, 1, 0})};
        check_refused(plugin.at(channel(ANI_CHANNEL_POSITION, nan_time), 0.5), id, "not finite");
        const std::vector<ani_key> far = {key(-1e308, {0, 0, 0, 0}), key(1e308, {1, 1, 1, 0})};
        check_refused(plugin.at(channel(ANI_CHANNEL_POSITION, far), 0.5), id, "too far");
    }
}

TEST_CASE("non-finite values are refused") {
    for (const char *id : kPlugins) {
        Interpolator plugin(id);
        for (double bad : {kNaN, kInf, -kInf}) {
            const std::vector<ani_key> keys = {key(0.0, {0, 0, 0, 0}), key(1.0, {1, bad, 3, 0})};
            check_refused(plugin.at(channel(ANI_CHANNEL_POSITION, keys), 0.5), id, "value[1]");
        }
    }
    // The fourth component matters only for the camera's rotation.
    Interpolator linear("interpolation.linear");
    const std::vector<ani_key> q = {key(0.0, {1, 0, 0, 0}), key(1.0, {0, 0, 0, kNaN})};
    check_refused(linear.at(channel(ANI_CHANNEL_CAMERA_ROTATION, q), 0.5), "interpolation.linear", "value[3]");
    const std::vector<ani_key> p = {key(0.0, {1, 0, 0, kNaN})};
    CHECK(linear.at(channel(ANI_CHANNEL_POSITION, p), 0.5).code == ANI_OK);
    // Angles' turns and the kinematic initial velocity are numbers too.
    const std::vector<ani_key> turns = {key(0.0, {1, 0, 0, 0}), key(1.0, {5, 0, 0, 0}, {0, kNaN, 0, 0})};
    check_refused(linear.at(channel(ANI_CHANNEL_ANGLES, turns), 0.5), "interpolation.linear", "turn[1]");
    Interpolator kinematic("interpolation.kinematic");
    check_refused(kinematic.at(channel(ANI_CHANNEL_POSITION, kGood, {0, 0, kInf, 0}), 0.5),
                  "interpolation.kinematic", "initial_rate[2]");
}

TEST_CASE("a channel kind the plugin does not handle is refused") {
    Interpolator kinematic("interpolation.kinematic");
    for (ani_channel_kind kind : {ANI_CHANNEL_ANGLES, ANI_CHANNEL_SCALE, ANI_CHANNEL_CAMERA_POSITION,
                                  ANI_CHANNEL_CAMERA_ROTATION})
        check_refused(kinematic.at(channel(kind, kGood), 0.5), "interpolation.kinematic",
                      "handles position");
    for (const char *id : kPlugins) {
        Interpolator plugin(id);
        for (int kind : {0, 6, -1, 1000}) {
            ani_channel ch = channel(ANI_CHANNEL_POSITION, kGood);
            ch.kind = kind;
            check_refused(plugin.at(ch, 0.5), id, "kind " + std::to_string(kind));
        }
    }
}

TEST_CASE("camera rotation keys that are not unit quaternions are refused") {
    for (const char *id : {"interpolation.linear", "interpolation.smooth"}) {
        Interpolator plugin(id);
        for (double scale : {0.0, 0.5, 2.0}) {
            const std::vector<ani_key> keys = {key(0.0, {1, 0, 0, 0}), key(1.0, {scale, 0, 0, 0})};
            check_refused(plugin.at(channel(ANI_CHANNEL_CAMERA_ROTATION, keys), 0.5), id, "unit quaternion");
        }
    }
}

TEST_CASE("bad calls are refused: null channel, null buffers, times out of order or not finite") {
    for (const char *id : kPlugins) {
        Interpolator plugin(id);
        const ani_channel ch = channel(ANI_CHANNEL_POSITION, kGood);
        double times[2] = {0.0, 1.0}, values[8], rates[8];
        ani_status status{};
        const auto &api = plugin.api();
        void *self = plugin.instance().handle();
        CHECK(api.evaluate(self, nullptr, times, 2, values, rates, &status) == ANI_ERR_INVALID_ARGUMENT);
        CHECK_THAT(std::string(status.message), Catch::Contains("channel is null"));
        CHECK(api.evaluate(self, &ch, nullptr, 2, values, rates, &status) == ANI_ERR_INVALID_ARGUMENT);
        CHECK(api.evaluate(self, &ch, times, 2, nullptr, rates, &status) == ANI_ERR_INVALID_ARGUMENT);
        CHECK(api.evaluate(self, &ch, times, 2, values, nullptr, &status) == ANI_ERR_INVALID_ARGUMENT);
        CHECK_THAT(std::string(status.message), Catch::Contains("rates is null"));
        CHECK(api.evaluate(nullptr, &ch, times, 2, values, rates, &status) == ANI_ERR_INVALID_ARGUMENT);
        // Nothing to evaluate needs no buffers.
        CHECK(api.evaluate(self, &ch, nullptr, 0, nullptr, nullptr, &status) == ANI_OK);

        check_refused(plugin.evaluate(ch, {0.5, 0.25}), id, "increasing order");
        check_refused(plugin.evaluate(ch, {0.5, kNaN}), id, "time 1 is not finite");
        check_refused(plugin.evaluate(ch, {-kInf}), id, "not finite");

        ani_channel small = ch;
        small.struct_size = 8;
        check_refused(plugin.at(small, 0.5), id, "size 8", ANI_ERR_VERSION);
    }
}

TEST_CASE("finite keys whose interpolation would overflow are refused, not answered with infinity") {
    for (const char *id : kPlugins) {
        Interpolator plugin(id);
        // 1e308 - (-1e308) overflows: the slope would be infinite.
        const std::vector<ani_key> keys = {key(0.0, {-1e308, 0, 0, 0}), key(1.0, {1e308, 0, 0, 0})};
        const Evaluation e = plugin.evaluate(channel(ANI_CHANNEL_POSITION, keys), {0.5});
        check_refused(e, id, "too large");
    }
    // Keys a hair apart in time with an initial velocity: the kinematic acceleration overflows.
    Interpolator kinematic("interpolation.kinematic");
    const std::vector<ani_key> keys = {key(0.0, {0, 0, 0, 0}), key(1e-300, {1e10, 0, 0, 0})};
    check_refused(kinematic.evaluate(channel(ANI_CHANNEL_POSITION, keys), {0.5e-300, 1.0}),
                  "interpolation.kinematic", "too large");
}
