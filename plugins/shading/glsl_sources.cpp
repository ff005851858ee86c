#include "glsl_sources.hpp"

namespace shading {

// Shading happens in world space, so the reflected and refracted rays can sample the skybox
// directly (the seed computes them in eye space and transforms them back; the result is the same
// ray).
const char *const kModelVertexBody = R"glsl(
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 uv;

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform mat3 normal_matrix;

out vec3 world_position;
out vec3 world_normal;
out vec2 texcoord;

// Shadow maps of the first SHADOW_MAPS lights (the feature bits say how many, shading.h; none
// with shadows off): world to each map and a texel's width at distance 1 from its light. Each
// vertex hands the fragment stage its point in each map (shadow_at) and how far in the map a push
// along its normal by 1.5 texel widths at distance 1 goes (shadow_push); the map's projection is
// linear in homogeneous coordinates, so the interpolated values are exact there and the fragment
// stage, which llvmpipe runs for every pixel of each 4x4 block a triangle touches, only scales
// the push by its distance from the light (docs/performance.md).
#if SHADOW_MAPS > 0
uniform mat4 shadow_matrices[SHADOW_MAPS];
uniform float shadow_texels[SHADOW_MAPS];
out vec4 shadow_at[SHADOW_MAPS];
out vec4 shadow_push[SHADOW_MAPS];
#endif

void main() {
    vec4 world = model * vec4(position, 1.0);
    world_position = world.xyz;
    world_normal = normal_matrix * normal;
    texcoord = uv;
    gl_Position = projection * view * world;
#if SHADOW_MAPS > 0
    vec3 n = normalize(world_normal);
    for (int i = 0; i < SHADOW_MAPS; ++i) {
        shadow_at[i] = shadow_matrices[i] * world;
        shadow_push[i] = shadow_matrices[i] * vec4(n * (1.5 * shadow_texels[i]), 0.0);
    }
#endif
}
)glsl";

const char *const kModelFragmentBody = R"glsl(
in vec3 world_position;
in vec3 world_normal;
in vec2 texcoord;

uniform vec3 camera_position;
// The scene's lights (LIGHTS of them, fixed by the feature bits; without them light_count, at
// least 1): the light reaching a point at distance d is colour / (c0 + c1 d + c2 d^2), with
// falloff (c0, c1, c2).
#if LIGHTS > 0
uniform vec3 light_positions[LIGHTS];
uniform vec3 light_colours[LIGHTS];
uniform vec3 light_falloffs[LIGHTS];
#else
uniform int light_count;
uniform vec3 light_positions[MAX_LIGHTS];
uniform vec3 light_colours[MAX_LIGHTS];
uniform vec3 light_falloffs[MAX_LIGHTS];
#endif
uniform vec3 ambient;
uniform vec3 kd;
uniform vec3 ks;
uniform float shininess;
#ifdef TEXTURE
uniform sampler2D model_texture;
uniform float tint;
#endif
#if defined(REFLECTION) || defined(REFRACTION)
uniform samplerCube skybox;
#endif
#ifdef REFLECTION
uniform float reflectivity;
#endif
#ifdef REFRACTION
uniform float transparency;
uniform float refractive_index;
#endif
#ifdef CEL
uniform int cel_bands;
uniform int cel_outline;
uniform float cel_outline_width;
uniform vec4 cel_outline_colour;
#endif
#ifdef SELECTED
uniform vec4 selected_tint;
#endif
// The shadow maps (a depth comparison, lit outside them) and each one's point and push from the
// vertex stage.
#if SHADOW_MAPS > 0
in vec4 shadow_at[SHADOW_MAPS];
in vec4 shadow_push[SHADOW_MAPS];
uniform sampler2DShadow shadow_map0;
#endif
#if SHADOW_MAPS > 1
uniform sampler2DShadow shadow_map1;
#endif
#if SHADOW_MAPS > 2
uniform sampler2DShadow shadow_map2;
#endif
#if SHADOW_MAPS > 3
uniform sampler2DShadow shadow_map3;
#endif

out vec4 colour;

#if SHADOW_MAPS > 0
// How much of the light reaches p, 0..1: percentage-closer filtering (Reeves, Salesin and Cook
// 1987) over 2x2 bilinear comparisons half a texel either side, which weigh the 3x3 texels
// around p as a tent (1 2 1): a shadow's edge is soft over about three texels, at four lookups.
float lit_fraction(sampler2DShadow map, vec4 q) { // (q: the point in the map's clip space)
    if (q.w <= 0.0) return 1.0; // behind the light
    vec3 t = q.xyz / q.w;
    if (t.z >= 1.0) return 1.0; // beyond the map's far plane
    vec2 texel = 1.0 / vec2(textureSize(map, 0));
    float lit = texture(map, vec3(t.xy + vec2(-0.5, -0.5) * texel, t.z));
    lit += texture(map, vec3(t.xy + vec2(0.5, -0.5) * texel, t.z));
    lit += texture(map, vec3(t.xy + vec2(-0.5, 0.5) * texel, t.z));
    lit += texture(map, vec3(t.xy + vec2(0.5, 0.5) * texel, t.z));
    return lit * 0.25;
}

// Light i's share here, from its map: the point is pushed along its normal (the side it is seen
// from, as main()'s n) by 1.5 texels of the map there (normal offset), so a lit surface never
// shadows itself while its shadow stays attached (the host's depth pass adds a slope-scaled bias).
float light_share(sampler2DShadow map, int i) {
    float d = length(light_positions[i] - world_position);
    return lit_fraction(map, shadow_at[i] + (gl_FrontFacing ? d : -d) * shadow_push[i]);
}
#endif

// Adds light i's diffuse and specular light here to c, `share` of it reaching this point.
void add_light(inout vec3 c, int i, vec3 n, vec3 to_eye, vec3 base, float share) {
    vec3 d = light_positions[i] - world_position;
    float r = length(d);
    vec3 f = light_falloffs[i];
    vec3 light = light_colours[i] / (f.x + f.y * r + f.z * r * r);
    vec3 to_light = normalize(d);
    float diffuse = max(dot(n, to_light), 0.0);
    if (diffuse <= 0.0) return; // facing away: no light
    light *= share;
    c += light * base * diffuse;
    if (shininess < SHININESS_MAX) {
        float facing = max(dot(reflect(-to_light, n), to_eye), 0.0);
        c += light * ks * pow(max(facing, 1e-8), shininess);
    }
}

#ifdef CEL
// The seed's step10 with `bands` steps: n < i / bands gives i / bands, so 0 gives the first band
// and nothing is ever black.
float cel_step(float n, float bands) {
    return min(floor(n * bands) + 1.0, bands) / bands;
}
#endif

void main() {
    vec3 n = normalize(world_normal);
    if (!gl_FrontFacing) n = -n; // open meshes (a floor) are lit from either side
    vec3 to_eye = normalize(camera_position - world_position);

    vec3 base = kd;
#ifdef TEXTURE
    base = mix(texture(model_texture, texcoord).rgb, kd, tint);
#endif

    vec3 c = ambient * base;
    // The lights with a shadow map first, each written out with its own map: a software
    // rasterizer runs every branch, so a lookup chosen by the light's index would be paid for
    // every map at every light. Then the others.
#if SHADOW_MAPS > 0
    add_light(c, 0, n, to_eye, base, light_share(shadow_map0, 0));
#endif
#if SHADOW_MAPS > 1
    add_light(c, 1, n, to_eye, base, light_share(shadow_map1, 1));
#endif
#if SHADOW_MAPS > 2
    add_light(c, 2, n, to_eye, base, light_share(shadow_map2, 2));
#endif
#if SHADOW_MAPS > 3
    add_light(c, 3, n, to_eye, base, light_share(shadow_map3, 3));
#endif
    // A loop over a count fixed here is unrolled with constant indices; one bounded by the
    // light_count uniform is run by llvmpipe for every pixel with variable indices into the
    // lights' arrays, which cost half of a plain frame (docs/performance.md).
#if LIGHTS > 0
    for (int i = SHADOW_MAPS; i < LIGHTS; ++i)
        add_light(c, i, n, to_eye, base, 1.0);
#else
    for (int i = SHADOW_MAPS; i < MAX_LIGHTS && i < light_count; ++i)
        add_light(c, i, n, to_eye, base, 1.0);
#endif

#ifdef REFLECTION
    c = mix(c, texture(skybox, reflect(-to_eye, n)).rgb, reflectivity);
#endif
#ifdef REFRACTION
    vec3 refracted = refract(-to_eye, n, 1.0 / refractive_index);
    if (dot(refracted, refracted) == 0.0) refracted = reflect(-to_eye, n); // total internal reflection
    c = mix(c, texture(skybox, refracted).rgb, transparency);
#endif

#ifdef CEL
    // Snapped after every light is summed: one light looks as it always did, and where lights
    // overlap their sum steps up a band (and stops at the top one, as any colour above 1 does).
    float bands = float(cel_bands);
    c = vec3(cel_step(c.r, bands), cel_step(c.g, bands), cel_step(c.b, bands));
    if (cel_outline != 0) {
        // Near a smooth surface's silhouette the normal turns away from the eye: within
        // `cel_outline_width` pixels of where it would be perpendicular, draw the outline.
        float facing = dot(n, to_eye);
        if (facing < cel_outline_width * fwidth(facing)) c = cel_outline_colour.rgb;
    }
#endif

#ifdef SELECTED
    c = mix(c, selected_tint.rgb, selected_tint.a);
#endif
    colour = vec4(c, 1.0);
}
)glsl";

// The seed's skybox: a cube around the camera turned by the camera's rotation only, so its sides
// seem infinitely far away. The host draws it behind the models, where none is
// (Renderer::draw_skybox).
const char *const kSkyboxVertexBody = R"glsl(
layout(location = 0) in vec3 position;

uniform mat4 view;
uniform mat4 projection;

out vec3 direction;

void main() {
    direction = position;
    gl_Position = projection * mat4(mat3(view)) * vec4(position, 1.0);
}
)glsl";

const char *const kSkyboxFragmentBody = R"glsl(
in vec3 direction;

uniform samplerCube skybox;

out vec4 colour;

void main() {
    // At the least level the host's sampler allows: the level that fits the view (docs/sdk.md),
    // without each pixel's own worked out from its neighbours' directions.
    colour = vec4(textureLod(skybox, direction, 0.0).rgb, 1.0);
}
)glsl";

} // namespace shading
