// An 8-bit RGB image and its PNG/BMP encoders (stb_image_write).
#pragma once

#include <glm/vec3.hpp>

#include <cstdint>
#include <filesystem>
#include <vector>

namespace animator::assetgen {

class Image {
  public:
    Image(int width, int height);
    int width() const { return width_; }
    int height() const { return height_; }
    // Row 0 is the top row of the file. The colour is clamped to [0, 1] and rounded.
    void set(int x, int y, const glm::dvec3 &colour);
    const std::vector<std::uint8_t> &rgb() const { return rgb_; }

  private:
    int width_, height_;
    std::vector<std::uint8_t> rgb_;
};

void write_png(const std::filesystem::path &path, const Image &image);
void write_bmp(const std::filesystem::path &path, const Image &image);

} // namespace animator::assetgen
