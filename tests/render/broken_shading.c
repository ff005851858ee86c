/* A shading plugin whose fragment shader does not compile, so the tests can watch the renderer
 * report it (plugin, stage, driver's log) and fall back to its built-in Phong. */
#include "animator/shading.h"

static const char *const vertex_source =
    "#version 330 core\n"
    "layout(location = 0) in vec3 position;\n"
    "uniform mat4 model;\n"
    "uniform mat4 view;\n"
    "uniform mat4 projection;\n"
    "void main() { gl_Position = projection * view * model * vec4(position, 1.0); }\n";

static const char *const fragment_source =
    "#version 330 core\n"
    "out vec4 colour;\n"
    "void main() { colour = vec4(1.0, 0.0, 0.0, 1.0) }\n"; /* the missing ';' */

static const ani_uniform_desc uniforms[] = {
    {"model", ANI_UNIFORM_MAT4, "model"},
    {"view", ANI_UNIFORM_MAT4, "view"},
    {"projection", ANI_UNIFORM_MAT4, "projection"},
};

static int instance_token;

static void *broken_create(const ani_host *host, ani_status *status) {
    (void)host;
    ani_status_set(status, ANI_OK, "");
    return &instance_token;
}
static void broken_destroy(void *instance) {
    (void)instance;
}
static ani_status_code broken_get_param(void *instance, const char *id, ani_param_value *value,
                                        ani_status *status) {
    (void)instance, (void)id, (void)value;
    return ani_status_set(status, ANI_ERR_UNKNOWN_PARAM, "shading.broken has no parameters");
}
static ani_status_code broken_set_param(void *instance, const char *id,
                                        const ani_param_value *value, ani_status *status) {
    (void)instance, (void)id, (void)value;
    return ani_status_set(status, ANI_ERR_UNKNOWN_PARAM, "shading.broken has no parameters");
}
static ani_status_code broken_get_program(void *instance, uint32_t features,
                                          ani_shader_program *program, ani_status *status) {
    (void)instance, (void)features;
    program->vertex_source = vertex_source;
    program->fragment_source = fragment_source;
    program->uniforms = uniforms;
    program->uniform_count = 3;
    return ani_status_set(status, ANI_OK, "");
}

static const ani_shading_api broken_api = {
    sizeof(ani_shading_api),
    {sizeof(ani_instance_api), broken_create, broken_destroy, broken_get_param, broken_set_param},
    broken_get_program,
};

static const ani_plugin_descriptor broken_descriptor = {
    sizeof(ani_plugin_descriptor),
    "shading.broken",
    ANI_KIND_SHADING,
    "Broken shading",
    {1, 0, 0},
    "A fragment shader with a syntax error.",
    NULL,
    0,
    &broken_api,
};

static ani_status_code broken_init(const ani_host *host, ani_status *status) {
    (void)host;
    return ani_status_set(status, ANI_OK, "");
}
static void broken_deinit(void) {}
static uint32_t broken_count(void) {
    return 1;
}
static const ani_plugin_descriptor *broken_get(uint32_t index) {
    return index == 0 ? &broken_descriptor : NULL;
}

ANI_DECLARE_ENTRY;
const ani_plugin_entry animator_plugin_entry = {
    sizeof(ani_plugin_entry),
    {ANI_ABI_MAJOR, ANI_ABI_MINOR, 0},
    broken_init,
    broken_deinit,
    broken_count,
    broken_get,
};
