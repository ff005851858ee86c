#include "image.hpp"

#include "file_io.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_WRITE_NO_STDIO // everything goes through write_bytes, which reports failures
#include <stb_image_write.h>

namespace animator::assetgen {

namespace {

void append(void *context, void *data, int size) {
    static_cast<std::string *>(context)->append(static_cast<const char *>(data),
                                                static_cast<std::size_t>(size));
}

} // namespace

Image::Image(int width, int height)
    : width_(width), height_(height), rgb_(static_cast<std::size_t>(width * height * 3), 0) {}

void Image::set(int x, int y, const glm::dvec3 &colour) {
    const auto offset = static_cast<std::size_t>((y * width_ + x) * 3);
    for (int c = 0; c < 3; ++c) {
        const double v = std::clamp(colour[c], 0.0, 1.0);
        rgb_[offset + static_cast<std::size_t>(c)] =
            static_cast<std::uint8_t>(std::lround(v * 255.0));
    }
}

void write_png(const std::filesystem::path &path, const Image &image) {
    std::string bytes;
    if (!stbi_write_png_to_func(append, &bytes, image.width(), image.height(), 3,
                                image.rgb().data(), image.width() * 3))
        throw std::runtime_error("cannot encode " + path.string());
    write_bytes(path, bytes);
}

void write_bmp(const std::filesystem::path &path, const Image &image) {
    std::string bytes;
    if (!stbi_write_bmp_to_func(append, &bytes, image.width(), image.height(), 3,
                                image.rgb().data()))
        throw std::runtime_error("cannot encode " + path.string());
    write_bytes(path, bytes);
}

} // namespace animator::assetgen
