#include "render/shadow_pass.hpp"

#include "render/render_error.hpp"

#include <glad/gl.h>
#include <glm/gtc/type_ptr.hpp>

#include <string>

namespace animator {

namespace {

const char *const kDepthVertex = R"glsl(#version 330 core
layout(location = 0) in vec3 position;
uniform mat4 model;
uniform mat4 view_projection;
void main() { gl_Position = view_projection * model * vec4(position, 1.0); }
)glsl";

const char *const kDepthFragment = R"glsl(#version 330 core
void main() {}
)glsl";

// The depth pass's slope-scaled bias (glPolygonOffset): a surface seen edge-on by the light gets
// the most, one facing it almost none, so a contact stays a contact.
constexpr float kSlopeBias = 2.0f, kConstantBias = 2.0f;

} // namespace

ShadowPass::ShadowPass() : program_(kDepthVertex, kDepthFragment) {
    model_location_ = program_.uniform_location("model");
    view_projection_location_ = program_.uniform_location("view_projection");
    glGenFramebuffers(1, &framebuffer_);
}

ShadowPass::~ShadowPass() {
    glDeleteFramebuffers(1, &framebuffer_);
    glDeleteTextures(kMaxShadowLights, maps_.data());
}

void ShadowPass::begin(int light, int size, const ShadowProjection &projection) {
    const size_t i = static_cast<size_t>(light);
    if (maps_[i] == 0 || sizes_[i] != size) {
        if (maps_[i] == 0) glGenTextures(1, &maps_[i]);
        glBindTexture(GL_TEXTURE_2D, maps_[i]);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, size, size, 0, GL_DEPTH_COMPONENT,
                     GL_UNSIGNED_INT, nullptr);
        // Compared in the sampler (sampler2DShadow), bilinearly: each lookup is already a 2x2
        // percentage-closer filter, smoothed further by the shader's taps.
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
        // Outside the map nothing is in shadow: the border is as far as depth goes.
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
        const float far[4] = {1.0f, 1.0f, 1.0f, 1.0f};
        glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, far);
        glBindTexture(GL_TEXTURE_2D, 0);
        sizes_[i] = size;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, maps_[i], 0);
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw RenderError("the shadow map framebuffer is incomplete at " + std::to_string(size) +
                          " texels");
    glViewport(0, 0, size, size);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_BLEND);
    glCullFace(GL_BACK);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(kSlopeBias, kConstantBias);
    glUseProgram(program_.name());
    const glm::mat4 vp(projection.view_projection);
    glUniformMatrix4fv(view_projection_location_, 1, GL_FALSE, glm::value_ptr(vp));
}

void ShadowPass::draw(const GpuMesh &mesh, const glm::mat4 &model, std::size_t level, bool one_sided) {
    if (one_sided)
        glEnable(GL_CULL_FACE);
    else
        glDisable(GL_CULL_FACE); // open meshes (a floor) cast from either side
    glUniformMatrix4fv(model_location_, 1, GL_FALSE, glm::value_ptr(model));
    mesh.draw(level);
}

void ShadowPass::finish() {
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_CULL_FACE);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void ShadowPass::bind(int count) const {
    for (int i = 0; i < count && i < kMaxShadowLights; ++i) {
        glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(kFirstShadowUnit + i));
        glBindTexture(GL_TEXTURE_2D, maps_[static_cast<size_t>(i)]);
    }
    glActiveTexture(GL_TEXTURE0);
}

} // namespace animator
