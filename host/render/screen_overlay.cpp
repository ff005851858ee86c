#include "render/screen_overlay.hpp"

#include <glad/gl.h>
#include <glm/geometric.hpp>

#include <cstddef>

namespace animator {

namespace {

const char *const kOverlayVertex = R"glsl(#version 330 core
layout(location = 0) in vec2 position;
layout(location = 1) in vec3 colour;
uniform vec2 size;
out vec3 shade;
void main() {
    gl_Position = vec4(position.x / size.x * 2.0 - 1.0, 1.0 - position.y / size.y * 2.0, 0.0, 1.0);
    shade = colour;
}
)glsl";

const char *const kOverlayFragment = R"glsl(#version 330 core
in vec3 shade;
out vec4 fragment;
void main() { fragment = vec4(shade, 1.0); }
)glsl";

} // namespace

void OverlayTriangles::line(glm::vec2 a, glm::vec2 b, float width, glm::vec3 colour) {
    const glm::vec2 d = b - a;
    const float n = glm::length(d);
    if (n <= 0.0f) return;
    const glm::vec2 side = glm::vec2(-d.y, d.x) / n * (width * 0.5f);
    // The ends go on by half the width, so the segments of a polyline meet without notches.
    const glm::vec2 on = d / n * (width * 0.5f);
    const glm::vec2 p0 = a - on + side, p1 = a - on - side, p2 = b + on - side, p3 = b + on + side;
    for (const glm::vec2 p : {p0, p1, p2, p0, p2, p3}) vertices.push_back({p, colour});
}

void OverlayTriangles::polyline(const std::vector<glm::vec2> &points, bool closed, float width, glm::vec3 colour) {
    const size_t n = points.size();
    if (n < 2) return;
    for (size_t i = 0; i + 1 < n; ++i) line(points[i], points[i + 1], width, colour);
    if (closed && n > 2) line(points[n - 1], points[0], width, colour);
}

void OverlayTriangles::convex(const std::vector<glm::vec2> &points, glm::vec3 colour) {
    for (size_t i = 1; i + 1 < points.size(); ++i)
        for (const glm::vec2 p : {points[0], points[i], points[i + 1]}) vertices.push_back({p, colour});
}

ScreenOverlay::ScreenOverlay() : program_(kOverlayVertex, kOverlayFragment) {
    size_location_ = program_.uniform_location("size");
    glGenVertexArrays(1, &vertex_array_);
    glGenBuffers(1, &buffer_);
    glBindVertexArray(vertex_array_);
    glBindBuffer(GL_ARRAY_BUFFER, buffer_);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(OverlayVertex),
                          reinterpret_cast<const void *>(offsetof(OverlayVertex, position)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(OverlayVertex),
                          reinterpret_cast<const void *>(offsetof(OverlayVertex, colour)));
    glBindVertexArray(0);
}

ScreenOverlay::~ScreenOverlay() {
    glDeleteBuffers(1, &buffer_);
    glDeleteVertexArrays(1, &vertex_array_);
}

void ScreenOverlay::draw(const OverlayTriangles &triangles, float width, float height) {
    if (triangles.vertices.empty() || width <= 0.0f || height <= 0.0f) return;
    glUseProgram(program_.name());
    glUniform2f(size_location_, width, height);
    glBindVertexArray(vertex_array_);
    glBindBuffer(GL_ARRAY_BUFFER, buffer_);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(triangles.vertices.size() * sizeof(OverlayVertex)),
                 triangles.vertices.data(), GL_STREAM_DRAW);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(triangles.vertices.size()));
    glBindVertexArray(0);
    glEnable(GL_DEPTH_TEST);
    glUseProgram(0);
}

} // namespace animator
