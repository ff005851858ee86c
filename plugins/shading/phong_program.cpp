#include "phong_program.hpp"

#include "glsl_sources.hpp"

#include <animator/document.h>

#include <cstdio>
#include <iterator>

namespace shading {

namespace {

std::string header(uint32_t features) {
    std::string h = "#version 330 core\n";
    char max_line[64];
    (void)std::snprintf(max_line, sizeof max_line, "#define SHININESS_MAX %.1f\n",
                        ANI_SHININESS_MAX);
    h += max_line;
    (void)std::snprintf(max_line, sizeof max_line, "#define MAX_LIGHTS %d\n", ANI_MAX_LIGHTS);
    h += max_line;
    (void)std::snprintf(max_line, sizeof max_line, "#define SHADOW_MAPS %d\n",
                        shadow_maps(features));
    h += max_line;
    (void)std::snprintf(max_line, sizeof max_line, "#define LIGHTS %d\n", lights(features));
    h += max_line;
    if (features & ANI_SHADE_TEXTURE) h += "#define TEXTURE 1\n";
    if (features & ANI_SHADE_REFLECTION) h += "#define REFLECTION 1\n";
    if (features & ANI_SHADE_REFRACTION) h += "#define REFRACTION 1\n";
    if (features & ANI_SHADE_CEL) h += "#define CEL 1\n";
    if (features & ANI_SHADE_SELECTED) h += "#define SELECTED 1\n";
    return h;
}

void add(std::vector<ani_uniform_desc> &uniforms, const char *name, ani_uniform_type type,
         const char *semantic) {
    uniforms.push_back({name, type, semantic});
}

// Each light's uniforms: an element of the GLSL's arrays, and its semantic (shading.h).
// clang-format off
#define LIGHT_UNIFORMS(N)                                                                          \
    {"light_positions[" #N "]", ANI_UNIFORM_VEC3, "light_position:" #N},                           \
    {"light_colours[" #N "]", ANI_UNIFORM_VEC3, "light_colour:" #N},                               \
    {"light_falloffs[" #N "]", ANI_UNIFORM_VEC3, "light_falloff:" #N}
// clang-format on
const ani_uniform_desc kLightUniforms[] = {LIGHT_UNIFORMS(0), LIGHT_UNIFORMS(1), LIGHT_UNIFORMS(2),
                                           LIGHT_UNIFORMS(3), LIGHT_UNIFORMS(4), LIGHT_UNIFORMS(5),
                                           LIGHT_UNIFORMS(6), LIGHT_UNIFORMS(7)};
#undef LIGHT_UNIFORMS
static_assert(sizeof kLightUniforms / sizeof kLightUniforms[0] == 3 * ANI_MAX_LIGHTS);

// Each shadow map's uniforms (ABI 1.9, shading.h).
// clang-format off
#define SHADOW_UNIFORMS(N)                                                                         \
    {"shadow_matrices[" #N "]", ANI_UNIFORM_MAT4, "shadow_matrix:" #N},                            \
    {"shadow_texels[" #N "]", ANI_UNIFORM_FLOAT, "shadow_texel:" #N},                              \
    {"shadow_map" #N, ANI_UNIFORM_SAMPLER_2D_SHADOW, "shadow_map:" #N}
// clang-format on
const ani_uniform_desc kShadowUniforms[] = {SHADOW_UNIFORMS(0), SHADOW_UNIFORMS(1),
                                            SHADOW_UNIFORMS(2), SHADOW_UNIFORMS(3)};
#undef SHADOW_UNIFORMS
static_assert(sizeof kShadowUniforms / sizeof kShadowUniforms[0] == 3 * ANI_MAX_SHADOW_LIGHTS);

} // namespace

std::string check_features(uint32_t features) {
    if (features & ~kKnownFeatures) return "unknown shading feature bits";
    if (shadow_maps(features) > ANI_MAX_SHADOW_LIGHTS) return "more shadow maps than it can read";
    if (lights(features) > ANI_MAX_LIGHTS) return "more lights than a scene has";
    if (lights(features) > 0 && lights(features) < shadow_maps(features))
        return "fewer lights than shadow maps";
    if ((features & ANI_SHADE_SKYBOX_PASS) && features != ANI_SHADE_SKYBOX_PASS)
        return "the skybox pass takes no other feature";
    return "";
}

ProgramSource build_program(uint32_t features) {
    ProgramSource p;
    const std::string h = header(features);
    auto &u = p.uniforms;
    add(u, "view", ANI_UNIFORM_MAT4, "view");
    add(u, "projection", ANI_UNIFORM_MAT4, "projection");
    if (features == ANI_SHADE_SKYBOX_PASS) {
        p.vertex = h + kSkyboxVertexBody;
        p.fragment = h + kSkyboxFragmentBody;
        add(u, "skybox", ANI_UNIFORM_SAMPLER_CUBE, "skybox");
        return p;
    }
    p.vertex = h + kModelVertexBody;
    p.fragment = h + kModelFragmentBody;
    add(u, "model", ANI_UNIFORM_MAT4, "model");
    add(u, "normal_matrix", ANI_UNIFORM_MAT3, "normal_matrix");
    add(u, "camera_position", ANI_UNIFORM_VEC3, "camera_position");
    // The lights it adds up: as many as the feature bits say (ABI 1.11), or every one of them up
    // to "light_count" when they do not say.
    if (const int n = lights(features); n > 0) {
        u.insert(u.end(), std::begin(kLightUniforms), std::begin(kLightUniforms) + 3 * n);
    } else {
        add(u, "light_count", ANI_UNIFORM_INT, "light_count");
        u.insert(u.end(), std::begin(kLightUniforms), std::end(kLightUniforms));
    }
    // The shadow maps it reads, their number fixed by the feature bits (shading.h, ABI 1.10).
    u.insert(u.end(), std::begin(kShadowUniforms), std::begin(kShadowUniforms) + 3 * shadow_maps(features));
    add(u, "ambient", ANI_UNIFORM_VEC3, "ambient");
    add(u, "kd", ANI_UNIFORM_VEC3, "kd");
    add(u, "ks", ANI_UNIFORM_VEC3, "ks");
    add(u, "shininess", ANI_UNIFORM_FLOAT, "shininess");
    if (features & ANI_SHADE_TEXTURE) {
        add(u, "model_texture", ANI_UNIFORM_SAMPLER_2D, "texture");
        add(u, "tint", ANI_UNIFORM_FLOAT, "tint");
    }
    if (features & (ANI_SHADE_REFLECTION | ANI_SHADE_REFRACTION))
        add(u, "skybox", ANI_UNIFORM_SAMPLER_CUBE, "skybox");
    if (features & ANI_SHADE_REFLECTION) add(u, "reflectivity", ANI_UNIFORM_FLOAT, "reflectivity");
    if (features & ANI_SHADE_REFRACTION) {
        add(u, "transparency", ANI_UNIFORM_FLOAT, "transparency");
        add(u, "refractive_index", ANI_UNIFORM_FLOAT, "refractive_index");
    }
    if (features & ANI_SHADE_CEL) {
        add(u, "cel_bands", ANI_UNIFORM_INT, "param:cel_bands");
        add(u, "cel_outline", ANI_UNIFORM_INT, "param:cel_outline");
        add(u, "cel_outline_width", ANI_UNIFORM_FLOAT, "param:cel_outline_width");
        add(u, "cel_outline_colour", ANI_UNIFORM_VEC4, "param:cel_outline_colour");
    }
    if (features & ANI_SHADE_SELECTED) add(u, "selected_tint", ANI_UNIFORM_VEC4, "selected_tint");
    return p;
}

} // namespace shading
