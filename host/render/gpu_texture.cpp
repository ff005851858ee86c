#include "render/gpu_texture.hpp"

#include "render/render_error.hpp"

#include <glad/gl.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace animator {

GpuTexture GpuTexture::image_2d(const Image &image) {
    const size_t row = static_cast<size_t>(image.width) * 3;
    std::vector<std::uint8_t> bottom_up(image.rgb.size());
    for (int y = 0; y < image.height; ++y)
        std::copy_n(image.rgb.begin() + static_cast<std::ptrdiff_t>(row * static_cast<size_t>(y)),
                    row,
                    bottom_up.begin() + static_cast<std::ptrdiff_t>(
                                            row * static_cast<size_t>(image.height - 1 - y)));
    GLuint name = 0;
    glGenTextures(1, &name);
    glBindTexture(GL_TEXTURE_2D, name);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, image.width, image.height, 0, GL_RGB, GL_UNSIGNED_BYTE,
                 bottom_up.data());
    glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glBindTexture(GL_TEXTURE_2D, 0);
    return GpuTexture(name);
}

GpuTexture GpuTexture::cube_map(const std::array<Image, 6> &faces) {
    for (const Image &face : faces)
        if (face.width != faces[0].width || face.height != faces[0].height ||
            face.width != face.height || face.width <= 0)
            throw RenderError("the skybox's six faces must be squares of one size");
    GLuint name = 0;
    glGenTextures(1, &name);
    glBindTexture(GL_TEXTURE_CUBE_MAP, name);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (GLenum i = 0; i < 6; ++i)
        glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + i, 0, GL_RGBA8, faces[i].width,
                     faces[i].height, 0, GL_RGB, GL_UNSIGNED_BYTE, faces[i].rgb.data());
    glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
        glTexParameteri(GL_TEXTURE_CUBE_MAP, wrap, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
    return GpuTexture(name);
}

GpuTexture GpuTexture::solid_cube_map(const glm::vec3 &colour) {
    Image texel;
    texel.width = texel.height = 1;
    for (float c : {colour.r, colour.g, colour.b})
        texel.rgb.push_back(
            static_cast<std::uint8_t>(std::lround(std::clamp(c, 0.0f, 1.0f) * 255.0f)));
    return cube_map({texel, texel, texel, texel, texel, texel});
}

GpuTexture &GpuTexture::operator=(GpuTexture &&other) noexcept {
    std::swap(name_, other.name_);
    return *this;
}

GpuTexture::~GpuTexture() {
    if (name_ != 0) glDeleteTextures(1, &name_);
}

} // namespace animator
