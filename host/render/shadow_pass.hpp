// The shadow maps of a frame: for each shadow-casting light, the depth of the nearest caster as
// the light sees it (a depth pass into a depth texture), read by the shading plugin through a
// comparison sampler (sampler2DShadow, "shadow_map:N") with the matrix "shadow_matrix:N". Its
// depth pass slopes its depths away from the light (glPolygonOffset) and shading pushes points
// along their normals before looking them up, so lit surfaces do not shadow themselves (acne)
// while shadows stay attached to what casts them. Needs a current GL context for its whole life.
#pragma once

#include "render/gpu_mesh.hpp"
#include "render/shader_program.hpp"
#include "render/shading_programs.hpp"
#include "render/shadow_projection.hpp"

#include <glm/mat4x4.hpp>

#include <array>

namespace animator {

// The most lights that cast shadows (the first ones of the scene's); light N's map is bound on
// texture unit kFirstShadowUnit + N.
constexpr int kMaxShadowLights = kMaxShadowSemantics;

class ShadowPass {
  public:
    ShadowPass();
    ~ShadowPass();
    ShadowPass(const ShadowPass &) = delete;
    ShadowPass &operator=(const ShadowPass &) = delete;

    // Starts light `light`'s map, `size` texels square (its texture is made or resized), seen
    // through `projection`. Draw the casters (each at a level of detail), then finish().
    void begin(int light, int size, const ShadowProjection &projection);
    // A caster; `one_sided` when it is a closed mesh and the light is outside it (outside its
    // bounding sphere): only its faces turned to the light are drawn. Its depth map is the same
    // (the nearest surface along a ray entering a closed mesh is a face turned to the light),
    // and llvmpipe drops the others before binning them: about half a ball's triangles.
    void draw(const GpuMesh &mesh, const glm::mat4 &model, std::size_t level, bool one_sided);
    void finish();

    // Binds the maps of lights 0..count-1 to their units (kFirstShadowUnit + N).
    void bind(int count) const;
    int size(int light) const { return sizes_[static_cast<size_t>(light)]; }

  private:
    ShaderProgram program_;
    int model_location_ = -1, view_projection_location_ = -1;
    unsigned framebuffer_ = 0;
    std::array<unsigned, kMaxShadowLights> maps_{};
    std::array<int, kMaxShadowLights> sizes_{};
};

} // namespace animator
