#include "render/uniform_semantics.hpp"

#include <utility>

namespace animator {

namespace {

struct Known {
    const char *name;
    UniformSemantic semantic;
    ani_uniform_type type;
};

constexpr Known kKnown[] = {
    {"model", UniformSemantic::Model, ANI_UNIFORM_MAT4},
    {"view", UniformSemantic::View, ANI_UNIFORM_MAT4},
    {"projection", UniformSemantic::Projection, ANI_UNIFORM_MAT4},
    {"normal_matrix", UniformSemantic::NormalMatrix, ANI_UNIFORM_MAT3},
    {"camera_position", UniformSemantic::CameraPosition, ANI_UNIFORM_VEC3},
    {"light_position", UniformSemantic::LightPosition, ANI_UNIFORM_VEC3},
    {"light_colour", UniformSemantic::LightColour, ANI_UNIFORM_VEC3},
    {"ambient", UniformSemantic::Ambient, ANI_UNIFORM_VEC3},
    {"kd", UniformSemantic::Kd, ANI_UNIFORM_VEC3},
    {"ks", UniformSemantic::Ks, ANI_UNIFORM_VEC3},
    {"shininess", UniformSemantic::Shininess, ANI_UNIFORM_FLOAT},
    {"tint", UniformSemantic::Tint, ANI_UNIFORM_FLOAT},
    {"reflectivity", UniformSemantic::Reflectivity, ANI_UNIFORM_FLOAT},
    {"transparency", UniformSemantic::Transparency, ANI_UNIFORM_FLOAT},
    {"refractive_index", UniformSemantic::RefractiveIndex, ANI_UNIFORM_FLOAT},
    {"texture", UniformSemantic::Texture, ANI_UNIFORM_SAMPLER_2D},
    {"skybox", UniformSemantic::Skybox, ANI_UNIFORM_SAMPLER_CUBE},
    {"selected_tint", UniformSemantic::SelectedTint, ANI_UNIFORM_VEC4},
    {"light_count", UniformSemantic::LightCount, ANI_UNIFORM_INT},
    {"shadow_lights", UniformSemantic::ShadowLights, ANI_UNIFORM_INT},
};

// "light_position:N" and the like: one of the scene's lights, N in 0..kMaxShadingLights-1.
constexpr Known kPerLight[] = {
    {"light_position:", UniformSemantic::LightPositionAt, ANI_UNIFORM_VEC3},
    {"light_colour:", UniformSemantic::LightColourAt, ANI_UNIFORM_VEC3},
    {"light_falloff:", UniformSemantic::LightFalloffAt, ANI_UNIFORM_VEC3},
};

// "shadow_map:N" and the like: the shadow map of light N, N in 0..kMaxShadowSemantics-1.
constexpr Known kPerShadow[] = {
    {"shadow_matrix:", UniformSemantic::ShadowMatrixAt, ANI_UNIFORM_MAT4},
    {"shadow_map:", UniformSemantic::ShadowMapAt, ANI_UNIFORM_SAMPLER_2D_SHADOW},
    {"shadow_texel:", UniformSemantic::ShadowTexelAt, ANI_UNIFORM_FLOAT},
};

constexpr const char kParamPrefix[] = "param:";

// N of "<prefix>N": one decimal digit below `count`, nothing else; -1 otherwise.
int light_index(const std::string &text, const std::string &prefix, int count = kMaxShadingLights) {
    if (text.size() != prefix.size() + 1 || text.compare(0, prefix.size(), prefix) != 0) return -1;
    const int n = text.back() - '0';
    return n >= 0 && n < count ? n : -1;
}

} // namespace

std::optional<UniformSemantic> parse_semantic(const std::string &text, std::string &param_id,
                                              int *light) {
    const std::string prefix = kParamPrefix;
    if (text.size() > prefix.size() && text.compare(0, prefix.size(), prefix) == 0) {
        param_id = text.substr(prefix.size());
        return UniformSemantic::Param;
    }
    for (const Known &k : kPerLight) {
        const int n = light_index(text, k.name);
        if (n < 0) continue;
        if (light) *light = n;
        return k.semantic;
    }
    for (const Known &k : kPerShadow) {
        const int n = light_index(text, k.name, kMaxShadowSemantics);
        if (n < 0) continue;
        if (light) *light = n;
        return k.semantic;
    }
    for (const Known &k : kKnown)
        if (text == k.name) return k.semantic;
    return std::nullopt;
}

bool semantic_accepts(UniformSemantic semantic, ani_uniform_type type) {
    if (semantic == UniformSemantic::Param)
        return type == ANI_UNIFORM_FLOAT || type == ANI_UNIFORM_INT || type == ANI_UNIFORM_VEC3 ||
               type == ANI_UNIFORM_VEC4;
    for (const Known &k : kKnown)
        if (k.semantic == semantic) return k.type == type;
    for (const Known &k : kPerLight)
        if (k.semantic == semantic) return k.type == type;
    for (const Known &k : kPerShadow)
        if (k.semantic == semantic) return k.type == type;
    return false;
}

} // namespace animator
