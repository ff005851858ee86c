#include "render/built_in_shading.hpp"

namespace animator {

namespace {

const char *const kModelVertex = R"glsl(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform mat3 normal_matrix;
out vec3 world_position;
out vec3 world_normal;
void main() {
    vec4 world = model * vec4(position, 1.0);
    world_position = world.xyz;
    world_normal = normal_matrix * normal;
    gl_Position = projection * view * world;
}
)glsl";

const char *const kModelFragment = R"glsl(#version 330 core
in vec3 world_position;
in vec3 world_normal;
uniform vec3 camera_position;
uniform int light_count;
uniform vec3 light_positions[8];
uniform vec3 light_colours[8];
uniform vec3 light_falloffs[8];
uniform vec3 ambient;
uniform vec3 kd;
uniform vec3 ks;
uniform float shininess;
uniform vec4 selected_tint;
out vec4 colour;
void main() {
    vec3 n = normalize(world_normal);
    if (!gl_FrontFacing) n = -n;
    vec3 to_eye = normalize(camera_position - world_position);
    vec3 c = ambient * kd;
    for (int i = 0; i < 8 && i < light_count; ++i) {
        vec3 d = light_positions[i] - world_position;
        float r = length(d);
        vec3 f = light_falloffs[i];
        vec3 light = light_colours[i] / (f.x + f.y * r + f.z * r * r);
        vec3 to_light = normalize(d);
        float diffuse = max(dot(n, to_light), 0.0);
        c += light * kd * diffuse;
        if (shininess < 128.0 && diffuse > 0.0) // ANI_SHININESS_MAX
            c += light * ks * pow(max(dot(reflect(-to_light, n), to_eye), 1e-8), shininess);
    }
    colour = vec4(mix(c, selected_tint.rgb, selected_tint.a), 1.0);
}
)glsl";

// clang-format off
#define ANI_LIGHT_UNIFORMS(N)                                                                      \
    {"light_positions[" #N "]", ANI_UNIFORM_VEC3, "light_position:" #N},                           \
    {"light_colours[" #N "]", ANI_UNIFORM_VEC3, "light_colour:" #N},                               \
    {"light_falloffs[" #N "]", ANI_UNIFORM_VEC3, "light_falloff:" #N}
// clang-format on

const ani_uniform_desc kModelUniforms[] = {
    {"model", ANI_UNIFORM_MAT4, "model"},
    {"view", ANI_UNIFORM_MAT4, "view"},
    {"projection", ANI_UNIFORM_MAT4, "projection"},
    {"normal_matrix", ANI_UNIFORM_MAT3, "normal_matrix"},
    {"camera_position", ANI_UNIFORM_VEC3, "camera_position"},
    {"light_count", ANI_UNIFORM_INT, "light_count"},
    ANI_LIGHT_UNIFORMS(0),
    ANI_LIGHT_UNIFORMS(1),
    ANI_LIGHT_UNIFORMS(2),
    ANI_LIGHT_UNIFORMS(3),
    ANI_LIGHT_UNIFORMS(4),
    ANI_LIGHT_UNIFORMS(5),
    ANI_LIGHT_UNIFORMS(6),
    ANI_LIGHT_UNIFORMS(7),
    {"ambient", ANI_UNIFORM_VEC3, "ambient"},
    {"kd", ANI_UNIFORM_VEC3, "kd"},
    {"ks", ANI_UNIFORM_VEC3, "ks"},
    {"shininess", ANI_UNIFORM_FLOAT, "shininess"},
    {"selected_tint", ANI_UNIFORM_VEC4, "selected_tint"},
};

#undef ANI_LIGHT_UNIFORMS

const char *const kSkyboxVertex = R"glsl(#version 330 core
layout(location = 0) in vec3 position;
uniform mat4 view;
uniform mat4 projection;
out vec3 direction;
void main() {
    direction = position;
    gl_Position = projection * mat4(mat3(view)) * vec4(position, 1.0);
}
)glsl";

const char *const kSkyboxFragment = R"glsl(#version 330 core
in vec3 direction;
uniform samplerCube skybox;
out vec4 colour;
// At the level the host's sampler sets for the view (docs/sdk.md).
void main() { colour = vec4(textureLod(skybox, direction, 0.0).rgb, 1.0); }
)glsl";

const ani_uniform_desc kSkyboxUniforms[] = {
    {"view", ANI_UNIFORM_MAT4, "view"},
    {"projection", ANI_UNIFORM_MAT4, "projection"},
    {"skybox", ANI_UNIFORM_SAMPLER_CUBE, "skybox"},
};

template <size_t N> uint32_t count(const ani_uniform_desc (&)[N]) {
    return N;
}

} // namespace

ani_shader_program built_in_program(bool skybox_pass) {
    if (skybox_pass)
        return {sizeof(ani_shader_program), kSkyboxVertex, kSkyboxFragment, kSkyboxUniforms,
                count(kSkyboxUniforms)};
    return {sizeof(ani_shader_program), kModelVertex, kModelFragment, kModelUniforms,
            count(kModelUniforms)};
}

} // namespace animator
