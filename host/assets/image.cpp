#include "assets/image.hpp"

#define STB_IMAGE_IMPLEMENTATION
#define STBI_FAILURE_USERMSG
#include <stb_image.h>

namespace animator {

Image load_image(const std::filesystem::path &path) {
    int w = 0, h = 0, channels = 0;
    stbi_uc *pixels = stbi_load(path.c_str(), &w, &h, &channels, 3);
    if (!pixels)
        throw AssetError(path.string() + ": cannot be read as an image: " + stbi_failure_reason());
    Image image;
    image.width = w;
    image.height = h;
    image.rgb.assign(pixels, pixels + static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 3);
    stbi_image_free(pixels);
    return image;
}

} // namespace animator
