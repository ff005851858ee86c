// Picking for the editor: which model is under a pixel. Models are drawn with their index + 1 as
// an integer colour into an off-screen R32UI buffer (0 is nothing), with the scissor shrunk to
// the one pixel asked about, so a pick costs a fraction of a frame.
#pragma once

#include "render/gpu_mesh.hpp"
#include "render/shader_program.hpp"

#include <glm/mat4x4.hpp>

#include <cstdint>
#include <memory>

namespace animator {

class PickingPass {
  public:
    // Needs a current GL context for its whole life.
    PickingPass();
    ~PickingPass();
    PickingPass(const PickingPass &) = delete;
    PickingPass &operator=(const PickingPass &) = delete;

    // Starts a pass over a target of this size at pixel (x, y) from the top left. Returns false
    // (and draws nothing) for a pixel outside it.
    bool begin(int width, int height, int x, int y, const glm::mat4 &view_projection);
    // A model's mesh at level of detail `level` (the one it is drawn with), as `id`.
    void draw(const GpuMesh &mesh, const glm::mat4 &model, std::size_t level, std::uint32_t id);
    // The id drawn at the pixel, 0 for none; ends the pass.
    std::uint32_t finish();

  private:
    void resize(int width, int height);

    ShaderProgram program_;
    int model_location_ = -1, view_projection_location_ = -1, id_location_ = -1;
    unsigned framebuffer_ = 0, ids_ = 0, depth_ = 0;
    int width_ = 0, height_ = 0, x_ = 0, y_ = 0;
};

} // namespace animator
