// The SDK's example plugin (sdk/examples/step_interpolator.c), loaded and used as the host uses
// any interpolator.
#include "plugin/instance.hpp"

#include "support.hpp"

#include <animator/interpolator.h>
#include <catch2/catch.hpp>

using namespace animator;

TEST_CASE("the example step interpolator holds each key until the next") {
    PluginRegistry registry({ANIMATOR_EXAMPLE_PLUGIN_DIR}, {});
    const PluginInfo *info = registry.find("interpolator.step");
    REQUIRE(info != nullptr);
    PluginInstance step(*info, registry.host());
    const auto &api = step.api<ani_interpolator_api>();
    CHECK((api.channel_mask & (1u << ANI_CHANNEL_POSITION)) != 0);

    const ani_key keys[] = {
        {0.0, {1, 10, 100, 0}, {0, 0, 0, 0}},
        {1.0, {5, 50, 500, 0}, {0, 0, 0, 0}},
        {2.0, {3, 30, 300, 0}, {0, 0, 0, 0}},
    };
    ani_channel channel{sizeof(ani_channel), ANI_CHANNEL_POSITION, keys, 3, {0, 0, 0, 0}};
    const double times[] = {-1.0, 0.0, 0.5, 1.0, 1.5, 2.0, 7.0};
    double values[4 * 7], rates[4 * 7];
    ani_status status{};
    REQUIRE(api.evaluate(step.handle(), &channel, times, 7, values, rates, &status) == ANI_OK);
    const double expected_x[] = {1, 1, 1, 5, 5, 3, 3};
    for (int i = 0; i < 7; ++i) {
        CAPTURE(times[i]);
        CHECK(values[4 * i] == expected_x[i]);
        CHECK(values[4 * i + 1] == expected_x[i] * 10);
        CHECK(rates[4 * i] == 0.0);
    }

    step.set_param("hold", {0.0, 0.0, 0.0, 0.0}); // jump to the next key as soon as we leave one
    REQUIRE(api.evaluate(step.handle(), &channel, times, 7, values, rates, &status) == ANI_OK);
    const double jumped_x[] = {1, 1, 5, 5, 3, 3, 3};
    for (int i = 0; i < 7; ++i) {
        CAPTURE(times[i]);
        CHECK(values[4 * i] == jumped_x[i]);
    }

    ani_channel empty{sizeof(ani_channel), ANI_CHANNEL_POSITION, keys, 0, {0, 0, 0, 0}};
    CHECK(api.evaluate(step.handle(), &empty, times, 1, values, rates, &status) == ANI_ERR_INVALID_ARGUMENT);
    CHECK(std::string(status.message).size() > 0);
}
