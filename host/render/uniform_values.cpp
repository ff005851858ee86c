#include "render/uniform_values.hpp"

#include <glad/gl.h>
#include <glm/gtc/type_ptr.hpp>

#include <cmath>

namespace animator {

namespace {

void set_param(const BoundUniform &u, const std::array<double, 4> &v) {
    switch (u.type) {
    case ANI_UNIFORM_INT:
        glUniform1i(u.location, static_cast<GLint>(std::lround(v[0])));
        break;
    case ANI_UNIFORM_VEC3:
        glUniform3f(u.location, static_cast<float>(v[0]), static_cast<float>(v[1]),
                    static_cast<float>(v[2]));
        break;
    case ANI_UNIFORM_VEC4:
        glUniform4f(u.location, static_cast<float>(v[0]), static_cast<float>(v[1]),
                    static_cast<float>(v[2]), static_cast<float>(v[3]));
        break;
    default:
        glUniform1f(u.location, static_cast<float>(v[0]));
        break;
    }
}

} // namespace

void apply_uniforms(const LinkedProgram &program, const ShadingPrograms &programs,
                    const FrameUniforms &frame, const ModelUniforms *model) {
    static const ModelUniforms kNoModel;
    const ModelUniforms &m = model ? *model : kNoModel;
    for (const BoundUniform &u : program.uniforms) {
        const GLint at = u.location;
        switch (u.semantic) {
        case UniformSemantic::Model:
            glUniformMatrix4fv(at, 1, GL_FALSE, glm::value_ptr(m.model));
            break;
        case UniformSemantic::View:
            glUniformMatrix4fv(at, 1, GL_FALSE, glm::value_ptr(frame.view));
            break;
        case UniformSemantic::Projection:
            glUniformMatrix4fv(at, 1, GL_FALSE, glm::value_ptr(frame.projection));
            break;
        case UniformSemantic::NormalMatrix:
            glUniformMatrix3fv(at, 1, GL_FALSE, glm::value_ptr(m.normal_matrix));
            break;
        case UniformSemantic::CameraPosition:
            glUniform3fv(at, 1, glm::value_ptr(frame.camera_position));
            break;
        case UniformSemantic::LightPosition:
            glUniform3fv(at, 1, glm::value_ptr(frame.light_position[0]));
            break;
        case UniformSemantic::LightColour:
            glUniform3fv(at, 1, glm::value_ptr(frame.light_colour[0]));
            break;
        case UniformSemantic::LightCount:
            glUniform1i(at, frame.light_count);
            break;
        case UniformSemantic::LightPositionAt:
            glUniform3fv(at, 1, glm::value_ptr(frame.light_position[static_cast<size_t>(u.light)]));
            break;
        case UniformSemantic::LightColourAt:
            glUniform3fv(at, 1, glm::value_ptr(frame.light_colour[static_cast<size_t>(u.light)]));
            break;
        case UniformSemantic::LightFalloffAt:
            glUniform3fv(at, 1, glm::value_ptr(frame.light_falloff[static_cast<size_t>(u.light)]));
            break;
        case UniformSemantic::Ambient:
            glUniform3fv(at, 1, glm::value_ptr(frame.ambient));
            break;
        case UniformSemantic::Kd:
            glUniform3fv(at, 1, glm::value_ptr(m.kd));
            break;
        case UniformSemantic::Ks:
            glUniform3fv(at, 1, glm::value_ptr(m.ks));
            break;
        case UniformSemantic::Shininess:
            glUniform1f(at, m.shininess);
            break;
        case UniformSemantic::Tint:
            glUniform1f(at, m.tint);
            break;
        case UniformSemantic::Reflectivity:
            glUniform1f(at, m.reflectivity);
            break;
        case UniformSemantic::Transparency:
            glUniform1f(at, m.transparency);
            break;
        case UniformSemantic::RefractiveIndex:
            glUniform1f(at, m.refractive_index);
            break;
        case UniformSemantic::SelectedTint: {
            glm::vec4 tint = frame.selected_tint;
            if (!m.selected) tint.a = 0.0f;
            glUniform4fv(at, 1, glm::value_ptr(tint));
            break;
        }
        case UniformSemantic::Param:
            set_param(u, programs.param_value(u.param));
            break;
        case UniformSemantic::ShadowLights:
            glUniform1i(at, frame.shadow_lights);
            break;
        case UniformSemantic::ShadowMatrixAt:
            glUniformMatrix4fv(at, 1, GL_FALSE,
                               glm::value_ptr(frame.shadow_matrix[static_cast<size_t>(u.light)]));
            break;
        case UniformSemantic::ShadowTexelAt:
            glUniform1f(at, frame.shadow_texel[static_cast<size_t>(u.light)]);
            break;
        case UniformSemantic::Texture:
        case UniformSemantic::Skybox:
        case UniformSemantic::ShadowMapAt:
            break; // units set at link time
        }
    }
}

} // namespace animator
