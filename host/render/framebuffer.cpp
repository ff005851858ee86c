#include "render/framebuffer.hpp"

#include "render/render_error.hpp"

#include <glad/gl.h>

#include <algorithm>
#include <string>

namespace animator {

namespace {

// Colour (RGBA8) and depth-stencil renderbuffers of `samples` samples on a new framebuffer.
unsigned make_framebuffer(int width, int height, int samples, unsigned &colour, unsigned *depth) {
    unsigned framebuffer = 0;
    glGenFramebuffers(1, &framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glGenRenderbuffers(1, &colour);
    glBindRenderbuffer(GL_RENDERBUFFER, colour);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples > 1 ? samples : 0, GL_RGBA8, width,
                                     height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour);
    if (depth) {
        glGenRenderbuffers(1, depth);
        glBindRenderbuffer(GL_RENDERBUFFER, *depth);
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples > 1 ? samples : 0,
                                         GL_DEPTH24_STENCIL8, width, height);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                                  *depth);
    }
    return framebuffer;
}

} // namespace

bool valid_sample_count(int samples) {
    return samples == 1 || samples == 2 || samples == 4 || samples == 8;
}

const char *sample_counts_text() {
    return "1, 2, 4 or 8";
}

int supported_samples(int asked, std::string *note) {
    GLint most = 1;
    glGetIntegerv(GL_MAX_SAMPLES, &most);
    int samples = asked;
    while (samples > 1 && samples > most) samples /= 2;
    if (samples != asked && note)
        *note = "anti-aliasing with " + std::to_string(asked) +
                " samples is not possible on this OpenGL (at most " + std::to_string(most) +
                "); drawing with " + std::to_string(samples);
    return samples;
}

OffscreenFramebuffer::OffscreenFramebuffer(int width, int height, int samples)
    : width_(width), height_(height), samples_(samples) {
    GLint largest = 0;
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &largest);
    if (width <= 0 || height <= 0 || width > largest || height > largest)
        throw RenderError("a frame of " + std::to_string(width) + "x" + std::to_string(height) +
                          " pixels is not possible (1 to " + std::to_string(largest) + " a side)");
    GLint most_samples = 0;
    glGetIntegerv(GL_MAX_SAMPLES, &most_samples);
    if (!valid_sample_count(samples) || samples > most_samples)
        throw RenderError("anti-aliasing with " + std::to_string(samples) +
                          " samples is not possible (" + sample_counts_text() + ", at most " +
                          std::to_string(most_samples) + " on this OpenGL)");
    framebuffer_ = make_framebuffer(width, height, samples, colour_, &depth_);
    glBindRenderbuffer(GL_RENDERBUFFER, colour_);
    GLint given = 0;
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_SAMPLES, &given);
    actual_samples_ = std::max(1, static_cast<int>(given));
    GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status == GL_FRAMEBUFFER_COMPLETE && samples > 1) {
        resolve_framebuffer_ = make_framebuffer(width, height, 1, resolve_colour_, nullptr);
        status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        release();
        throw RenderError("the off-screen framebuffer is incomplete (status " +
                          std::to_string(status) + ")");
    }
}

OffscreenFramebuffer::~OffscreenFramebuffer() {
    release();
}

void OffscreenFramebuffer::release() {
    glDeleteFramebuffers(1, &framebuffer_);
    glDeleteRenderbuffers(1, &colour_);
    glDeleteRenderbuffers(1, &depth_);
    glDeleteFramebuffers(1, &resolve_framebuffer_);
    glDeleteRenderbuffers(1, &resolve_colour_);
    framebuffer_ = colour_ = depth_ = resolve_framebuffer_ = resolve_colour_ = 0;
}

unsigned OffscreenFramebuffer::resolved() const {
    if (!resolve_framebuffer_) return framebuffer_;
    // Each pixel's samples averaged into one (the multisample resolve).
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolve_framebuffer_);
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT,
                      GL_NEAREST);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    return resolve_framebuffer_;
}

void OffscreenFramebuffer::copy_to(const RenderTarget &target) const {
    const bool same_size = target.width == width_ && target.height == height_;
    // A multisampled source may be blitted to a single-sampled target of its own size only:
    // stretched, it is resolved first.
    glBindFramebuffer(GL_READ_FRAMEBUFFER, same_size ? framebuffer_ : resolved());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target.framebuffer);
    glBlitFramebuffer(0, 0, width_, height_, target.x, target.y, target.x + target.width,
                      target.y + target.height, GL_COLOR_BUFFER_BIT,
                      same_size ? GL_NEAREST : GL_LINEAR);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void OffscreenFramebuffer::read_rgb(std::vector<std::uint8_t> &out) const {
    const auto w = static_cast<size_t>(width_), h = static_cast<size_t>(height_);
    out.resize(w * h * 3);
    // Read as the colour buffer stores it, RGBA: llvmpipe copies that as it is, where GL_RGB had
    // it convert every pixel (1.5 ms of a 1280x720 frame, docs/performance.md). Then the alpha
    // dropped here, with the rows turned top first as images are stored (GL's run bottom up).
    rgba_.resize(w * h * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, resolved());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, rgba_.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    for (size_t y = 0; y < h; ++y) {
        const std::uint8_t *from = rgba_.data() + (h - 1 - y) * w * 4;
        std::uint8_t *to = out.data() + y * w * 3;
        for (size_t x = 0; x < w; ++x, from += 4, to += 3) {
            to[0] = from[0];
            to[1] = from[1];
            to[2] = from[2];
        }
    }
}

} // namespace animator
