// The uniform semantics of the SDK (shading.h): what the host puts in a shading plugin's uniform,
// parsed once when a program is linked so that a draw compares no strings.
#pragma once

#include <animator/shading.h>

#include <optional>
#include <string>

namespace animator {

enum class UniformSemantic {
    Model,
    View,
    Projection,
    NormalMatrix,
    CameraPosition,
    LightPosition,
    LightColour,
    Ambient,
    Kd,
    Ks,
    Shininess,
    Tint,
    Reflectivity,
    Transparency,
    RefractiveIndex,
    Texture,
    Skybox,
    SelectedTint,
    Param,           // "param:<id>": one of the plugin's own parameters
    LightCount,      // "light_count": how many of the lights below are in use, 1..8
    LightPositionAt, // "light_position:N", N in 0..kMaxShadingLights-1
    LightColourAt,   // "light_colour:N"
    LightFalloffAt,  // "light_falloff:N": (c0, c1, c2); at d, colour / (c0 + c1 d + c2 d^2)
    // Since ABI 1.9: shadow maps of the first lights (shadow_pass.hpp).
    ShadowLights,   // "shadow_lights": how many lights (0..kMaxShadowLights) have a shadow map
    ShadowMatrixAt, // "shadow_matrix:N": world to light N's map (x, y 0..1, z the depth 0..1)
    ShadowMapAt,    // "shadow_map:N": light N's map, a sampler2DShadow
    ShadowTexelAt,  // "shadow_texel:N": a texel's width at distance 1 from light N
};

// The most lights a program is given (ANI_MAX_LIGHTS).
constexpr int kMaxShadingLights = 8;
// The most lights with a shadow map (ANI_MAX_SHADOW_LIGHTS): N of "shadow_map:N" is below it.
constexpr int kMaxShadowSemantics = 4;

// The semantic named `text`, or nothing for one the host does not know. For "param:<id>",
// `param_id` receives the id; for "light_position:N", "shadow_map:N" and the other lights'
// semantics, `light` (when given) receives N.
std::optional<UniformSemantic> parse_semantic(const std::string &text, std::string &param_id,
                                              int *light = nullptr);

// Whether the host can fill a uniform of `type` with `semantic` (a parameter: float, int, vec3 or
// vec4; the others: the one type shading.h gives them).
bool semantic_accepts(UniformSemantic semantic, ani_uniform_type type);

} // namespace animator
