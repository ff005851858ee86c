#include "render/reflection_probes.hpp"

#include "render/render_error.hpp"
#include "render/shader_program.hpp"

#include <glad/gl.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <string>

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

// A level of cube maps from the level above, their six faces in one draw: a triangle covering
// the face, once a face (gl_Layer from the instance, GL_ARB_shader_viewport_layer_array), each
// pixel the bilinear sample at the corner its 2x2 texels above share, which is their average: the
// box filter glGenerateMipmap uses. The direction of a face's (s, t) inverts the GL
// specification's cube-map face selection (its table of major axes and sc, tc).
constexpr const char *kDownsampleVertex = R"(#version 330 core
#extension GL_ARB_shader_viewport_layer_array : require
out vec2 st;
flat out int face;
void main() {
    vec2 p = vec2(float((gl_VertexID & 1) * 4 - 1), float((gl_VertexID & 2) * 2 - 1));
    st = p;
    face = gl_InstanceID;
    gl_Layer = gl_InstanceID;
    gl_Position = vec4(p, 0.0, 1.0);
}
)";

// The fragment stage for `count` cube maps at once, one colour output each (a framebuffer with
// that many attachments): `above<i>` is cube map i at the level above.
std::string downsample_fragment(int count) {
    std::string source = "#version 330 core\n"
                         "uniform float above_level;\n"
                         "in vec2 st;\n"
                         "flat in int face;\n";
    for (int i = 0; i < count; ++i) {
        const std::string n = std::to_string(i);
        source += "uniform samplerCube above" + n + ";\nlayout(location = " + n +
                  ") out vec4 colour" + n + ";\n";
    }
    source += R"(void main() {
    float sc = st.x, tc = st.y;
    vec3 d;
    if (face == 0) d = vec3(1.0, -tc, -sc);
    else if (face == 1) d = vec3(-1.0, -tc, sc);
    else if (face == 2) d = vec3(sc, 1.0, tc);
    else if (face == 3) d = vec3(sc, -1.0, -tc);
    else if (face == 4) d = vec3(sc, -tc, 1.0);
    else d = vec3(-sc, -tc, -1.0);
)";
    for (int i = 0; i < count; ++i) {
        const std::string n = std::to_string(i);
        source += "    colour" + n + " = textureLod(above" + n + ", d, above_level);\n";
    }
    return source + "}\n";
}

bool has_extension(const char *name) {
    GLint count = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count; ++i) {
        const auto *e = reinterpret_cast<const char *>(glGetStringi(GL_EXTENSIONS, static_cast<GLuint>(i)));
        if (e && std::strcmp(e, name) == 0) return true;
    }
    return false;
}

} // namespace

ReflectionProbes::~ReflectionProbes() {
    for (const auto &[model, probe] : probes_) glDeleteTextures(1, &probe.texture);
    if (depth_) glDeleteRenderbuffers(1, &depth_);
    if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
    if (layers_framebuffer_) glDeleteFramebuffers(1, &layers_framebuffer_);
    if (empty_vertices_) glDeleteVertexArrays(1, &empty_vertices_);
}

ReflectionProbes::ReflectionProbes() = default;

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

bool ReflectionProbes::copies_sky() {
    return GLAD_GL_ARB_copy_image != 0;
}

glm::dmat4 ReflectionProbes::face_view_projection(int face, const glm::dvec3 &centre) {
    return face_projection(kNear, kFar) * face_view(face, centre);
}

void ReflectionProbes::draw(
    int model, int size, const glm::dvec3 &centre, const glm::vec3 &background, const Sky *sky,
    unsigned faces, const std::function<void(const glm::dmat4 &, const glm::dmat4 &)> &draw_face) {
    Probe &probe = probes_[model];
    if (probe.size != size) {
        if (probe.texture) glDeleteTextures(1, &probe.texture); // (unbound wherever it was)
        glGenTextures(1, &probe.texture);
        const CubeMapBound bound(probe.texture);
        for (int level = 0; level <= kLastLevel; ++level)
            for (GLenum f = 0; f < 6; ++f)
                glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, level, GL_RGBA8,
                             std::max(1, size >> level), std::max(1, size >> level), 0, GL_RGBA,
                             GL_UNSIGNED_BYTE, nullptr);
        // Mipmapped as the skybox is: along a silhouette the shading is extrapolated, and a
        // reflected direction there jumps from pixel to pixel; a single level then sparkles.
        // Three levels are enough for that (a fifth of the frame's time went to making all eight
        // of a 128-pixel map on llvmpipe; with three, it looked the same).
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LEVEL, kLastLevel);
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
    // The sky under everything, its six faces in one copy (a memcpy on llvmpipe, where drawing
    // it into each face was a sixth of a probe's time): what the probe's faces would draw of it,
    // their pixel centres on that level's texel centres.
    if (sky)
        glCopyImageSubData(sky->texture, GL_TEXTURE_CUBE_MAP, sky->level, 0, 0, 0, probe.texture,
                           GL_TEXTURE_CUBE_MAP, 0, 0, 0, 0, size, size, 6);
    glViewport(0, 0, size, size);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glDepthMask(GL_TRUE);
    glClearColor(background.r, background.g, background.b, 1.0f);
    const glm::dmat4 projection = face_projection(kNear, kFar);
    // (Each face drawn is a pass of its own on llvmpipe, with a fixed cost: six cube maps of
    // nothing but their sky took 7 ms a frame, docs/performance.md.)
    if (!sky) faces = 0x3f;
    bool checked = false;
    for (int f = 0; f < 6; ++f) {
        if (!(faces & (1u << f))) continue;
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                               GL_TEXTURE_CUBE_MAP_POSITIVE_X + static_cast<GLenum>(f),
                               probe.texture, 0);
        if (!checked && glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            throw RenderError("a reflection cube map cannot be drawn into");
        checked = true;
        glClear(sky ? GL_DEPTH_BUFFER_BIT : GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        draw_face(face_view(f, centre), projection);
    }
    unleveled_.push_back(model);
}

void ReflectionProbes::finish() {
    // After every probe's faces: on llvmpipe the first level drawn waits for all the faces drawn
    // before it, once, where making each probe's levels after its faces waited six times.
    if (!layered()) {
        for (int model : unleveled_) {
            const CubeMapBound bound(probes_.at(model).texture);
            glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
        }
        unleveled_.clear();
        return;
    }
    // Up to at_once_ cube maps of one size a draw: each draw is a pass of its own on llvmpipe,
    // with a fixed cost (docs/performance.md), and six cube maps made their levels in twelve.
    std::vector<const Probe *> batch;
    for (std::size_t i = 0; i < unleveled_.size(); ++i) {
        const Probe &probe = probes_.at(unleveled_[i]);
        if (!batch.empty() && (batch.size() == at_once_ || batch.front()->size != probe.size)) {
            make_levels(batch);
            batch.clear();
        }
        batch.push_back(&probe);
    }
    if (!batch.empty()) make_levels(batch);
    unleveled_.clear();
}

bool ReflectionProbes::layered() {
    if (!tried_layers_) {
        tried_layers_ = true;
        if (!std::getenv("ANIMATOR_PROBE_MIPMAPS") && has_extension("GL_ARB_shader_viewport_layer_array")) {
            GLint buffers = 1, attachments = 1, units = 1;
            glGetIntegerv(GL_MAX_DRAW_BUFFERS, &buffers);
            glGetIntegerv(GL_MAX_COLOR_ATTACHMENTS, &attachments);
            glGetIntegerv(GL_MAX_TEXTURE_IMAGE_UNITS, &units);
            at_once_ = static_cast<std::size_t>(std::clamp(std::min({buffers, attachments, units}),
                                                           1, static_cast<int>(kMostAtOnce)));
            if (!downsample(1)) at_once_ = 0; // glGenerateMipmap then
        }
    }
    return at_once_ > 0;
}

ShaderProgram *ReflectionProbes::downsample(std::size_t count) {
    std::unique_ptr<ShaderProgram> &program = downsample_[count - 1];
    if (!program) {
        try {
            program = std::make_unique<ShaderProgram>(kDownsampleVertex,
                                                      downsample_fragment(static_cast<int>(count)));
        } catch (const ShaderError &) {
            return nullptr;
        }
    }
    return program.get();
}

void ReflectionProbes::make_levels(const std::vector<const Probe *> &batch) {
    // glGenerateMipmap on llvmpipe blits each face of each level apart, a draw and a wait each:
    // twelve a probe, a fifth of the frame with six probes (docs/performance.md). Here: two for
    // the whole batch, each cube map an attachment of its own and a unit of its own.
    ShaderProgram *program = downsample(batch.size());
    if (!program) { // (the one-at-a-time program compiled: layered())
        for (const Probe *probe : batch) make_levels({probe});
        return;
    }
    const auto count = static_cast<GLsizei>(batch.size());
    GLint current = 0, vertices = 0, active = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &current);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertices);
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    const GLboolean depth_test = glIsEnabled(GL_DEPTH_TEST);
    if (!layers_framebuffer_) glGenFramebuffers(1, &layers_framebuffer_);
    if (!empty_vertices_) glGenVertexArrays(1, &empty_vertices_);
    glBindFramebuffer(GL_FRAMEBUFFER, layers_framebuffer_);
    glBindVertexArray(empty_vertices_);
    glUseProgram(program->name());
    // Attachments left from a larger batch are taken off (an attachment may not be sampled).
    for (GLsizei i = count; i < attached_; ++i)
        glFramebufferTexture(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i), 0, 0);
    attached_ = count;
    GLenum buffers[kMostAtOnce];
    GLint held[kMostAtOnce];
    for (GLsizei i = 0; i < count; ++i) {
        buffers[i] = GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i);
        glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(i));
        glGetIntegerv(GL_TEXTURE_BINDING_CUBE_MAP, &held[i]);
        glBindTexture(GL_TEXTURE_CUBE_MAP, batch[static_cast<std::size_t>(i)]->texture);
        glUniform1i(program->uniform_location("above" + std::to_string(i)), i);
    }
    glDrawBuffers(count, buffers);
    const GLint level_at = program->uniform_location("above_level");
    glDisable(GL_DEPTH_TEST);
    for (int level = 1; level <= kLastLevel; ++level) {
        for (GLsizei i = 0; i < count; ++i) {
            // Only the level above is sampled while this one is drawn (no feedback).
            glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(i));
            glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_BASE_LEVEL, level - 1);
            glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LEVEL, level - 1);
            glFramebufferTexture(GL_FRAMEBUFFER, buffers[i],
                                 batch[static_cast<std::size_t>(i)]->texture, level);
        }
        const int side = std::max(1, batch.front()->size >> level);
        glViewport(0, 0, side, side);
        glUniform1f(level_at, static_cast<float>(level - 1));
        glDrawArraysInstanced(GL_TRIANGLES, 0, 3, 6);
    }
    for (GLsizei i = 0; i < count; ++i) {
        glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(i));
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_BASE_LEVEL, 0);
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LEVEL, kLastLevel);
        glBindTexture(GL_TEXTURE_CUBE_MAP, static_cast<GLuint>(held[i]));
    }
    glActiveTexture(static_cast<GLenum>(active));
    if (depth_test) glEnable(GL_DEPTH_TEST);
    glBindVertexArray(static_cast<GLuint>(vertices));
    glUseProgram(static_cast<GLuint>(current));
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
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
        unleveled_.erase(std::remove(unleveled_.begin(), unleveled_.end(), it->first), unleveled_.end());
        it = probes_.erase(it);
    }
}

} // namespace animator
