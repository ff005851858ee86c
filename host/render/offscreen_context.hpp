// An OpenGL 3.3 core context with no window and no display server, for `animator render` and the
// render tests: EGL on Mesa's surfaceless platform (EGL_MESA_platform_surfaceless), else on an EGL
// device (EGL_EXT_platform_device). Draws go to framebuffer objects (framebuffer.hpp). The editor
// uses its GLFW window's context instead; the renderer works with either.
#pragma once

#include <string>

namespace animator {

class OffscreenContext {
  public:
    // Creates the context, makes it current on this thread and loads the GL functions (glad).
    // Throws RenderError saying what EGL refused.
    OffscreenContext();
    ~OffscreenContext();
    OffscreenContext(const OffscreenContext &) = delete;
    OffscreenContext &operator=(const OffscreenContext &) = delete;

    // "EGL surfaceless: OpenGL 4.5 (Core Profile) Mesa 22.3.6 on llvmpipe (...)"
    const std::string &description() const { return description_; }

  private:
    void *display_ = nullptr; // EGLDisplay
    void *context_ = nullptr; // EGLContext
    std::string description_;
};

} // namespace animator
