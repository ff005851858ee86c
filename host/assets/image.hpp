// Images (textures and skybox faces) loaded through stb_image: PNG, BMP and the rest stb reads.
#pragma once

#include "assets/mesh.hpp" // AssetError

#include <cstdint>
#include <filesystem>
#include <vector>

namespace animator {

struct Image {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgb; // width * height * 3, rows top to bottom
};

// Throws AssetError naming the file and stb's reason.
Image load_image(const std::filesystem::path &path);

} // namespace animator
