// The programs draws need, asked of the shading plugin by feature set (shading.h), compiled and
// linked once, with each uniform's semantic parsed and its location found. A feature set whose
// program cannot be had (the plugin refuses, a shader does not compile or link, a uniform the
// host cannot fill) is reported once, naming the plugin, the stage and the driver's log, and is
// drawn with the host's built-in program instead (built_in_shading.hpp).
#pragma once

#include "plugin/instance.hpp"
#include "render/shader_program.hpp"
#include "render/uniform_semantics.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace animator {

// Texture units the host binds samplers to.
constexpr int kTextureUnit = 0;
constexpr int kSkyboxUnit = 1;
constexpr int kFirstShadowUnit = 2; // light N's shadow map on kFirstShadowUnit + N

struct BoundUniform {
    int location = -1;
    ani_uniform_type type = ANI_UNIFORM_FLOAT;
    UniformSemantic semantic = UniformSemantic::Model;
    int param = -1; // for UniformSemantic::Param: the index into ShadingPrograms' values
    int light = 0;  // for the per-light semantics ("light_position:N"): N
};

struct LinkedProgram {
    std::unique_ptr<ShaderProgram> shader;
    std::vector<BoundUniform> uniforms; // the active ones; samplers are already set to their unit
    bool built_in = false;
};

class ShadingPrograms {
  public:
    using LogSink = std::function<void(const std::string &message)>;

    // `plugin` (a shading instance) may be null: every draw then uses the built-in programs.
    // Needs a current GL context for its whole life.
    ShadingPrograms(std::unique_ptr<PluginInstance> plugin, LogSink log);
    ~ShadingPrograms();
    ShadingPrograms(const ShadingPrograms &) = delete;
    ShadingPrograms &operator=(const ShadingPrograms &) = delete;

    // The program for a feature set (ani_shading_feature bits), built on first use. A failure
    // is logged and answered with the built-in program; this throws only for a failure of the
    // built-in program itself (RenderError).
    const LinkedProgram &get(uint32_t features);

    // Every parameter of the plugin back to its default.
    void reset_params();
    // Sets one of the plugin's parameters (param:<id> uniforms). Throws PluginError.
    void set_param(const std::string &id, const std::array<double, 4> &value);
    const std::array<double, 4> &param_value(int index) const {
        return param_values_[static_cast<size_t>(index)];
    }

    // The plugin's id, or "" without one.
    std::string plugin_id() const { return plugin_ ? plugin_->info().id : std::string(); }
    // How many feature sets fell back to the built-in program.
    std::size_t fallbacks() const { return fallbacks_; }

  private:
    std::unique_ptr<LinkedProgram> link(const ani_shader_program &source, bool built_in);
    std::unique_ptr<LinkedProgram> from_plugin(uint32_t features);
    const LinkedProgram &built_in(bool skybox_pass);

    std::unique_ptr<PluginInstance> plugin_;
    LogSink log_;
    std::vector<std::string> param_ids_;
    std::vector<std::array<double, 4>> param_values_;
    // The feature bits newer than the plugin, left out of what it is asked: a plugin built for
    // ABI 1.10 or newer is asked for the shadow maps' count, one for 1.11 or newer for the
    // lights' count; an older one's programs read "shadow_lights" and "light_count" (shading.h).
    uint32_t unknown_to_plugin_ = 0;
    // Every combination of ani_shading_feature bits, shadow-map counts (0..7 in 3 bits) and
    // light counts (0..15 in 4 bits).
    static constexpr size_t kFeatureSets = std::size_t{1} << (ANI_SHADE_LIGHTS_SHIFT + 4);
    std::array<std::unique_ptr<LinkedProgram>, kFeatureSets> from_plugin_;
    std::array<const LinkedProgram *, kFeatureSets> resolved_{};
    std::unique_ptr<LinkedProgram> built_in_model_, built_in_skybox_;
    std::size_t fallbacks_ = 0;
};

// "texture|cel|2 shadow maps|3 lights" for a feature set, "none" for 0: for messages and tests.
std::string feature_names(uint32_t features);

} // namespace animator
