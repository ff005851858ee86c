#include "plugin/descriptor_check.hpp"

#include <catch2/catch.hpp>

#include <limits>

using namespace animator;

namespace {

ani_param_descriptor float_param() {
    ani_param_descriptor p{};
    p.struct_size = sizeof p;
    p.id = "step";
    p.name = "Time step";
    p.description = "";
    p.kind = ANI_PARAM_TIME;
    p.min_value = 1e-5;
    p.max_value = 0.1;
    p.default_value = {{1.0 / 240.0, 0, 0, 0}};
    return p;
}

ani_param_value value(double v) { return ani_param_value{{v, 0, 0, 0}}; }

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

} // namespace

TEST_CASE("a well-formed parameter descriptor passes") {
    CHECK(check_param_descriptor(float_param()).empty());
}

TEST_CASE("parameter descriptors with bad ranges, defaults or ids are refused") {
    auto p = float_param();
    p.min_value = 1.0; // min > max
    CHECK_THAT(check_param_descriptor(p), Catch::Contains("min > max"));
    p = float_param();
    p.max_value = kInf;
    CHECK_THAT(check_param_descriptor(p), Catch::Contains("not finite"));
    p = float_param();
    p.default_value.value[0] = 1.0; // outside [min, max]
    CHECK_THAT(check_param_descriptor(p), Catch::Contains("invalid default"));
    p = float_param();
    p.default_value.value[0] = kNaN;
    CHECK_THAT(check_param_descriptor(p), Catch::Contains("default"));
    p = float_param();
    p.id = "Time Step";
    CHECK_THAT(check_param_descriptor(p), Catch::Contains("id"));
    p = float_param();
    p.name = "";
    CHECK_THAT(check_param_descriptor(p), Catch::Contains("no name"));
    p = float_param();
    p.kind = 99;
    CHECK_THAT(check_param_descriptor(p), Catch::Contains("unknown kind"));
    p = float_param();
    p.step = -1.0;
    CHECK_THAT(check_param_descriptor(p), Catch::Contains("step"));
    p = float_param();
    p.struct_size = 8;
    CHECK_THAT(check_param_descriptor(p), Catch::Contains("size"));
}

TEST_CASE("int, bool and enum parameters take whole numbers in range") {
    auto p = float_param();
    p.kind = ANI_PARAM_INT;
    p.min_value = 1;
    p.max_value = 50;
    p.default_value = value(10);
    CHECK(check_param_descriptor(p).empty());
    CHECK(check_param_value(p, value(50)).empty());
    CHECK_THAT(check_param_value(p, value(2.5)), Catch::Contains("whole number"));
    CHECK_THAT(check_param_value(p, value(51)), Catch::Contains("outside"));
    p.min_value = 0.5;
    CHECK_FALSE(check_param_descriptor(p).empty());

    auto b = float_param();
    b.kind = ANI_PARAM_BOOL;
    b.min_value = 0;
    b.max_value = 1;
    b.default_value = value(1);
    CHECK(check_param_descriptor(b).empty());
    CHECK_FALSE(check_param_value(b, value(2)).empty());
    b.max_value = 2;
    CHECK_FALSE(check_param_descriptor(b).empty());

    static const char *const labels[] = {"box", "hull", "mesh"};
    auto e = float_param();
    e.kind = ANI_PARAM_ENUM;
    e.enum_labels = labels;
    e.enum_count = 3;
    e.min_value = 0;
    e.max_value = 2;
    e.default_value = value(1);
    CHECK(check_param_descriptor(e).empty());
    CHECK(check_param_value(e, value(2)).empty());
    CHECK_FALSE(check_param_value(e, value(3)).empty());
    e.enum_count = 0;
    CHECK_THAT(check_param_descriptor(e), Catch::Contains("labels"));
}

TEST_CASE("values must be finite and inside the range, colours in 0..1") {
    const auto p = float_param();
    CHECK(check_param_value(p, value(0.01)).empty());
    CHECK(check_param_value(p, value(0.1)).empty());
    CHECK_FALSE(check_param_value(p, value(0.2)).empty());
    CHECK_FALSE(check_param_value(p, value(0.0)).empty());
    CHECK_FALSE(check_param_value(p, value(kNaN)).empty());
    CHECK_FALSE(check_param_value(p, value(kInf)).empty());

    auto c = float_param();
    c.kind = ANI_PARAM_COLOUR;
    c.min_value = 0;
    c.max_value = 1;
    c.default_value = {{0, 0, 0, 1}};
    CHECK(check_param_descriptor(c).empty());
    CHECK(check_param_value(c, ani_param_value{{0.2, 0.4, 1.0, 1.0}}).empty());
    CHECK_FALSE(check_param_value(c, ani_param_value{{0.2, 1.5, 0.0, 1.0}}).empty());
}

TEST_CASE("plugin ids are 'kind.name' in lower case") {
    CHECK(valid_plugin_id("physics.custom"));
    CHECK(valid_plugin_id("format.ani"));
    CHECK(valid_plugin_id("physics.bullet-ccd"));
    CHECK_FALSE(valid_plugin_id("physics"));
    CHECK_FALSE(valid_plugin_id("Physics.Custom"));
    CHECK_FALSE(valid_plugin_id("physics.custom!"));
    CHECK_FALSE(valid_plugin_id(".custom"));
    CHECK_FALSE(valid_plugin_id(""));
}
