#include "render/framebuffer.hpp"

#include "render/render_error.hpp"

#include <glad/gl.h>

#include <algorithm>
#include <string>

namespace animator {

OffscreenFramebuffer::OffscreenFramebuffer(int width, int height) : width_(width), height_(height) {
    GLint largest = 0;
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &largest);
    if (width <= 0 || height <= 0 || width > largest || height > largest)
        throw RenderError("a frame of " + std::to_string(width) + "x" + std::to_string(height) +
                          " pixels is not possible (1 to " + std::to_string(largest) + " a side)");
    glGenFramebuffers(1, &framebuffer_);
    glGenRenderbuffers(1, &colour_);
    glGenRenderbuffers(1, &depth_);
    glBindRenderbuffer(GL_RENDERBUFFER, colour_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, depth_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depth_);
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
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
    framebuffer_ = colour_ = depth_ = 0;
}

void OffscreenFramebuffer::read_rgb(std::vector<std::uint8_t> &out) const {
    const size_t row = static_cast<size_t>(width_) * 3;
    out.resize(row * static_cast<size_t>(height_));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width_, height_, GL_RGB, GL_UNSIGNED_BYTE, out.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    // GL's rows run bottom up; images are stored top first.
    for (size_t top = 0, bottom = static_cast<size_t>(height_) - 1; top < bottom; ++top, --bottom)
        std::swap_ranges(out.begin() + static_cast<std::ptrdiff_t>(top * row),
                         out.begin() + static_cast<std::ptrdiff_t>((top + 1) * row),
                         out.begin() + static_cast<std::ptrdiff_t>(bottom * row));
}

} // namespace animator
