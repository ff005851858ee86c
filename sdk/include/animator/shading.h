/* animator plugin SDK: shading models (ANI_KIND_SHADING).
 *
 * A shading model hands the host GLSL (330 core) source and the uniforms it needs; the host
 * compiles, binds and fills them. No GL call happens in a plugin.
 */
#ifndef ANIMATOR_SDK_SHADING_H
#define ANIMATOR_SDK_SHADING_H

#include "animator/instance.h"

#ifdef __cplusplus
extern "C" {
#endif

/* What a draw needs; the host asks for the program of exactly the features in use, so a scene
 * without them does not pay for them. */
typedef enum ani_shading_feature {
    ANI_SHADE_TEXTURE = 1 << 0,
    ANI_SHADE_REFLECTION = 1 << 1,
    ANI_SHADE_REFRACTION = 1 << 2,
    ANI_SHADE_CEL = 1 << 3,
    ANI_SHADE_SELECTED = 1 << 4,
    /* The program that draws the skybox itself. The host binds with the skybox a sampler whose
     * least level of detail fits the view: `textureLod(skybox, d, 0.0)` samples that level
     * without each pixel's own worked out (docs/sdk.md); `texture()` works too, slower. */
    ANI_SHADE_SKYBOX_PASS = 1 << 5
} ani_shading_feature;

typedef enum ani_uniform_type {
    ANI_UNIFORM_FLOAT = 1,
    ANI_UNIFORM_INT = 2,
    ANI_UNIFORM_VEC3 = 3,
    ANI_UNIFORM_VEC4 = 4,
    ANI_UNIFORM_MAT3 = 5,
    ANI_UNIFORM_MAT4 = 6,
    ANI_UNIFORM_SAMPLER_2D = 7,
    ANI_UNIFORM_SAMPLER_CUBE = 8,
    ANI_UNIFORM_SAMPLER_2D_SHADOW = 9 /* ABI 1.9: a depth map with comparison, sampler2DShadow */
} ani_uniform_type;

/* ABI 1.9: the most lights with a shadow map (the first ones of the scene's). */
#define ANI_MAX_SHADOW_LIGHTS 4

/* Since ABI 1.10: how many shadow maps a model's program reads, 0 to ANI_MAX_SHADOW_LIGHTS, in
 * the feature bits above ANI_SHADE_SKYBOX_PASS: features & ANI_SHADE_SHADOW_MAPS_MASK is
 * ANI_SHADE_SHADOW_MAPS(n), and "shadow_lights" is then n for every draw with it. A program for 0
 * reads none and need not declare their uniforms. Why it is a feature and not only a uniform: a
 * software rasterizer (Mesa's llvmpipe) runs both sides of every branch of a fragment shader for
 * all its pixels at once, so a shadow lookup behind `if (i < shadow_lights)` costs its full price
 * with shadows off (docs/performance.md). A host asks for these bits only of a plugin built for
 * ABI 1.10 or newer; an older plugin's programs read "shadow_lights" as before. */
#define ANI_SHADE_SHADOW_MAPS_SHIFT 6
#define ANI_SHADE_SHADOW_MAPS_MASK (7u << ANI_SHADE_SHADOW_MAPS_SHIFT)
#define ANI_SHADE_SHADOW_MAPS(n) ((uint32_t)(n) << ANI_SHADE_SHADOW_MAPS_SHIFT)
/* The n of a feature set's ANI_SHADE_SHADOW_MAPS(n). */
#define ANI_SHADE_SHADOW_MAP_COUNT(features)                                                       \
    (((uint32_t)(features) & ANI_SHADE_SHADOW_MAPS_MASK) >> ANI_SHADE_SHADOW_MAPS_SHIFT)

/* Since ABI 1.11: how many of the scene's lights a model's program adds up, 1 to ANI_MAX_LIGHTS
 * (document.h), in the four bits above the shadow maps': features & ANI_SHADE_LIGHTS_MASK is
 * ANI_SHADE_LIGHTS(n), and "light_count" is then n for every draw with it, so the program may
 * loop over a count fixed when it is compiled and read only those lights' uniforms. 0 (no bits)
 * says nothing: the program reads "light_count" (so does every program of an older plugin). Why:
 * llvmpipe runs a loop bounded by a uniform, and indexes the lights' arrays with a variable, for
 * every pixel at a cost that halved the frame rate of a plain scene with one light
 * (docs/performance.md). A host asks for these bits only of a plugin built for ABI 1.11 or newer. */
#define ANI_SHADE_LIGHTS_SHIFT 9
#define ANI_SHADE_LIGHTS_MASK (15u << ANI_SHADE_LIGHTS_SHIFT)
#define ANI_SHADE_LIGHTS(n) ((uint32_t)(n) << ANI_SHADE_LIGHTS_SHIFT)
/* The n of a feature set's ANI_SHADE_LIGHTS(n) (0: not said). */
#define ANI_SHADE_LIGHT_COUNT(features)                                                            \
    (((uint32_t)(features) & ANI_SHADE_LIGHTS_MASK) >> ANI_SHADE_LIGHTS_SHIFT)

/* A uniform and what the host puts in it. Semantics (docs/sdk.md lists them): "model",
 * "view", "projection", "normal_matrix", "camera_position", "light_position", "light_colour",
 * "ambient", "kd", "ks", "shininess", "tint", "reflectivity", "transparency",
 * "refractive_index", "texture", "skybox", "selected_tint", and "param:<id>" for the value of
 * one of the plugin's own parameters; since the scene's lights (appended, no ABI change):
 * "light_count", and "light_position:N", "light_colour:N", "light_falloff:N" for N in 0..7;
 * since ABI 1.9 (shadows): "shadow_lights", and "shadow_matrix:N", "shadow_map:N",
 * "shadow_texel:N" for N in 0..3. */
typedef struct ani_uniform_desc {
    const char *name; /* as in the GLSL */
    int32_t type;     /* ani_uniform_type */
    const char *semantic;
} ani_uniform_desc;

typedef struct ani_shader_program {
    uint32_t struct_size;
    const char *vertex_source;
    const char *fragment_source;
    const ani_uniform_desc *uniforms;
    uint32_t uniform_count;
} ani_shader_program;

typedef struct ani_shading_api {
    uint32_t struct_size;
    ani_instance_api instance;
    /* The program for a set of ani_shading_feature bits. The strings stay valid until the
     * instance is destroyed. */
    ani_status_code (*get_program)(void *instance, uint32_t features, ani_shader_program *program,
                                   ani_status *status);
} ani_shading_api;

/* ---- conventions (appended; no ABI change) ---------------------------------------------- */

/* Vertex inputs the host provides, as `layout(location = N) in` in the GLSL: a model's position
 * and normal in model space and its texture coordinates (v up, the OBJ convention). The skybox
 * pass gets only the position: the corners of a cube from -1 to 1. The fragment output is
 * location 0. */
#define ANI_VERTEX_POSITION 0
#define ANI_VERTEX_NORMAL 1
#define ANI_VERTEX_UV 2

/* Shininess at or above this turns specular light off (the seed's Model Interface: "to turn off
 * specular lighting, drag it to the maximum value"); the editor's slider ends here. 128 is the
 * range of OpenGL's classic GL_SHININESS. */
#define ANI_SHININESS_MAX 128.0

/* What the host puts in each semantic (shading happens in world space):
 *   model            mat4  model to world           view        mat4  world to camera
 *   projection       mat4  camera to clip           normal_matrix mat3 model to world, normals
 *   camera_position  vec3  world                    light_position vec3 world
 *   light_colour     vec3                           ambient     vec3  ambient light
 *   kd, ks           vec3  the model's colours      shininess   float the Phong exponent
 *   tint             float how much kd replaces the texture's colour, 0..1
 *   reflectivity, transparency  float 0..1          refractive_index float the model's (air: 1)
 *   texture          sampler2D the model's texture  skybox      samplerCube the scene's skybox
 *   selected_tint    vec4  rgb, and in alpha how much of it covers a selected model
 *   param:<id>       float, int, vec3 or vec4: the plugin parameter's value[0..n)
 * The skybox pass gets view, projection and skybox; it drops the view's translation itself.
 *
 * The scene's lights (appended; a plugin that reads only light_position and light_colour gets
 * light 0, the first of the document's or, when it has none, the one riding with the camera):
 *   light_count      int   how many lights are in use, 1..ANI_MAX_LIGHTS (8, document.h)
 *   light_position:N vec3  world, light N (N a single digit, 0..7)
 *   light_colour:N   vec3  its colour, >= 0, may exceed 1; 0 for N >= light_count
 *   light_falloff:N  vec3  (c0, c1, c2): the light reaching distance d is
 *                          colour / (c0 + c1 d + c2 d^2); (1, 0, 0) for the camera's light and
 *                          for N >= light_count
 * A uniform array element may carry one ("light_positions[3]" with "light_position:3").
 *
 * Shadows (ABI 1.9; a plugin built for 1.8 or before gets none and draws as it did):
 *   shadow_lights    int   how many lights have a shadow map: lights 0..shadow_lights-1, at
 *                          most ANI_MAX_SHADOW_LIGHTS; 0 when shadows are off
 *   shadow_matrix:N  mat4  world to light N's map: p = shadow_matrix * vec4(world, 1), then
 *                          p.xyz / p.w has x and y 0..1 across the map and z its depth 0..1
 *   shadow_map:N     sampler2DShadow  light N's map, compare mode LEQUAL, linear (each lookup
 *                          is a 2x2 percentage-closer filter); outside the map is lit
 *   shadow_texel:N   float the width of one of the map's texels at distance 1 from light N (at
 *                          distance d, d times it): push the point along its normal (towards
 *                          the light) by about 1.5 texels before the lookup, so a surface does
 *                          not shadow itself; the host's depth pass adds a slope-scaled bias
 * A map is bound only while shadow_lights says it is in use: look one up only for N below it. */

#ifdef __cplusplus
}
#endif

#endif /* ANIMATOR_SDK_SHADING_H */
