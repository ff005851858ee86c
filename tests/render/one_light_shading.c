/* A shading plugin written before the scene's lights: it reads only "light_position" and
 * "light_colour" (shading.h), so the tests can check those still mean light 0 of a document with
 * several lights. Diffuse light only, without falloff. Built for ABI 1.9, it refuses feature bits
 * it does not know, as shading.phong of 1.9 did: a host must not ask it for the shadow-map bits
 * of 1.10. */
#include "animator/shading.h"

static const char *const vertex_source = "#version 330 core\n"
                                         "layout(location = 0) in vec3 position;\n"
                                         "layout(location = 1) in vec3 normal;\n"
                                         "uniform mat4 model;\n"
                                         "uniform mat4 view;\n"
                                         "uniform mat4 projection;\n"
                                         "uniform mat3 normal_matrix;\n"
                                         "out vec3 world_position;\n"
                                         "out vec3 world_normal;\n"
                                         "void main() {\n"
                                         "    vec4 world = model * vec4(position, 1.0);\n"
                                         "    world_position = world.xyz;\n"
                                         "    world_normal = normal_matrix * normal;\n"
                                         "    gl_Position = projection * view * world;\n"
                                         "}\n";

static const char *const fragment_source =
    "#version 330 core\n"
    "in vec3 world_position;\n"
    "in vec3 world_normal;\n"
    "uniform vec3 light_position;\n"
    "uniform vec3 light_colour;\n"
    "uniform vec3 ambient;\n"
    "uniform vec3 kd;\n"
    "out vec4 colour;\n"
    "void main() {\n"
    "    vec3 n = normalize(world_normal);\n"
    "    float diffuse = max(dot(n, normalize(light_position - world_position)), 0.0);\n"
    "    colour = vec4(ambient * kd + light_colour * kd * diffuse, 1.0);\n"
    "}\n";

static const ani_uniform_desc uniforms[] = {
    {"model", ANI_UNIFORM_MAT4, "model"},
    {"view", ANI_UNIFORM_MAT4, "view"},
    {"projection", ANI_UNIFORM_MAT4, "projection"},
    {"normal_matrix", ANI_UNIFORM_MAT3, "normal_matrix"},
    {"light_position", ANI_UNIFORM_VEC3, "light_position"},
    {"light_colour", ANI_UNIFORM_VEC3, "light_colour"},
    {"ambient", ANI_UNIFORM_VEC3, "ambient"},
    {"kd", ANI_UNIFORM_VEC3, "kd"},
};

static int instance_token;

static void *one_light_create(const ani_host *host, ani_status *status) {
    (void)host;
    ani_status_set(status, ANI_OK, "");
    return &instance_token;
}
static void one_light_destroy(void *instance) {
    (void)instance;
}
static ani_status_code one_light_get_param(void *instance, const char *id, ani_param_value *value,
                                           ani_status *status) {
    (void)instance, (void)id, (void)value;
    return ani_status_set(status, ANI_ERR_UNKNOWN_PARAM, "shading.one_light has no parameters");
}
static ani_status_code one_light_set_param(void *instance, const char *id,
                                           const ani_param_value *value, ani_status *status) {
    (void)instance, (void)id, (void)value;
    return ani_status_set(status, ANI_ERR_UNKNOWN_PARAM, "shading.one_light has no parameters");
}
static ani_status_code one_light_get_program(void *instance, uint32_t features,
                                             ani_shader_program *program, ani_status *status) {
    (void)instance;
    if (features & ~(uint32_t)0x3f) /* ABI 1.9's bits: texture .. skybox pass */
        return ani_status_set(status, ANI_ERR_INVALID_ARGUMENT, "unknown shading feature bits");
    program->vertex_source = vertex_source;
    program->fragment_source = fragment_source;
    program->uniforms = uniforms;
    program->uniform_count = (uint32_t)(sizeof uniforms / sizeof uniforms[0]);
    return ani_status_set(status, ANI_OK, "");
}

static const ani_shading_api one_light_api = {
    sizeof(ani_shading_api),
    {sizeof(ani_instance_api), one_light_create, one_light_destroy, one_light_get_param,
     one_light_set_param},
    one_light_get_program,
};

static const ani_plugin_descriptor one_light_descriptor = {
    sizeof(ani_plugin_descriptor),
    "shading.one_light",
    ANI_KIND_SHADING,
    "One light",
    {1, 0, 0},
    "Diffuse light from light_position and light_colour only.",
    NULL,
    0,
    &one_light_api,
};

static ani_status_code one_light_init(const ani_host *host, ani_status *status) {
    (void)host;
    return ani_status_set(status, ANI_OK, "");
}
static void one_light_deinit(void) {}
static uint32_t one_light_count(void) {
    return 1;
}
static const ani_plugin_descriptor *one_light_get(uint32_t index) {
    return index == 0 ? &one_light_descriptor : NULL;
}

ANI_DECLARE_ENTRY;
const ani_plugin_entry animator_plugin_entry = {
    sizeof(ani_plugin_entry), {ANI_ABI_MAJOR, 9, 0},
    one_light_init,           one_light_deinit,
    one_light_count,          one_light_get,
};
