// Readers for the generated assets, written independently of the generator so the tests check
// the files, not the generator's own idea of them: a small OBJ parser, stb_image for PNG and BMP,
// and a RIFF/WAVE parser.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace animator::test::assets {

// ANIMATOR_GENERATED_ASSET_DIR: the build's asset folder.
std::filesystem::path generated_dir();
// Every file the generator documents (docs/assets.md), relative to the asset folder.
const std::vector<std::string> &documented_files();

struct ObjCorner {
    int v = -1, vt = -1, vn = -1; // 0-based
};
struct ObjMesh {
    std::vector<glm::dvec3> positions;
    std::vector<glm::dvec2> uvs;
    std::vector<glm::dvec3> normals;
    std::vector<std::array<ObjCorner, 3>> triangles;
};
// Accepts comments, v, vt, vn and triangular `f v/vt/vn` faces only; throws std::runtime_error
// naming the line on anything else, on an index out of range, or on a polygon.
ObjMesh read_obj(const std::filesystem::path &path);

struct Image {
    int width = 0, height = 0, channels = 0;
    std::vector<std::uint8_t> pixels;
    int at(int x, int y, int channel) const {
        return pixels[static_cast<std::size_t>((y * width + x) * channels + channel)];
    }
    double luminance(int x, int y) const; // Rec. 709 weights, 0..255
};
// Loads with the file's own channel count; throws on failure.
Image read_image(const std::filesystem::path &path);

struct Wav {
    int format = 0, channels = 0, sample_rate = 0, bits_per_sample = 0;
    int byte_rate = 0, block_align = 0;
    std::vector<std::int16_t> samples; // only filled for 16-bit PCM
};
// Walks the RIFF chunks; throws on a malformed or inconsistent file.
Wav read_wav(const std::filesystem::path &path);

} // namespace animator::test::assets
