#include "render/reflection_probes.hpp"

#include "render/render_error.hpp"

#include <glad/gl.h>
#include <glm/gtc/matrix_transform.hpp>

namespace animator {

namespace {

// Binds a cube map on the active texture unit for as long as it lives, then puts back the one
// that was there: the renderer keeps track of what its units hold (Renderer::bind).
struct CubeMapBound {
    GLint held = 0;
    explicit CubeMapBound(GLuint texture) {
        glGetIntegerv(GL_TEXTURE_BINDING_CUBE_MAP, &held);
        glBindTexture(GL_TEXTURE_CUBE_MAP, texture);
    }
    ~CubeMapBound() { glBindTexture(GL_TEXTURE_CUBE_MAP, static_cast<GLuint>(held)); }
};

} // namespace

ReflectionProbes::~ReflectionProbes() {
    for (const auto &[model, probe] : probes_) glDeleteTextures(1, &probe.texture);
    if (depth_) glDeleteRenderbuffers(1, &depth_);
    if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
}

glm::dmat4 ReflectionProbes::face_view(int face, const glm::dvec3 &centre) {
    static const glm::dvec3 forward[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                          {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
    static const glm::dvec3 up[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1},
                                     {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
    return glm::lookAt(centre, centre + forward[face], up[face]);
}

glm::dmat4 ReflectionProbes::face_projection(double near, double far) {
    return glm::perspective(glm::radians(90.0), 1.0, near, far);
}

void ReflectionProbes::draw(
    int model, int size, const glm::dvec3 &centre, const glm::vec3 &background,
    const std::function<void(const glm::dmat4 &, const glm::dmat4 &)> &draw_face) {
    Probe &probe = probes_[model];
    if (probe.size != size) {
        if (probe.texture) glDeleteTextures(1, &probe.texture); // (unbound wherever it was)
        glGenTextures(1, &probe.texture);
        const CubeMapBound bound(probe.texture);
        for (GLenum f = 0; f < 6; ++f)
            glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, GL_RGBA8, size, size, 0, GL_RGBA,
                         GL_UNSIGNED_BYTE, nullptr);
        // Mipmapped as the skybox is: along a silhouette the shading is extrapolated, and a
        // reflected direction there jumps from pixel to pixel; a single level then sparkles.
        // Three levels are enough for that (a fifth of the frame's time went to making all eight
        // of a 128-pixel map on llvmpipe; with three, it looked the same).
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LEVEL, 2);
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
            glTexParameteri(GL_TEXTURE_CUBE_MAP, wrap, GL_CLAMP_TO_EDGE);
        probe.size = size;
    }
    if (!framebuffer_) glGenFramebuffers(1, &framebuffer_);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    if (depth_size_ != size) {
        if (!depth_) glGenRenderbuffers(1, &depth_);
        glBindRenderbuffer(GL_RENDERBUFFER, depth_);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, size, size);
        glBindRenderbuffer(GL_RENDERBUFFER, 0);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
        depth_size_ = size;
    }
    glViewport(0, 0, size, size);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glDepthMask(GL_TRUE);
    glClearColor(background.r, background.g, background.b, 1.0f);
    const glm::dmat4 projection = face_projection(0.05, 1000.0);
    for (int f = 0; f < 6; ++f) {
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                               GL_TEXTURE_CUBE_MAP_POSITIVE_X + static_cast<GLenum>(f),
                               probe.texture, 0);
        if (f == 0 && glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            throw RenderError("a reflection cube map cannot be drawn into");
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        draw_face(face_view(f, centre), projection);
    }
    const CubeMapBound bound(probe.texture);
    glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
}

unsigned ReflectionProbes::texture(int model) const {
    const auto found = probes_.find(model);
    return found == probes_.end() ? 0 : found->second.texture;
}

void ReflectionProbes::keep_only(const std::function<bool(int)> &kept) {
    for (auto it = probes_.begin(); it != probes_.end();) {
        if (kept(it->first)) {
            ++it;
            continue;
        }
        glDeleteTextures(1, &it->second.texture);
        it = probes_.erase(it);
    }
}

} // namespace animator
