// Reflections of other models (seed, "Reflecting Other Models"): each reflective or transparent
// model gets a cube map drawn every frame from its centre, with the skybox and every other model
// in it, and its reflection and refraction sample that cube map instead of the skybox alone (a
// dynamic environment map, as real-time engines' reflection probes). A face is drawn by a
// 90-degree camera looking along one axis, in GL's cube-map order and orientation, so the shading
// plugin's programs sample it as they sample the skybox: by a world direction.
#pragma once

#include <glm/mat4x4.hpp>

#include <functional>
#include <map>
#include <memory>
#include <vector>

namespace animator {

class ShaderProgram;

class ReflectionProbes {
  public:
    ReflectionProbes();
    ~ReflectionProbes();
    ReflectionProbes(const ReflectionProbes &) = delete;
    ReflectionProbes &operator=(const ReflectionProbes &) = delete;

    // The camera of face `face` (0..5: +X, -X, +Y, -Y, +Z, -Z) at `centre`: what a direction
    // lookup of the cube map finds is what this camera draws (the GL specification's face
    // orientation: "up" is -Y on the side faces, +Z and -Z on the top and bottom).
    static glm::dmat4 face_view(int face, const glm::dvec3 &centre);
    // A square 90-degree perspective from `near` to `far`.
    static glm::dmat4 face_projection(double near, double far);
    // What draw() draws a face with: face_projection(kNear, kFar) * face_view(face, centre).
    static glm::dmat4 face_view_projection(int face, const glm::dvec3 &centre);
    static constexpr double kNear = 0.05, kFar = 1000.0;

    // A cube map (RGBA8) whose level `level` has faces as large as the probes': the skybox, the
    // same from every centre, copied into a probe instead of drawn into each of its faces.
    struct Sky {
        unsigned texture = 0;
        int level = 0;
    };
    // Whether draw() can copy a Sky (GL_ARB_copy_image, core in OpenGL 4.3).
    static bool copies_sky();

    // Draws model `model`'s cube map, `size` pixels a side, from `centre`: copies `sky` into it
    // when given (copies_sky() must be true), then for each face binds it as the framebuffer
    // (with a depth buffer), clears it (its depth only over a sky, else to `background` too) and
    // calls draw_face(view, projection). Over a sky only the faces whose bits `faces` has set
    // (1 << face) are drawn: the others, where nothing is seen, keep the sky. Leaves the
    // framebuffer it bound bound.
    void draw(int model, int size, const glm::dvec3 &centre, const glm::vec3 &background,
              const Sky *sky, unsigned faces,
              const std::function<void(const glm::dmat4 &, const glm::dmat4 &)> &draw_face);
    // Makes the mipmap levels of the cube maps drawn since the last call: call it after the
    // last draw() of a frame, before the cube maps are sampled.
    void finish();
    // Model `model`'s cube map (a GL texture name) if drawn, else 0.
    unsigned texture(int model) const;
    // Frees the cube maps of the models `kept` says false of.
    void keep_only(const std::function<bool(int)> &kept);
    // Whether finish() draws the levels layered, all six faces of several cube maps at once: the
    // OpenGL has GL_ARB_shader_viewport_layer_array, the program compiled, and
    // ANIMATOR_PROBE_MIPMAPS is not set (it asks for glGenerateMipmap, to compare). Decided on
    // the first call.
    bool layered();
    // How many cube maps finish() makes the levels of in one draw a level (0 until layered() has
    // said yes): at most 8, and as many as the OpenGL has draw buffers, colour attachments and
    // texture units.
    std::size_t at_once() const { return at_once_; }

  private:
    struct Probe {
        unsigned texture = 0;
        int size = 0;
    };
    // The cube maps' last mipmap level (three levels: see draw()).
    static constexpr int kLastLevel = 2;
    static constexpr std::size_t kMostAtOnce = 8;
    // Makes levels 1 .. kLastLevel of the cube maps of `batch` (at most at_once_, of one size)
    // from their level 0, in one layered draw a level.
    void make_levels(const std::vector<const Probe *> &batch);
    // The program that makes a level of `count` cube maps, compiled on first use; null if it
    // does not compile.
    ShaderProgram *downsample(std::size_t count);

    std::map<int, Probe> probes_;
    unsigned framebuffer_ = 0, depth_ = 0;
    int depth_size_ = 0;
    bool tried_layers_ = false;
    std::size_t at_once_ = 0;
    std::unique_ptr<ShaderProgram> downsample_[kMostAtOnce];
    unsigned layers_framebuffer_ = 0, empty_vertices_ = 0;
    int attached_ = 0;           // colour attachments layers_framebuffer_ has
    std::vector<int> unleveled_; // the models whose cube maps draw() drew, finish() to level
};

} // namespace animator
