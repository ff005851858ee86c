// The animator-shading library: the `shading.phong` plugin (descriptor, parameters, instances,
// get_program) and the entry. The GLSL lives in glsl_sources.cpp, its assembly per feature set in
// phong_program.cpp. No GL call happens here: the host compiles and binds what this returns.
#include "phong_program.hpp"

#include <animator/plugin_cpp.hpp>
#include <animator/shading.h>

#include <map>

namespace {

const char *const kPhongId = "shading.phong";

const ani_param_descriptor phong_params[] = {
    {sizeof(ani_param_descriptor),
     "cel_bands",
     "Cel bands",
     "How many steps each colour channel is snapped to when cel shading is on; the seed's step10 "
     "is 10.",
     ANI_PARAM_INT,
     2.0,
     32.0,
     {{10.0, 0.0, 0.0, 0.0}},
     1.0,
     nullptr,
     0},
    {sizeof(ani_param_descriptor),
     "cel_outline",
     "Cel outline",
     "On: cel shading draws a line along the silhouettes of smooth surfaces.",
     ANI_PARAM_BOOL,
     0.0,
     1.0,
     {{0.0, 0.0, 0.0, 0.0}},
     0.0,
     nullptr,
     0},
    {sizeof(ani_param_descriptor),
     "cel_outline_width",
     "Outline width",
     "The cel outline's width in pixels.",
     ANI_PARAM_FLOAT,
     0.5,
     8.0,
     {{1.5, 0.0, 0.0, 0.0}},
     0.1,
     nullptr,
     0},
    {sizeof(ani_param_descriptor),
     "cel_outline_colour",
     "Outline colour",
     "The cel outline's colour (alpha unused).",
     ANI_PARAM_COLOUR,
     0.0,
     1.0,
     {{0.0, 0.0, 0.0, 1.0}},
     0.0,
     nullptr,
     0},
};

struct Instance {
    ani::ParamStore params{phong_params, sizeof(phong_params) / sizeof(phong_params[0])};
    // Built on first request; map nodes never move, so the strings handed out stay valid until
    // the instance is destroyed, as shading.h promises.
    std::map<uint32_t, shading::ProgramSource> programs;
};

void *phong_create(const ani_host *, ani_status *status) {
    Instance *self = nullptr;
    ani::guarded(status, [&] { self = new Instance(); });
    return self;
}

void phong_destroy(void *instance) {
    delete static_cast<Instance *>(instance);
}

ani_status_code phong_get_program(void *instance, uint32_t features, ani_shader_program *program,
                                  ani_status *status) {
    return ani::guarded(status, [&] {
        if (instance == nullptr || program == nullptr)
            throw ani::Failure(ANI_ERR_INVALID_ARGUMENT, "get_program: null instance or program");
        if (program->struct_size < sizeof(ani_shader_program))
            throw ani::Failure(ANI_ERR_VERSION, "get_program: the program struct is too small");
        if (auto problem = shading::check_features(features); !problem.empty())
            throw ani::Failure(ANI_ERR_INVALID_ARGUMENT, std::string(kPhongId) + ": " + problem +
                                                             " (features " +
                                                             std::to_string(features) + ")");
        auto &programs = static_cast<Instance *>(instance)->programs;
        auto found = programs.find(features);
        if (found == programs.end())
            found = programs.emplace(features, shading::build_program(features)).first;
        const shading::ProgramSource &p = found->second;
        program->vertex_source = p.vertex.c_str();
        program->fragment_source = p.fragment.c_str();
        program->uniforms = p.uniforms.data();
        program->uniform_count = static_cast<uint32_t>(p.uniforms.size());
    });
}

const ani_shading_api phong_api = {
    sizeof(ani_shading_api),
    {sizeof(ani_instance_api), phong_create, phong_destroy, ani::store_get_param<Instance>, ani::store_set_param<Instance>},
    phong_get_program,
};

const ani_plugin_descriptor phong_descriptor = {
    sizeof(ani_plugin_descriptor),
    kPhongId,
    ANI_KIND_SHADING,
    "Phong",
    {1, 0, 0},
    "Per-pixel Phong lighting with kd, ks and shininess, texture mapping tinted by kd, skybox "
    "reflection and refraction, cel shading with a band count and an optional outline, and the "
    "editor's selection tint.",
    phong_params,
    sizeof(phong_params) / sizeof(phong_params[0]),
    &phong_api,
};

const ani_plugin_descriptor *const kPlugins[] = {&phong_descriptor};

} // namespace

ANI_PLUGIN_ENTRY(kPlugins)
