#include "render/shading_programs.hpp"

#include "render/built_in_shading.hpp"

#include <glad/gl.h>

#include <algorithm>

namespace animator {

namespace {

GLenum gl_type(ani_uniform_type type) {
    switch (type) {
    case ANI_UNIFORM_FLOAT:
        return GL_FLOAT;
    case ANI_UNIFORM_INT:
        return GL_INT;
    case ANI_UNIFORM_VEC3:
        return GL_FLOAT_VEC3;
    case ANI_UNIFORM_VEC4:
        return GL_FLOAT_VEC4;
    case ANI_UNIFORM_MAT3:
        return GL_FLOAT_MAT3;
    case ANI_UNIFORM_MAT4:
        return GL_FLOAT_MAT4;
    case ANI_UNIFORM_SAMPLER_2D:
        return GL_SAMPLER_2D;
    case ANI_UNIFORM_SAMPLER_CUBE:
        return GL_SAMPLER_CUBE;
    case ANI_UNIFORM_SAMPLER_2D_SHADOW:
        return GL_SAMPLER_2D_SHADOW;
    }
    return 0;
}

// A GLSL bool is filled as an int (glUniform1i), so either declaration takes an INT parameter.
bool gl_type_matches(ani_uniform_type declared, GLenum actual) {
    return actual == gl_type(declared) || (declared == ANI_UNIFORM_INT && actual == GL_BOOL);
}

} // namespace

std::string feature_names(uint32_t features) {
    static const char *const names[] = {"texture", "reflection", "refraction",
                                        "cel",     "selected",   "skybox pass"};
    std::string out;
    for (uint32_t bit = 0; bit < 6; ++bit)
        if (features & (1u << bit)) out += (out.empty() ? "" : "|") + std::string(names[bit]);
    if (const uint32_t maps = ANI_SHADE_SHADOW_MAP_COUNT(features))
        out += (out.empty() ? "" : "|") + std::to_string(maps) + (maps == 1 ? " shadow map" : " shadow maps");
    if (const uint32_t lights = ANI_SHADE_LIGHT_COUNT(features))
        out += (out.empty() ? "" : "|") + std::to_string(lights) + (lights == 1 ? " light" : " lights");
    for (uint32_t bit = ANI_SHADE_LIGHTS_SHIFT + 4; bit < 32; ++bit)
        if (features & (1u << bit)) out += (out.empty() ? "bit " : "|bit ") + std::to_string(bit);
    return out.empty() ? "none" : out;
}

ShadingPrograms::ShadingPrograms(std::unique_ptr<PluginInstance> plugin, LogSink log)
    : plugin_(std::move(plugin)), log_(std::move(log)) {
    if (!plugin_) return;
    const ani_plugin_descriptor &d = *plugin_->info().descriptor;
    for (uint32_t i = 0; i < d.param_count; ++i) {
        param_ids_.emplace_back(d.params[i].id);
        param_values_.push_back(plugin_->get_param(d.params[i].id));
    }
    const uint32_t minor = plugin_->info().abi.minor;
    unknown_to_plugin_ = (minor < 10 ? ANI_SHADE_SHADOW_MAPS_MASK : 0u) |
                         (minor < 11 ? ANI_SHADE_LIGHTS_MASK : 0u);
}

ShadingPrograms::~ShadingPrograms() = default;

void ShadingPrograms::reset_params() {
    if (!plugin_) return;
    const ani_plugin_descriptor &d = *plugin_->info().descriptor;
    for (uint32_t i = 0; i < d.param_count; ++i) {
        std::array<double, 4> value{};
        std::copy(d.params[i].default_value.value, d.params[i].default_value.value + 4,
                  value.begin());
        set_param(d.params[i].id, value);
    }
}

void ShadingPrograms::set_param(const std::string &id, const std::array<double, 4> &value) {
    if (!plugin_) throw PluginError("there is no shading plugin to take parameter '" + id + "'");
    plugin_->set_param(id, value);
    for (size_t i = 0; i < param_ids_.size(); ++i)
        if (param_ids_[i] == id) param_values_[i] = plugin_->get_param(id);
}

std::unique_ptr<LinkedProgram> ShadingPrograms::link(const ani_shader_program &source,
                                                     bool built_in) {
    if (!source.vertex_source || !source.fragment_source)
        throw ShaderError("the program has no vertex or fragment source");
    if (source.uniform_count > 0 && !source.uniforms)
        throw ShaderError("the program names uniforms but gives none");
    auto linked = std::make_unique<LinkedProgram>();
    linked->built_in = built_in;
    linked->shader = std::make_unique<ShaderProgram>(source.vertex_source, source.fragment_source);
    glUseProgram(linked->shader->name());
    for (uint32_t i = 0; i < source.uniform_count; ++i) {
        const ani_uniform_desc &u = source.uniforms[i];
        const std::string name = u.name ? u.name : "";
        const std::string semantic_text = u.semantic ? u.semantic : "";
        std::string param_id;
        int light = 0;
        const auto semantic = parse_semantic(semantic_text, param_id, &light);
        if (!semantic)
            throw ShaderError("uniform '" + name + "' has a semantic the host does not know: '" +
                              semantic_text + "'");
        const auto type = static_cast<ani_uniform_type>(u.type);
        if (!semantic_accepts(*semantic, type))
            throw ShaderError("uniform '" + name + "' cannot hold '" + semantic_text +
                              "' with its declared type");
        BoundUniform bound;
        bound.location = linked->shader->uniform_location(name);
        if (bound.location < 0) continue; // unused by the GLSL, so dropped by the compiler
        const GLenum actual = linked->shader->uniform_type(name);
        if (!gl_type_matches(type, actual))
            throw ShaderError("uniform '" + name + "' is declared with another type in the GLSL");
        bound.type = type;
        bound.semantic = *semantic;
        bound.light = light;
        if (*semantic == UniformSemantic::Param) {
            for (size_t p = 0; p < param_ids_.size(); ++p)
                if (param_ids_[p] == param_id) bound.param = static_cast<int>(p);
            if (bound.param < 0)
                throw ShaderError("uniform '" + name + "' names parameter '" + param_id +
                                  "', which the plugin does not declare");
        }
        if (*semantic == UniformSemantic::Texture) glUniform1i(bound.location, kTextureUnit);
        if (*semantic == UniformSemantic::Skybox) glUniform1i(bound.location, kSkyboxUnit);
        if (*semantic == UniformSemantic::ShadowMapAt)
            glUniform1i(bound.location, kFirstShadowUnit + light);
        linked->uniforms.push_back(bound);
    }
    glUseProgram(0);
    return linked;
}

std::unique_ptr<LinkedProgram> ShadingPrograms::from_plugin(uint32_t features) {
    const std::string who = plugin_->info().id;
    const std::string what = " (features " + feature_names(features) + ")";
    try {
        ani_shader_program source{};
        source.struct_size = sizeof source;
        ani_status status{};
        const auto &api = plugin_->api<ani_shading_api>();
        if (api.get_program(plugin_->handle(), features, &source, &status) != ANI_OK)
            throw ShaderError(std::string("get_program failed: ") + status.message);
        return link(source, false);
    } catch (const std::exception &e) { // ShaderError, PluginError, bad_alloc
        if (log_) log_(who + what + ": " + e.what() + "; drawing with the built-in Phong instead");
    }
    return nullptr;
}

const LinkedProgram &ShadingPrograms::built_in(bool skybox_pass) {
    auto &slot = skybox_pass ? built_in_skybox_ : built_in_model_;
    if (!slot) slot = link(built_in_program(skybox_pass), true);
    return *slot;
}

const LinkedProgram &ShadingPrograms::get(uint32_t features) {
    if (features >= kFeatureSets)
        throw RenderError("no shading program for unknown features " + feature_names(features));
    features &= ~unknown_to_plugin_;
    if (resolved_[features]) return *resolved_[features];
    const bool skybox_pass = (features & ANI_SHADE_SKYBOX_PASS) != 0;
    std::unique_ptr<LinkedProgram> own = plugin_ ? from_plugin(features) : nullptr;
    const LinkedProgram *chosen = own.get();
    if (!chosen) {
        fallbacks_ += plugin_ ? 1 : 0;
        chosen = &built_in(skybox_pass);
    }
    from_plugin_[features] = std::move(own);
    resolved_[features] = chosen;
    return *chosen;
}

} // namespace animator
