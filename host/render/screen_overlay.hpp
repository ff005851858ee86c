// Flat shapes drawn over the 3D view in its own pixels (the transform gizmo's arrows, rings and
// boxes: editor/gizmo.hpp): triangles built on the CPU (a line of any width is two triangles, as
// a core profile need not draw wide lines), drawn over everything, without depth or blending.
#pragma once

#include "render/shader_program.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace animator {

struct OverlayVertex {
    glm::vec2 position; // pixels: x right, y down from the view's top-left corner
    glm::vec3 colour;
};

// Triangles, three vertices each, in the order they are drawn (later over earlier).
struct OverlayTriangles {
    std::vector<OverlayVertex> vertices;
    void line(glm::vec2 a, glm::vec2 b, float width, glm::vec3 colour);
    void polyline(const std::vector<glm::vec2> &points, bool closed, float width, glm::vec3 colour);
    // A convex polygon, filled.
    void convex(const std::vector<glm::vec2> &points, glm::vec3 colour);
};

class ScreenOverlay {
  public:
    // Needs a current GL context for its whole life.
    ScreenOverlay();
    ~ScreenOverlay();
    ScreenOverlay(const ScreenOverlay &) = delete;
    ScreenOverlay &operator=(const ScreenOverlay &) = delete;

    // Into the bound framebuffer's current viewport, which shows `width` x `height` of the
    // triangles' pixels (the view's size in window coordinates; the viewport may have more).
    void draw(const OverlayTriangles &triangles, float width, float height);

  private:
    ShaderProgram program_;
    int size_location_ = -1;
    unsigned vertex_array_ = 0, buffer_ = 0;
};

} // namespace animator
