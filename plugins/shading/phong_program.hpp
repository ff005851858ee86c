// The Phong shading model's program for a set of features: GLSL 330 core source with one
// `#define` per feature, and exactly the uniforms those features read.
#pragma once

#include <animator/shading.h>

#include <cstdint>
#include <string>
#include <vector>

namespace shading {

// Every feature bit the plugin knows.
constexpr uint32_t kKnownFeatures = ANI_SHADE_TEXTURE | ANI_SHADE_REFLECTION |
                                    ANI_SHADE_REFRACTION | ANI_SHADE_CEL | ANI_SHADE_SELECTED |
                                    ANI_SHADE_SKYBOX_PASS | ANI_SHADE_SHADOW_MAPS_MASK |
                                    ANI_SHADE_LIGHTS_MASK;

// How many shadow maps a feature set's program reads (ABI 1.10).
inline int shadow_maps(uint32_t features) {
    return static_cast<int>(ANI_SHADE_SHADOW_MAP_COUNT(features));
}

// How many lights a feature set's program adds up (ABI 1.11): 1..ANI_MAX_LIGHTS, or 0 when the
// bits do not say, and the program loops over the uniform "light_count".
inline int lights(uint32_t features) {
    return static_cast<int>(ANI_SHADE_LIGHT_COUNT(features));
}

struct ProgramSource {
    std::string vertex;
    std::string fragment;
    std::vector<ani_uniform_desc> uniforms; // names and semantics are string literals
};

// "" when `features` is a set this model can draw, else why not (an unknown bit, more shadow maps
// than ANI_MAX_SHADOW_LIGHTS, more lights than ANI_MAX_LIGHTS or fewer than shadow maps, or the
// skybox pass combined with a model feature).
std::string check_features(uint32_t features);

// The program for a valid feature set (check_features first).
ProgramSource build_program(uint32_t features);

} // namespace shading
