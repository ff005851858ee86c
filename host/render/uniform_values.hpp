// Filling a linked program's uniforms from their semantics (shading.h): what is the same for the
// whole frame, and what belongs to one model.
#pragma once

#include "render/shading_programs.hpp"

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>

namespace animator {

struct FrameUniforms {
    glm::mat4 view{1.0f}, projection{1.0f};
    glm::vec3 camera_position{0.0f}, ambient{0.0f};
    // The lights in use, 1..kMaxShadingLights of them; "light_position" and "light_colour" are
    // the first one's. Falloff (c0, c1, c2): the light reaching distance d is colour / (c0 + c1 d +
    // c2 d^2).
    int light_count = 1;
    std::array<glm::vec3, kMaxShadingLights> light_position{}, light_colour{}, light_falloff{};
    glm::vec4 selected_tint{0.0f}; // the colour and how much of it covers a selected model
    // Lights 0..shadow_lights-1 have a shadow map (shadow_pass.hpp): world to map, and a texel's
    // width at distance 1 from the light.
    int shadow_lights = 0;
    std::array<glm::mat4, kMaxShadowSemantics> shadow_matrix{};
    std::array<float, kMaxShadowSemantics> shadow_texel{};
};

struct ModelUniforms {
    glm::mat4 model{1.0f};
    glm::mat3 normal_matrix{1.0f};
    glm::vec3 kd{0.0f}, ks{0.0f};
    float shininess = 0.0f, tint = 0.0f, reflectivity = 0.0f, transparency = 0.0f;
    float refractive_index = 1.0f;
    bool selected = false; // an unselected model gets selected_tint with alpha 0
};

// Sets every uniform of `program` (which must be in use). `model` is null for the skybox pass.
// Samplers were set to their units when the program was linked.
void apply_uniforms(const LinkedProgram &program, const ShadingPrograms &programs,
                    const FrameUniforms &frame, const ModelUniforms *model);

} // namespace animator
