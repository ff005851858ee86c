// The shading.phong plugin: its descriptor and parameters, the programs it hands over for every
// feature set, and that each of them compiles and links on Mesa.
#include "render_support.hpp"

#include "render/shading_programs.hpp"

#include <catch2/catch.hpp>

#include <cstring>
#include <set>

using namespace animator;
using namespace animator::test;

namespace {
constexpr uint32_t kModelFeatures = ANI_SHADE_TEXTURE | ANI_SHADE_REFLECTION |
                                    ANI_SHADE_REFRACTION | ANI_SHADE_CEL | ANI_SHADE_SELECTED;
}

TEST_CASE("shading.phong declares its cel parameters") {
    const PluginInfo *info = environment().plugins.find("shading.phong");
    REQUIRE(info);
    CHECK(info->kind == ANI_KIND_SHADING);
    PluginInstance instance(*info, environment().plugins.host());
    CHECK(instance.get_param("cel_bands")[0] == 10.0); // the seed's step10
    CHECK(instance.get_param("cel_outline")[0] == 0.0);
    CHECK(instance.find_param("cel_outline_width"));
    CHECK(instance.find_param("cel_outline_colour")->kind == ANI_PARAM_COLOUR);
    instance.set_param("cel_bands", {4, 0, 0, 0});
    CHECK(instance.get_param("cel_bands")[0] == 4.0);
    CHECK_THROWS_AS(instance.set_param("cel_bands", {1, 0, 0, 0}), PluginError); // below 2
}

TEST_CASE("shading.phong hands over a program with exactly the uniforms of each feature set") {
    const PluginInfo *info = environment().plugins.find("shading.phong");
    REQUIRE(info);
    PluginInstance instance(*info, environment().plugins.host());
    const auto &api = instance.api<ani_shading_api>();
    auto program_for = [&](uint32_t features, ani_shader_program &p) {
        p = ani_shader_program{};
        p.struct_size = sizeof p;
        ani_status status{};
        return api.get_program(instance.handle(), features, &p, &status);
    };
    auto has = [](const ani_shader_program &p, const char *semantic) {
        for (uint32_t i = 0; i < p.uniform_count; ++i)
            if (std::strcmp(p.uniforms[i].semantic, semantic) == 0) return true;
        return false;
    };
    ani_shader_program plain{};
    REQUIRE(program_for(0, plain) == ANI_OK);
    CHECK(has(plain, "kd"));
    CHECK(has(plain, "shininess"));
    // Every light of the scene (shading.h's lights): how many, and each one's place, colour,
    // falloff.
    for (const char *light :
         {"light_count", "light_position:0", "light_colour:0", "light_falloff:0",
          "light_position:7", "light_colour:7", "light_falloff:7"})
        CHECK(has(plain, light));
    // Without shadow maps asked (ABI 1.10's bits), none of theirs: no lookup to pay for.
    for (const char *unused : {"texture", "skybox", "tint", "reflectivity", "transparency",
                               "selected_tint", "param:cel_bands", "shadow_lights",
                               "shadow_matrix:0", "shadow_map:0", "shadow_texel:0"})
        CHECK_FALSE(has(plain, unused));
    CHECK(std::strstr(plain.fragment_source, "#define TEXTURE") == nullptr);
    CHECK(std::strstr(plain.fragment_source, "#define SHADOW_MAPS 0") != nullptr);
    // With the lights' count said (ABI 1.11): those lights' uniforms only, and a loop over a
    // count fixed when compiled, not over "light_count".
    for (int n = 1; n <= ANI_MAX_LIGHTS; ++n) {
        CAPTURE(n);
        ani_shader_program counted{};
        REQUIRE(program_for(ANI_SHADE_LIGHTS(n), counted) == ANI_OK);
        CHECK_FALSE(has(counted, "light_count"));
        for (int i = 0; i < ANI_MAX_LIGHTS; ++i)
            for (const char *what : {"light_position:", "light_colour:", "light_falloff:"})
                CHECK(has(counted, (what + std::to_string(i)).c_str()) == (i < n));
        CHECK(std::strstr(counted.fragment_source, ("#define LIGHTS " + std::to_string(n) + "\n").c_str()) !=
              nullptr);
    }
    CHECK(std::strstr(plain.fragment_source, "#define LIGHTS 0\n") != nullptr);
    // With n shadow maps: each one's matrix, map and texel size, for maps 0..n-1 only.
    for (int n = 1; n <= ANI_MAX_SHADOW_LIGHTS; ++n) {
        CAPTURE(n);
        ani_shader_program shadowed{};
        REQUIRE(program_for(ANI_SHADE_SHADOW_MAPS(n), shadowed) == ANI_OK);
        for (int i = 0; i < ANI_MAX_SHADOW_LIGHTS; ++i)
            for (const char *what : {"shadow_matrix:", "shadow_map:", "shadow_texel:"})
                CHECK(has(shadowed, (what + std::to_string(i)).c_str()) == (i < n));
    }

    ani_shader_program all{};
    REQUIRE(program_for(kModelFeatures, all) == ANI_OK);
    for (const char *used :
         {"texture", "skybox", "tint", "reflectivity", "transparency", "refractive_index",
          "selected_tint", "param:cel_bands", "param:cel_outline"})
        CHECK(has(all, used));

    ani_shader_program sky{};
    REQUIRE(program_for(ANI_SHADE_SKYBOX_PASS, sky) == ANI_OK);
    CHECK(has(sky, "skybox"));
    CHECK_FALSE(has(sky, "kd"));

    ani_shader_program refused{};
    CHECK(program_for(ANI_SHADE_SKYBOX_PASS | ANI_SHADE_TEXTURE, refused) ==
          ANI_ERR_INVALID_ARGUMENT);
    CHECK(program_for(ANI_SHADE_SHADOW_MAPS(ANI_MAX_SHADOW_LIGHTS + 1), refused) ==
          ANI_ERR_INVALID_ARGUMENT);
    CHECK(program_for(ANI_SHADE_LIGHTS(ANI_MAX_LIGHTS + 1), refused) == ANI_ERR_INVALID_ARGUMENT);
    // (The lights with a shadow map are among the lights added up.)
    CHECK(program_for(ANI_SHADE_SHADOW_MAPS(2) | ANI_SHADE_LIGHTS(1), refused) ==
          ANI_ERR_INVALID_ARGUMENT);
    CHECK(program_for(1u << 13, refused) == ANI_ERR_INVALID_ARGUMENT);
}

TEST_CASE("every shading.phong program compiles and links on Mesa, with every uniform filled") {
    gl_context();
    const PluginInfo *info = environment().plugins.find("shading.phong");
    REQUIRE(info);
    std::vector<std::string> log;
    ShadingPrograms programs(std::make_unique<PluginInstance>(*info, environment().plugins.host()),
                             [&](const std::string &m) { log.push_back(m); });
    // Each model feature set with each count of shadow maps, its lights not said (0) or as few
    // as can be; every count of lights for no model feature and for all of them.
    std::vector<uint32_t> sets;
    for (uint32_t model = 0; model <= kModelFeatures; ++model)
        for (int n = 0; n <= ANI_MAX_SHADOW_LIGHTS; ++n) {
            const int fewest = std::max(n, 1);
            for (int lights = 0; lights <= ANI_MAX_LIGHTS; ++lights)
                if (lights == 0 || lights == fewest ||
                    ((model == 0 || model == kModelFeatures) && lights > fewest))
                    sets.push_back(model | ANI_SHADE_SHADOW_MAPS(n) | ANI_SHADE_LIGHTS(lights));
        }
    for (const uint32_t features : sets) {
      {
        const int n = static_cast<int>(ANI_SHADE_SHADOW_MAP_COUNT(features));
        const auto lights = static_cast<size_t>(ANI_SHADE_LIGHT_COUNT(features));
        CAPTURE(feature_names(features));
        const LinkedProgram &p = programs.get(features);
        CHECK_FALSE(p.built_in);
        // Each element of the lights' arrays is found and filled, once each: lights 0..7 when
        // their count is not said, else that many.
        std::set<int> positions, falloffs;
        for (const BoundUniform &u : p.uniforms) {
            if (u.semantic == UniformSemantic::LightPositionAt) positions.insert(u.light);
            if (u.semantic == UniformSemantic::LightFalloffAt) falloffs.insert(u.light);
        }
        CHECK(positions.size() == (lights ? lights : kMaxShadingLights));
        CHECK(falloffs.size() == (lights ? lights : kMaxShadingLights));
        // And each shadow map's sampler, matrix and texel, once each.
        std::set<int> maps, matrices, texels;
        for (const BoundUniform &u : p.uniforms) {
            if (u.semantic == UniformSemantic::ShadowMapAt) maps.insert(u.light);
            if (u.semantic == UniformSemantic::ShadowMatrixAt) matrices.insert(u.light);
            if (u.semantic == UniformSemantic::ShadowTexelAt) texels.insert(u.light);
        }
        CHECK(maps.size() == static_cast<size_t>(n));
        CHECK(matrices.size() == static_cast<size_t>(n));
        CHECK(texels.size() == static_cast<size_t>(n));
      }
    }
    CHECK_FALSE(programs.get(ANI_SHADE_SKYBOX_PASS).built_in);
    for (const std::string &line : log) UNSCOPED_INFO(line);
    CHECK(log.empty());
    CHECK(programs.fallbacks() == 0);
    CHECK(feature_names(ANI_SHADE_TEXTURE | ANI_SHADE_CEL) == "texture|cel");
    CHECK(feature_names(ANI_SHADE_TEXTURE | ANI_SHADE_SHADOW_MAPS(2)) == "texture|2 shadow maps");
    CHECK(feature_names(ANI_SHADE_SHADOW_MAPS(1) | ANI_SHADE_LIGHTS(3)) == "1 shadow map|3 lights");
    CHECK(feature_names(ANI_SHADE_LIGHTS(1) | (1u << 13)) == "1 light|bit 13");
    CHECK(feature_names(0) == "none");
}
