// Where a draw goes. A RenderTarget names any framebuffer and its size: 0 for a window's own
// (the editor), or an OffscreenFramebuffer's, whose colour can be read back (frames written to
// PNG, the tests).
#pragma once

#include <cstdint>
#include <vector>

namespace animator {

struct RenderTarget {
    unsigned framebuffer = 0; // a GL framebuffer object name; 0 is the window's
    int width = 0, height = 0;
    // Where the viewport starts in the framebuffer (GL's origin, bottom left): the editor draws
    // the scene in the space its panels leave. Only the viewport is cleared and drawn.
    int x = 0, y = 0;
};

// A framebuffer object with an 8-bit RGBA colour, a 24-bit depth and an 8-bit stencil buffer
// (the renderer marks in it where a transparent model has something behind it). Needs a current
// GL context for its whole life.
class OffscreenFramebuffer {
  public:
    // Throws RenderError for a size GL refuses or an incomplete framebuffer.
    OffscreenFramebuffer(int width, int height);
    ~OffscreenFramebuffer();
    OffscreenFramebuffer(const OffscreenFramebuffer &) = delete;
    OffscreenFramebuffer &operator=(const OffscreenFramebuffer &) = delete;

    RenderTarget target() const { return {framebuffer_, width_, height_}; }
    int width() const { return width_; }
    int height() const { return height_; }

    // The colour as 8-bit RGB, rows top first (as images are stored). `out` is resized to
    // width * height * 3, so reusing it allocates nothing.
    void read_rgb(std::vector<std::uint8_t> &out) const;

  private:
    void release();

    unsigned framebuffer_ = 0, colour_ = 0, depth_ = 0;
    int width_, height_;
};

} // namespace animator
