#include "render/selection_outline.hpp"

#include <animator/shading.h>

#include <glad/gl.h>
#include <glm/gtc/type_ptr.hpp>

namespace animator {

namespace {

// Each vertex moves `pixels` away from the model's centre as the screen shows it: radial, not
// along the normal, so a cube's split normals open no gaps at its corners. For a convex
// silhouette the moved one encloses it with a band about that wide.
const char *const kOutlineVertex = R"glsl(#version 330 core
layout(location = 0) in vec3 position;
uniform mat4 model;
uniform mat4 view_projection;
uniform float pixels;
uniform vec2 viewport;
void main() {
    vec4 clip = view_projection * model * vec4(position, 1.0);
    vec4 centre = view_projection * model * vec4(0.0, 0.0, 0.0, 1.0);
    vec2 away = vec2(0.0);
    if (clip.w > 0.0 && centre.w > 0.0) {
        vec2 d = (clip.xy / clip.w - centre.xy / centre.w) * viewport;
        if (dot(d, d) > 1e-12) away = normalize(d);
    }
    // NDC spans 2 per viewport: pixels * 2 / viewport, times w to stay in clip space.
    clip.xy += away * pixels * 2.0 / viewport * clip.w;
    gl_Position = clip;
}
)glsl";

const char *const kOutlineFragment = R"glsl(#version 330 core
uniform vec3 colour;
out vec4 fragment;
void main() { fragment = vec4(colour, 1.0); }
)glsl";

} // namespace

SelectionOutline::SelectionOutline() : program_(kOutlineVertex, kOutlineFragment) {
    model_location_ = program_.uniform_location("model");
    view_projection_location_ = program_.uniform_location("view_projection");
    pixels_location_ = program_.uniform_location("pixels");
    viewport_location_ = program_.uniform_location("viewport");
    colour_location_ = program_.uniform_location("colour");
}

void SelectionOutline::begin(const glm::mat4 &view_projection, int width, int height) {
    glUseProgram(program_.name());
    glUniformMatrix4fv(view_projection_location_, 1, GL_FALSE, glm::value_ptr(view_projection));
    glUniform2f(viewport_location_, static_cast<float>(width), static_cast<float>(height));
    // Over everything, also what hides part of the model: the selection is never lost behind
    // another model.
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glEnable(GL_STENCIL_TEST);
    glStencilMask(0xFF);
    glClearStencil(0);
    glClear(GL_STENCIL_BUFFER_BIT);
    // Marking: the silhouette at its true size, stencil 1, no colour.
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glStencilFunc(GL_ALWAYS, 1, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glUniform1f(pixels_location_, 0.0f);
}

void SelectionOutline::mark(const GpuMesh &mesh, const glm::mat4 &model, std::size_t level) {
    glUniformMatrix4fv(model_location_, 1, GL_FALSE, glm::value_ptr(model));
    mesh.draw(level);
}

void SelectionOutline::ring(const GpuMesh &mesh, const glm::mat4 &model, std::size_t level, float pixels,
                            const glm::vec3 &colour) {
    glUniformMatrix4fv(model_location_, 1, GL_FALSE, glm::value_ptr(model));
    glUniform1f(pixels_location_, pixels);
    glUniform3fv(colour_location_, 1, glm::value_ptr(colour));
    mesh.draw(level);
}

void SelectionOutline::outline(const GpuMesh &mesh, const glm::mat4 &model, std::size_t level,
                               const OutlineStyle &style) {
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    // Outside every selected silhouette only (bit 1); the wide dark band first, the light one
    // over it.
    glStencilFunc(GL_NOTEQUAL, 1, 0x01);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    ring(mesh, model, level, style.outer_pixels, style.outer);
    ring(mesh, model, level, style.inner_pixels, style.inner);
}

void SelectionOutline::outline_alone(const GpuMesh &mesh, const glm::mat4 &model, std::size_t level,
                                     const OutlineStyle &style) {
    // Its own silhouette in bit 2 (cleared first), with no colour.
    glStencilMask(0x02);
    glClear(GL_STENCIL_BUFFER_BIT);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glStencilFunc(GL_ALWAYS, 0x02, 0x02);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glUniform1f(pixels_location_, 0.0f);
    mark(mesh, model, level);
    // The ring outside it (over other models, selected ones too: their own rings come after).
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glStencilFunc(GL_EQUAL, 0, 0x02);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    ring(mesh, model, level, style.outer_pixels, style.outer);
    ring(mesh, model, level, style.inner_pixels, style.inner);
    glStencilMask(0xFF);
}

void SelectionOutline::end() {
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_STENCIL_TEST);
    glEnable(GL_DEPTH_TEST);
    glUseProgram(0);
}

} // namespace animator
