#include "assets/image.hpp"

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

namespace {

// stb_image allocates through these, so that no single allocation exceeds this cap however a
// file lies: the dimensions are checked from the header first, but a zlib stream can inflate
// far past the size the header promises, and stb doubles its buffer until the stream ends.
constexpr std::size_t kMaxDecoderAllocation = std::size_t{256} << 20;
thread_local bool decoder_allocation_refused = false;

void *capped_malloc(std::size_t size) {
    if (size > kMaxDecoderAllocation) {
        decoder_allocation_refused = true;
        return nullptr; // stb fails with "outofmem"
    }
    return std::malloc(size);
}

void *capped_realloc(void *p, std::size_t size) {
    if (size > kMaxDecoderAllocation) {
        decoder_allocation_refused = true;
        return nullptr; // stb frees p itself on failure
    }
    return std::realloc(p, size);
}

} // namespace

#define STBI_MALLOC(size) capped_malloc(size)
#define STBI_REALLOC(p, size) capped_realloc(p, size)
#define STBI_FREE(p) std::free(p)
// stb picks a decoder from a file's first bytes, never from its name, so every decoder compiled
// in is reachable by any file named as a texture. Only the two formats textures are found by:
// the others are code no asset needs (and the fuzzer found stb's PNM decoder reading past its
// buffer on a 16-bit image; docs/fuzzing.md).
#define STBI_ONLY_PNG
#define STBI_ONLY_BMP
#define STB_IMAGE_IMPLEMENTATION
#define STBI_FAILURE_USERMSG
#include <stb_image.h>

namespace animator {

Image load_image(const std::filesystem::path &path) {
    const std::string name = path.string();
    const std::unique_ptr<std::FILE, int (*)(std::FILE *)> file(std::fopen(path.c_str(), "rb"),
                                                                &std::fclose);
    if (!file) throw AssetError(name + ": cannot be read as an image: cannot open the file");

    int w = 0, h = 0, channels = 0;
    // The header first (stbi_info rewinds the file), so that an image too large is refused
    // before anything is allocated for its pixels.
    if (stbi_info_from_file(file.get(), &w, &h, &channels) &&
        (w > kMaxImageSide || h > kMaxImageSide ||
         static_cast<std::size_t>(w) * static_cast<std::size_t>(h) > kMaxImagePixels))
        throw AssetError(name + ": the image is " + std::to_string(w) + " x " + std::to_string(h) +
                         " pixels; at most " + std::to_string(kMaxImageSide) + " on a side and " +
                         std::to_string(kMaxImagePixels) + " pixels in all are read");

    decoder_allocation_refused = false;
    stbi_uc *pixels = stbi_load_from_file(file.get(), &w, &h, &channels, 3);
    if (!pixels && decoder_allocation_refused)
        throw AssetError(name + ": cannot be read as an image: decoding it would need more than " +
                         std::to_string(kMaxDecoderAllocation >> 20) +
                         " MiB at once (its compressed data inflates past its size)");
    if (!pixels) throw AssetError(name + ": cannot be read as an image: " + stbi_failure_reason());
    Image image;
    image.width = w;
    image.height = h;
    image.rgb.assign(pixels,
                     pixels + static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 3);
    stbi_image_free(pixels);
    return image;
}

} // namespace animator
