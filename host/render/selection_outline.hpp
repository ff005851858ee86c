// The selection outline: a two-colour ring drawn around each selected model's silhouette, a
// light inner band against a dark outer one, so it reads on any colour (the yellow tint alone is
// invisible on a yellow model). The silhouette is marked in the stencil, then each model is drawn
// again pushed outwards on the screen by a width in pixels, only where the stencil is unmarked:
// the ring never covers the model's own pixels, and its width does not change with distance.
#pragma once

#include "render/gpu_mesh.hpp"
#include "render/shader_program.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace animator {

struct OutlineStyle {
    glm::vec3 inner{1.0f, 0.55f, 0.0f}; // orange: reads on dark and mid colours
    glm::vec3 outer{0.0f, 0.0f, 0.0f};  // black: reads on light ones (yellow, white, sky)
    float inner_pixels = 2.0f, outer_pixels = 4.0f; // from the silhouette outwards
};

class SelectionOutline {
  public:
    // Needs a current GL context for its whole life.
    SelectionOutline();
    SelectionOutline(const SelectionOutline &) = delete;
    SelectionOutline &operator=(const SelectionOutline &) = delete;

    // Over the frame drawn in the bound framebuffer (its stencil is cleared and reused):
    // `count` selected models, each with its mesh, world matrix and level of detail (the one it
    // was drawn with), seen through view_projection in a viewport `width` x `height` pixels.
    void begin(const glm::mat4 &view_projection, int width, int height);
    void mark(const GpuMesh &mesh, const glm::mat4 &model, std::size_t level); // first every selected silhouette
    void outline(const GpuMesh &mesh, const glm::mat4 &model, std::size_t level,
                 const OutlineStyle &style); // then each ring
    // A ring that keeps off only the model's own silhouette (a flagged model's, which may lie
    // over a floor that is flagged or selected): after mark(), before outline().
    void outline_alone(const GpuMesh &mesh, const glm::mat4 &model, std::size_t level,
                       const OutlineStyle &style);
    void end();

  private:
    void ring(const GpuMesh &mesh, const glm::mat4 &model, std::size_t level, float pixels,
              const glm::vec3 &colour);

    ShaderProgram program_;
    int model_location_ = -1, view_projection_location_ = -1, pixels_location_ = -1, viewport_location_ = -1,
        colour_location_ = -1;
};

} // namespace animator
