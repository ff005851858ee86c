// Where a draw goes. A RenderTarget names any framebuffer and its size: 0 for a window's own
// (the editor), or an OffscreenFramebuffer's, whose colour can be read back (frames written to
// PNG, the tests).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace animator {

struct RenderTarget {
    unsigned framebuffer = 0; // a GL framebuffer object name; 0 is the window's
    int width = 0, height = 0;
    // Where the viewport starts in the framebuffer (GL's origin, bottom left): the editor draws
    // the scene in the space its panels leave. Only the viewport is cleared and drawn.
    int x = 0, y = 0;
};

// The multisample counts a framebuffer may be asked for (anti-aliasing; 1 is none).
bool valid_sample_count(int samples);
// "1, 2, 4 or 8": what valid_sample_count accepts, for messages.
const char *sample_counts_text();
// The most of `asked` samples the current GL gives (GL_MAX_SAMPLES; llvmpipe's is 4): `asked`, or
// the largest valid count below it, with `note` saying so when it is less.
int supported_samples(int asked, std::string *note = nullptr);

// A framebuffer object with an 8-bit RGBA colour, a 24-bit depth and an 8-bit stencil buffer
// (the renderer marks in it where a transparent model has something behind it). Needs a current
// GL context for its whole life.
//
// With samples > 1 (multisample anti-aliasing) the buffers drawn into are multisampled, and a
// second, single-sampled colour buffer receives them resolved (glBlitFramebuffer) before they are
// read back or copied elsewhere.
class OffscreenFramebuffer {
  public:
    // Throws RenderError for a size GL refuses, a sample count that is not 1, 2, 4 or 8 or above
    // GL_MAX_SAMPLES, or an incomplete framebuffer.
    OffscreenFramebuffer(int width, int height, int samples = 1);
    ~OffscreenFramebuffer();
    OffscreenFramebuffer(const OffscreenFramebuffer &) = delete;
    OffscreenFramebuffer &operator=(const OffscreenFramebuffer &) = delete;

    RenderTarget target() const { return {framebuffer_, width_, height_}; }
    int width() const { return width_; }
    int height() const { return height_; }
    // The samples a pixel asked for, and those GL gave (it may give more: llvmpipe draws 2x as 4x).
    int samples() const { return samples_; }
    int actual_samples() const { return actual_samples_; }

    // Copies the colour (resolved when multisampled) into `target`'s viewport: how the editor puts
    // its anti-aliased view on the window. A viewport of another size gets it stretched, filtered
    // (linear): the view drawn at a lower resolution.
    void copy_to(const RenderTarget &target) const;

    // The colour as 8-bit RGB, rows top first (as images are stored). `out` is resized to
    // width * height * 3, so reusing it allocates nothing.
    void read_rgb(std::vector<std::uint8_t> &out) const;

  private:
    void release();
    // The framebuffer whose colour is single-sampled: this one, or the resolved copy of it.
    unsigned resolved() const;

    unsigned framebuffer_ = 0, colour_ = 0, depth_ = 0;
    unsigned resolve_framebuffer_ = 0, resolve_colour_ = 0; // only when multisampled
    int width_, height_, samples_, actual_samples_ = 1;
    mutable std::vector<std::uint8_t> rgba_; // read_rgb's pixels as read, kept for the next frame
};

} // namespace animator
