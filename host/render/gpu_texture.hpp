// Images on the GPU: a model's texture (seed, "Texture Mapping": linear filtering) and the
// skybox's cube map (seed, "Skybox": six faces in GL_TEXTURE_CUBE_MAP).
#pragma once

#include "assets/image.hpp"

#include <glm/vec3.hpp>

#include <array>

namespace animator {

// One GL texture name, deleted with the object. Needs a current GL context for its whole life.
class GpuTexture {
  public:
    // A 2D texture, flipped so UV (0, 0) is the image's bottom left (the OBJ convention), with
    // mipmaps and linear filtering, repeating.
    static GpuTexture image_2d(const Image &image);
    // A cube map from faces in GL order (+X, -X, +Y, -Y, +Z, -Z: right, left, top, bottom,
    // front, back), uploaded unflipped as docs/assets.md says, RGBA8 with every mipmap level (so
    // a level can be copied into a reflection's cube map: ReflectionProbes::Sky). Throws
    // RenderError for faces that are not squares of one size.
    static GpuTexture cube_map(const std::array<Image, 6> &faces);
    // A cube map of one colour everywhere: what reflection and refraction see without a skybox.
    static GpuTexture solid_cube_map(const glm::vec3 &colour);

    GpuTexture(GpuTexture &&other) noexcept : name_(other.name_) { other.name_ = 0; }
    GpuTexture &operator=(GpuTexture &&other) noexcept;
    ~GpuTexture();
    GpuTexture(const GpuTexture &) = delete;
    GpuTexture &operator=(const GpuTexture &) = delete;

    unsigned name() const { return name_; }

  private:
    explicit GpuTexture(unsigned name) : name_(name) {}
    unsigned name_ = 0;
};

} // namespace animator
