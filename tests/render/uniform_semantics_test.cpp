// The SDK's uniform semantics, as the host reads them.
#include "render/uniform_semantics.hpp"

#include <animator/document.h>

#include <catch2/catch.hpp>

#include <tuple>

using namespace animator;

TEST_CASE("every semantic of shading.h is known with its type, and param:<id> names a parameter") {
    const std::pair<const char *, ani_uniform_type> known[] = {
        {"model", ANI_UNIFORM_MAT4},
        {"view", ANI_UNIFORM_MAT4},
        {"projection", ANI_UNIFORM_MAT4},
        {"normal_matrix", ANI_UNIFORM_MAT3},
        {"camera_position", ANI_UNIFORM_VEC3},
        {"light_position", ANI_UNIFORM_VEC3},
        {"light_colour", ANI_UNIFORM_VEC3},
        {"ambient", ANI_UNIFORM_VEC3},
        {"kd", ANI_UNIFORM_VEC3},
        {"ks", ANI_UNIFORM_VEC3},
        {"shininess", ANI_UNIFORM_FLOAT},
        {"tint", ANI_UNIFORM_FLOAT},
        {"reflectivity", ANI_UNIFORM_FLOAT},
        {"transparency", ANI_UNIFORM_FLOAT},
        {"refractive_index", ANI_UNIFORM_FLOAT},
        {"texture", ANI_UNIFORM_SAMPLER_2D},
        {"skybox", ANI_UNIFORM_SAMPLER_CUBE},
        {"selected_tint", ANI_UNIFORM_VEC4},
    };
    for (const auto &[name, type] : known) {
        CAPTURE(name);
        std::string param;
        const auto semantic = parse_semantic(name, param);
        REQUIRE(semantic);
        CHECK(semantic_accepts(*semantic, type));
        CHECK_FALSE(semantic_accepts(*semantic, type == ANI_UNIFORM_INT ? ANI_UNIFORM_FLOAT
                                                                        : ANI_UNIFORM_INT));
        CHECK(param.empty());
    }
    std::string param;
    CHECK(parse_semantic("param:cel_bands", param) == UniformSemantic::Param);
    CHECK(param == "cel_bands");
    for (auto type : {ANI_UNIFORM_FLOAT, ANI_UNIFORM_INT, ANI_UNIFORM_VEC3, ANI_UNIFORM_VEC4})
        CHECK(semantic_accepts(UniformSemantic::Param, type));
    CHECK_FALSE(semantic_accepts(UniformSemantic::Param, ANI_UNIFORM_MAT4));
    CHECK_FALSE(parse_semantic("colour", param));
    CHECK_FALSE(parse_semantic("param:", param));
    CHECK_FALSE(parse_semantic("", param));
}

TEST_CASE("the lights' semantics: light_count, and light_position:N, light_colour:N, "
          "light_falloff:N for N in 0..7") {
    std::string param;
    CHECK(parse_semantic("light_count", param) == UniformSemantic::LightCount);
    CHECK(semantic_accepts(UniformSemantic::LightCount, ANI_UNIFORM_INT));
    CHECK_FALSE(semantic_accepts(UniformSemantic::LightCount, ANI_UNIFORM_FLOAT));
    const std::pair<const char *, UniformSemantic> per_light[] = {
        {"light_position:", UniformSemantic::LightPositionAt},
        {"light_colour:", UniformSemantic::LightColourAt},
        {"light_falloff:", UniformSemantic::LightFalloffAt},
    };
    for (const auto &[prefix, semantic] : per_light) {
        CAPTURE(prefix);
        for (int n = 0; n < kMaxShadingLights; ++n) {
            int light = -1;
            CHECK(parse_semantic(prefix + std::to_string(n), param, &light) == semantic);
            CHECK(light == n);
        }
        CHECK(semantic_accepts(semantic, ANI_UNIFORM_VEC3));
        CHECK_FALSE(semantic_accepts(semantic, ANI_UNIFORM_VEC4));
        for (const char *bad : {"8", "", "-1", "01", "1 ", "x"})
            CHECK_FALSE(parse_semantic(prefix + std::string(bad), param));
    }
    // The single light's semantics are still there: light 0.
    CHECK(parse_semantic("light_position", param) == UniformSemantic::LightPosition);
    CHECK(parse_semantic("light_colour", param) == UniformSemantic::LightColour);
    CHECK_FALSE(parse_semantic("light_falloff", param));
    CHECK(kMaxShadingLights == ANI_MAX_LIGHTS);
}

TEST_CASE("the shadows' semantics (ABI 1.9): shadow_lights, and shadow_matrix:N, shadow_map:N, "
          "shadow_texel:N for N in 0..3") {
    std::string param;
    CHECK(parse_semantic("shadow_lights", param) == UniformSemantic::ShadowLights);
    CHECK(semantic_accepts(UniformSemantic::ShadowLights, ANI_UNIFORM_INT));
    const std::tuple<const char *, UniformSemantic, ani_uniform_type> per_shadow[] = {
        {"shadow_matrix:", UniformSemantic::ShadowMatrixAt, ANI_UNIFORM_MAT4},
        {"shadow_map:", UniformSemantic::ShadowMapAt, ANI_UNIFORM_SAMPLER_2D_SHADOW},
        {"shadow_texel:", UniformSemantic::ShadowTexelAt, ANI_UNIFORM_FLOAT},
    };
    for (const auto &[prefix, semantic, type] : per_shadow) {
        CAPTURE(prefix);
        for (int n = 0; n < ANI_MAX_SHADOW_LIGHTS; ++n) {
            int light = -1;
            CHECK(parse_semantic(prefix + std::to_string(n), param, &light) == semantic);
            CHECK(light == n);
        }
        CHECK(semantic_accepts(semantic, type));
        CHECK_FALSE(semantic_accepts(semantic, ANI_UNIFORM_SAMPLER_2D));
        for (const char *bad : {"4", "7", "", "-1", "01"})
            CHECK_FALSE(parse_semantic(prefix + std::string(bad), param));
    }
    CHECK(kMaxShadowSemantics == ANI_MAX_SHADOW_LIGHTS);
}
