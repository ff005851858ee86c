// Images (textures and skybox faces) loaded through stb_image: PNG and BMP, the formats a
// texture or a skybox face is found by (asset_paths.cpp).
#pragma once

#include "assets/mesh.hpp" // AssetError

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <vector>

namespace animator {

struct Image {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgb; // width * height * 3, rows top to bottom
};

// The largest image loaded: 16384 pixels on a side (what most GPUs take as a texture) and
// 4096 x 4096 pixels in all, so that decoding one never needs more than a few hundred MiB
// even at 16 bits per channel with alpha.
constexpr int kMaxImageSide = 16384;
constexpr std::size_t kMaxImagePixels = std::size_t{4096} * 4096;

// Throws AssetError naming the file and what is wrong: not a PNG or BMP, corrupt (stb's
// reason), or larger than the limits above (refused from its header, before decoding).
Image load_image(const std::filesystem::path &path);

} // namespace animator
