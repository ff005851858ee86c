// Motion paths drawn over a frame (docs/manual.md, "Motion paths"): each path a line through
// the model's position at every frame, a dot at each frame, a larger mark at each of its keys
// and at each collision. Drawn over everything (no depth test), in the view the last frame was
// drawn with, so a path behind a model is not lost.
#pragma once

#include "render/shader_program.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace animator {

struct PathLines {
    std::vector<glm::vec3> frames; // world positions, one per frame, in time order
    std::vector<glm::vec3> keys;   // at the model's keys
    std::vector<glm::vec3> hits;   // at its collisions
};

struct PathStyle {
    glm::vec3 line{1.0f, 0.78f, 0.25f};  // amber
    glm::vec3 dot{0.08f, 0.08f, 0.1f};   // near black: reads on the sky and the floor
    glm::vec3 key{1.0f, 1.0f, 1.0f};     // white
    glm::vec3 hit{0.95f, 0.2f, 0.85f};   // magenta (red is the overlap ring's)
    float dot_pixels = 3.0f, key_pixels = 8.0f, hit_pixels = 10.0f;
};

class MotionPathOverlay {
  public:
    // Needs a current GL context for its whole life.
    MotionPathOverlay();
    ~MotionPathOverlay();
    MotionPathOverlay(const MotionPathOverlay &) = delete;
    MotionPathOverlay &operator=(const MotionPathOverlay &) = delete;

    // Into the bound framebuffer's current viewport.
    void draw(const std::vector<PathLines> &paths, const glm::mat4 &view_projection, const PathStyle &style);

  private:
    void upload(const std::vector<glm::vec3> &points);
    ShaderProgram program_;
    int view_projection_location_ = -1, colour_location_ = -1, size_location_ = -1;
    unsigned vertex_array_ = 0, buffer_ = 0;
};

} // namespace animator
