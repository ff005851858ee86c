#include "render/motion_path_overlay.hpp"

#include <glad/gl.h>
#include <glm/gtc/type_ptr.hpp>

namespace animator {

namespace {

const char *const kPathVertex = R"glsl(#version 330 core
layout(location = 0) in vec3 position;
uniform mat4 view_projection;
uniform float size;
void main() {
    gl_Position = view_projection * vec4(position, 1.0);
    gl_PointSize = size;
}
)glsl";

// Round dots: the point's square less its corners.
const char *const kPathFragment = R"glsl(#version 330 core
uniform vec3 colour;
uniform float size;
out vec4 fragment;
void main() {
    if (size > 1.0 && length(gl_PointCoord - vec2(0.5)) > 0.5) discard;
    fragment = vec4(colour, 1.0);
}
)glsl";

} // namespace

MotionPathOverlay::MotionPathOverlay() : program_(kPathVertex, kPathFragment) {
    view_projection_location_ = program_.uniform_location("view_projection");
    colour_location_ = program_.uniform_location("colour");
    size_location_ = program_.uniform_location("size");
    glGenVertexArrays(1, &vertex_array_);
    glGenBuffers(1, &buffer_);
    glBindVertexArray(vertex_array_);
    glBindBuffer(GL_ARRAY_BUFFER, buffer_);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    glBindVertexArray(0);
}

MotionPathOverlay::~MotionPathOverlay() {
    glDeleteBuffers(1, &buffer_);
    glDeleteVertexArrays(1, &vertex_array_);
}

void MotionPathOverlay::upload(const std::vector<glm::vec3> &points) {
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(points.size() * sizeof(glm::vec3)), points.data(),
                 GL_STREAM_DRAW);
}

void MotionPathOverlay::draw(const std::vector<PathLines> &paths, const glm::mat4 &view_projection,
                             const PathStyle &style) {
    glUseProgram(program_.name());
    glUniformMatrix4fv(view_projection_location_, 1, GL_FALSE, glm::value_ptr(view_projection));
    glBindVertexArray(vertex_array_);
    glBindBuffer(GL_ARRAY_BUFFER, buffer_);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_BLEND);
    glEnable(GL_PROGRAM_POINT_SIZE);
    auto pass = [&](const std::vector<glm::vec3> &points, GLenum mode, const glm::vec3 &colour, float size) {
        if (points.empty()) return;
        upload(points);
        glUniform3fv(colour_location_, 1, glm::value_ptr(colour));
        glUniform1f(size_location_, size);
        glDrawArrays(mode, 0, static_cast<GLsizei>(points.size()));
    };
    for (const PathLines &p : paths) {
        pass(p.frames, GL_LINE_STRIP, style.line, 1.0f);
        pass(p.frames, GL_POINTS, style.dot, style.dot_pixels);
        pass(p.keys, GL_POINTS, style.key, style.key_pixels);
        pass(p.hits, GL_POINTS, style.hit, style.hit_pixels);
    }
    glDisable(GL_PROGRAM_POINT_SIZE);
    glBindVertexArray(0);
    glEnable(GL_DEPTH_TEST);
    glUseProgram(0);
}

} // namespace animator
