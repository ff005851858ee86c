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
    Param, // "param:<id>": one of the plugin's own parameters
};

// The semantic named `text`, or nothing for one the host does not know. For "param:<id>",
// `param_id` receives the id.
std::optional<UniformSemantic> parse_semantic(const std::string &text, std::string &param_id);

// Whether the host can fill a uniform of `type` with `semantic` (a parameter: float, int, vec3 or
// vec4; the others: the one type shading.h gives them).
bool semantic_accepts(UniformSemantic semantic, ani_uniform_type type);

} // namespace animator
