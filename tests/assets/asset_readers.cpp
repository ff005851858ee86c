#include "asset_readers.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>

namespace fs = std::filesystem;

namespace animator::test::assets {

fs::path generated_dir() {
    return ANIMATOR_GENERATED_ASSET_DIR;
}

const std::vector<std::string> &documented_files() {
    static const std::vector<std::string> files = [] {
        std::vector<std::string> list;
        for (const char *mesh : {"sphere", "sphere_low", "sphere_high", "cube", "plane",
                                 "floor_fine", "cylinder", "cone", "torus", "stairs"})
            list.push_back(std::string("meshes/") + mesh + ".obj");
        for (const char *texture :
             {"checker.png", "checker.bmp", "wood.png", "marble.png", "brick.png"})
            list.push_back(std::string("textures/") + texture);
        for (const char *sky : {"day", "sunset", "night"})
            for (const char *face : {"right", "left", "top", "bottom", "front", "back"})
                list.push_back(std::string("skyboxes/") + sky + "/" + face + ".png");
        for (const char *sound : {"click", "knock", "ping", "thud", "hum"})
            list.push_back(std::string("sounds/") + sound + ".wav");
        return list;
    }();
    return files;
}

namespace {

std::string slurp(const fs::path &path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot open " + path.string());
    std::ostringstream out;
    out << in.rdbuf();
    return out.str();
}

// One `a/b/c` corner; OBJ indices are 1-based.
ObjCorner parse_corner(const std::string &token, const ObjMesh &mesh) {
    ObjCorner c;
    char slash1 = 0, slash2 = 0;
    std::istringstream in(token);
    if (!(in >> c.v >> slash1 >> c.vt >> slash2 >> c.vn) || slash1 != '/' || slash2 != '/' ||
        in.peek() != EOF)
        throw std::runtime_error("corner is not v/vt/vn: " + token);
    --c.v;
    --c.vt;
    --c.vn;
    if (c.v < 0 || c.v >= static_cast<int>(mesh.positions.size()) || c.vt < 0 ||
        c.vt >= static_cast<int>(mesh.uvs.size()) || c.vn < 0 ||
        c.vn >= static_cast<int>(mesh.normals.size()))
        throw std::runtime_error("index out of range: " + token);
    return c;
}

} // namespace

ObjMesh read_obj(const fs::path &path) {
    std::istringstream lines(slurp(path));
    ObjMesh mesh;
    int number = 0;
    for (std::string line; std::getline(lines, line);) {
        ++number;
        try {
            std::istringstream in(line);
            std::string kind;
            if (!(in >> kind) || kind[0] == '#') continue;
            if (kind == "v" || kind == "vn") {
                glm::dvec3 p;
                if (!(in >> p.x >> p.y >> p.z)) throw std::runtime_error("bad vector");
                (kind == "v" ? mesh.positions : mesh.normals).push_back(p);
            } else if (kind == "vt") {
                glm::dvec2 t;
                if (!(in >> t.x >> t.y)) throw std::runtime_error("bad uv");
                mesh.uvs.push_back(t);
            } else if (kind == "f") {
                std::vector<std::string> tokens;
                for (std::string token; in >> token;) tokens.push_back(token);
                if (tokens.size() != 3) throw std::runtime_error("face is not a triangle");
                mesh.triangles.push_back({parse_corner(tokens[0], mesh),
                                          parse_corner(tokens[1], mesh),
                                          parse_corner(tokens[2], mesh)});
                continue;
            } else {
                throw std::runtime_error("unexpected statement " + kind);
            }
            std::string extra;
            if (in >> extra) throw std::runtime_error("trailing text");
        } catch (const std::runtime_error &e) {
            throw std::runtime_error(path.string() + ":" + std::to_string(number) + ": " +
                                     e.what());
        }
    }
    return mesh;
}

double Image::luminance(int x, int y) const {
    if (channels < 3) return at(x, y, 0);
    return 0.2126 * at(x, y, 0) + 0.7152 * at(x, y, 1) + 0.0722 * at(x, y, 2);
}

Image read_image(const fs::path &path) {
    Image image;
    stbi_uc *data =
        stbi_load(path.string().c_str(), &image.width, &image.height, &image.channels, 0);
    if (!data)
        throw std::runtime_error("cannot load " + path.string() + ": " + stbi_failure_reason());
    image.pixels.assign(data, data + image.width * image.height * image.channels);
    stbi_image_free(data);
    return image;
}

namespace {

std::uint32_t u32_at(const std::string &b, std::size_t at) {
    if (at + 4 > b.size()) throw std::runtime_error("truncated");
    return static_cast<std::uint32_t>(static_cast<unsigned char>(b[at])) |
           static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 1])) << 8 |
           static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 2])) << 16 |
           static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 3])) << 24;
}
int u16_at(const std::string &b, std::size_t at) {
    if (at + 2 > b.size()) throw std::runtime_error("truncated");
    return static_cast<unsigned char>(b[at]) | static_cast<unsigned char>(b[at + 1]) << 8;
}

} // namespace

Wav read_wav(const fs::path &path) {
    const std::string b = slurp(path);
    const auto fail = [&](const std::string &why) {
        return std::runtime_error(path.string() + ": " + why);
    };
    if (b.size() < 12 || b.compare(0, 4, "RIFF") != 0 || b.compare(8, 4, "WAVE") != 0)
        throw fail("not RIFF/WAVE");
    if (u32_at(b, 4) != b.size() - 8) throw fail("RIFF size does not match the file size");
    Wav wav;
    bool have_fmt = false, have_data = false;
    std::size_t at = 12;
    while (at < b.size()) {
        if (at + 8 > b.size()) throw fail("truncated chunk header");
        const std::string id = b.substr(at, 4);
        const std::uint32_t size = u32_at(b, at + 4);
        const std::size_t body = at + 8;
        if (body + size > b.size()) throw fail("chunk " + id + " runs past the end");
        if (id == "fmt ") {
            if (size < 16) throw fail("fmt chunk too small");
            wav.format = u16_at(b, body);
            wav.channels = u16_at(b, body + 2);
            wav.sample_rate = static_cast<int>(u32_at(b, body + 4));
            wav.byte_rate = static_cast<int>(u32_at(b, body + 8));
            wav.block_align = u16_at(b, body + 12);
            wav.bits_per_sample = u16_at(b, body + 14);
            have_fmt = true;
        } else if (id == "data") {
            if (!have_fmt) throw fail("data before fmt");
            if (wav.format == 1 && wav.bits_per_sample == 16) {
                if (size % 2 != 0) throw fail("odd data size for 16-bit samples");
                for (std::size_t i = 0; i < size; i += 2) {
                    const int raw = u16_at(b, body + i); // two's complement, little-endian
                    wav.samples.push_back(
                        static_cast<std::int16_t>(raw >= 32768 ? raw - 65536 : raw));
                }
            }
            have_data = true;
        }
        at = body + size + (size & 1); // chunks are padded to an even length
    }
    if (!have_fmt || !have_data) throw fail("missing fmt or data chunk");
    return wav;
}

} // namespace animator::test::assets
