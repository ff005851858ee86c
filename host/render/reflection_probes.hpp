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

namespace animator {

class ReflectionProbes {
  public:
    ReflectionProbes() = default;
    ~ReflectionProbes();
    ReflectionProbes(const ReflectionProbes &) = delete;
    ReflectionProbes &operator=(const ReflectionProbes &) = delete;

    // The camera of face `face` (0..5: +X, -X, +Y, -Y, +Z, -Z) at `centre`: what a direction
    // lookup of the cube map finds is what this camera draws (the GL specification's face
    // orientation: "up" is -Y on the side faces, +Z and -Z on the top and bottom).
    static glm::dmat4 face_view(int face, const glm::dvec3 &centre);
    // A square 90-degree perspective from `near` to `far`.
    static glm::dmat4 face_projection(double near, double far);

    // Draws model `model`'s cube map, `size` pixels a side, from `centre`: for each face, binds
    // it as the framebuffer (with a depth buffer), clears it to `background` and calls
    // draw_face(view, projection). Leaves the framebuffer it bound bound.
    void draw(int model, int size, const glm::dvec3 &centre, const glm::vec3 &background,
              const std::function<void(const glm::dmat4 &, const glm::dmat4 &)> &draw_face);
    // Model `model`'s cube map (a GL texture name) if drawn, else 0.
    unsigned texture(int model) const;
    // Frees the cube maps of the models `kept` says false of.
    void keep_only(const std::function<bool(int)> &kept);

  private:
    struct Probe {
        unsigned texture = 0;
        int size = 0;
    };
    std::map<int, Probe> probes_;
    unsigned framebuffer_ = 0, depth_ = 0;
    int depth_size_ = 0;
};

} // namespace animator
