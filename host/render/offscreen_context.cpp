#include "render/offscreen_context.hpp"

#include "render/render_error.hpp"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <dlfcn.h>
#include <glad/gl.h>
#include <link.h>

#include <cstdio>
#include <cstring>

namespace animator {

namespace {

bool has_extension(const char *list, const char *name) {
    if (list == nullptr) return false;
    const size_t n = std::strlen(name);
    for (const char *p = list; (p = std::strstr(p, name)) != nullptr; p += n)
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    return false;
}

std::string egl_error(const char *what) {
    char code[16];
    (void)std::snprintf(code, sizeof code, "0x%04x", static_cast<unsigned>(eglGetError()));
    return std::string(what) + " failed (EGL error " + code + ")";
}

// Keeps Mesa's driver (swrast_dri.so, or another *_dri.so) loaded for the life of the process.
// eglTerminate unloads it otherwise, and a program that renders again loads it again; worse,
// the sanitizers then see its allocations and thread-local storage as belonging to no module,
// so its leaks cannot be suppressed and LeakSanitizer can crash.
int pin_driver(dl_phdr_info *info, size_t, void *) {
    if (info->dlpi_name && std::strstr(info->dlpi_name, "_dri.so"))
        dlopen(info->dlpi_name, RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
    return 0;
}

// An initialised display on the first platform that works, and its name; nullptr when none.
EGLDisplay open_display(std::string &platform, std::string &why) {
    const char *client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    auto get_platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!get_platform_display || !has_extension(client, "EGL_EXT_platform_base")) {
        why = "EGL has no EGL_EXT_platform_base";
        return EGL_NO_DISPLAY;
    }
    if (has_extension(client, "EGL_MESA_platform_surfaceless")) {
        EGLDisplay d =
            get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (d != EGL_NO_DISPLAY && eglInitialize(d, nullptr, nullptr)) {
            platform = "EGL surfaceless";
            return d;
        }
        why = egl_error("the surfaceless platform");
    }
    auto query_devices =
        reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    if (query_devices && has_extension(client, "EGL_EXT_platform_device")) {
        EGLDeviceEXT devices[16];
        EGLint count = 0;
        if (query_devices(16, devices, &count)) {
            for (EGLint i = 0; i < count; ++i) {
                EGLDisplay d = get_platform_display(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
                if (d != EGL_NO_DISPLAY && eglInitialize(d, nullptr, nullptr)) {
                    platform = "EGL device";
                    return d;
                }
            }
        }
        why += (why.empty() ? "" : "; ") + egl_error("every EGL device");
    }
    if (why.empty())
        why = "EGL offers neither EGL_MESA_platform_surfaceless nor EGL_EXT_platform_device";
    return EGL_NO_DISPLAY;
}

} // namespace

OffscreenContext::OffscreenContext() {
    std::string platform, why;
    EGLDisplay display = open_display(platform, why);
    if (display == EGL_NO_DISPLAY)
        throw RenderError("no off-screen OpenGL context: " + why +
                          " (install Mesa's EGL: libegl-mesa0, libgl1-mesa-dri)");
    display_ = display;
    dl_iterate_phdr(pin_driver, nullptr);
    const char *extensions = eglQueryString(display, EGL_EXTENSIONS);
    if (!has_extension(extensions, "EGL_KHR_surfaceless_context") ||
        !has_extension(extensions, "EGL_KHR_no_config_context")) {
        eglTerminate(display);
        throw RenderError("no off-screen OpenGL context: " + platform +
                          " lacks EGL_KHR_surfaceless_context or EGL_KHR_no_config_context");
    }
    if (!eglBindAPI(EGL_OPENGL_API)) {
        eglTerminate(display);
        throw RenderError("no off-screen OpenGL context: " + egl_error("eglBindAPI(OpenGL)"));
    }
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                 3,
                                 EGL_CONTEXT_MINOR_VERSION,
                                 3,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                 EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                 EGL_NONE};
    EGLContext context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
    if (context == EGL_NO_CONTEXT) {
        const std::string reason = egl_error("eglCreateContext(OpenGL 3.3 core)");
        eglTerminate(display);
        throw RenderError("no off-screen OpenGL context: " + platform + ": " + reason);
    }
    context_ = context;
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
        const std::string reason = egl_error("eglMakeCurrent");
        eglDestroyContext(display, context);
        eglTerminate(display);
        throw RenderError("no off-screen OpenGL context: " + platform + ": " + reason);
    }
    if (gladLoadGL(reinterpret_cast<GLADloadfunc>(eglGetProcAddress)) == 0) {
        eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display, context);
        eglTerminate(display);
        throw RenderError("no off-screen OpenGL context: glad could not load OpenGL 3.3");
    }
    auto text = [](GLenum name) {
        const auto *s = reinterpret_cast<const char *>(glGetString(name));
        return std::string(s ? s : "?");
    };
    description_ = platform + ": OpenGL " + text(GL_VERSION) + " on " + text(GL_RENDERER);
}

OffscreenContext::~OffscreenContext() {
    auto display = static_cast<EGLDisplay>(display_);
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display, static_cast<EGLContext>(context_));
    eglTerminate(display);
    eglReleaseThread();
}

} // namespace animator
