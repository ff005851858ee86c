#include "render/picking_pass.hpp"

#include "render/render_error.hpp"

#include <glad/gl.h>
#include <glm/gtc/type_ptr.hpp>

#include <string>

namespace animator {

namespace {

const char *const kIdVertex = R"glsl(#version 330 core
layout(location = 0) in vec3 position;
uniform mat4 model;
uniform mat4 view_projection;
void main() { gl_Position = view_projection * model * vec4(position, 1.0); }
)glsl";

const char *const kIdFragment = R"glsl(#version 330 core
uniform uint object_id;
out uint id;
void main() { id = object_id; }
)glsl";

} // namespace

PickingPass::PickingPass() : program_(kIdVertex, kIdFragment) {
    model_location_ = program_.uniform_location("model");
    view_projection_location_ = program_.uniform_location("view_projection");
    id_location_ = program_.uniform_location("object_id");
}

PickingPass::~PickingPass() {
    glDeleteFramebuffers(1, &framebuffer_);
    glDeleteRenderbuffers(1, &ids_);
    glDeleteRenderbuffers(1, &depth_);
}

void PickingPass::resize(int width, int height) {
    if (width == width_ && height == height_) return;
    if (framebuffer_ == 0) {
        glGenFramebuffers(1, &framebuffer_);
        glGenRenderbuffers(1, &ids_);
        glGenRenderbuffers(1, &depth_);
    }
    glBindRenderbuffer(GL_RENDERBUFFER, ids_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_R32UI, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, depth_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, ids_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw RenderError("the picking framebuffer is incomplete at " + std::to_string(width) +
                          "x" + std::to_string(height));
    width_ = width;
    height_ = height;
}

bool PickingPass::begin(int width, int height, int x, int y, const glm::mat4 &view_projection) {
    if (x < 0 || y < 0 || x >= width || y >= height) return false;
    resize(width, height);
    x_ = x;
    y_ = height - 1 - y; // GL counts rows from the bottom
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glViewport(0, 0, width, height);
    glEnable(GL_SCISSOR_TEST);
    glScissor(x_, y_, 1, 1);
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
    const GLuint nothing[4] = {0, 0, 0, 0};
    glClearBufferuiv(GL_COLOR, 0, nothing);
    glClear(GL_DEPTH_BUFFER_BIT);
    glUseProgram(program_.name());
    glUniformMatrix4fv(view_projection_location_, 1, GL_FALSE, glm::value_ptr(view_projection));
    return true;
}

void PickingPass::draw(const GpuMesh &mesh, const glm::mat4 &model, std::size_t level,
                       std::uint32_t id) {
    glUniformMatrix4fv(model_location_, 1, GL_FALSE, glm::value_ptr(model));
    glUniform1ui(id_location_, id);
    mesh.draw(level);
}

std::uint32_t PickingPass::finish() {
    GLuint id = 0;
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glReadPixels(x_, y_, 1, 1, GL_RED_INTEGER, GL_UNSIGNED_INT, &id);
    glDisable(GL_SCISSOR_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glUseProgram(0);
    return id;
}

} // namespace animator
