// libFuzzer harness of mesh loading (host/assets/mesh.cpp): each input is written to a file
// named for the format its first bytes look like (.ply, .glb, .gltf, .stl, else .obj: the
// loader picks its importer by the extension) and loaded as the renderer and the physics bake
// load a model's mesh. assimp, which
// parses the file, is Debian's shared library and not instrumented: ASan still sees its heap
// (malloc is intercepted process-wide) but not its reads and writes, and libFuzzer is guided
// only by what our code does with assimp's result.
#include "assets/mesh.hpp"
#include "input_file.hpp"

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace {

const char *extension_of(const std::uint8_t *data, std::size_t size) {
    const auto starts = [&](const char *prefix) {
        const std::size_t n = std::strlen(prefix);
        return size >= n && std::memcmp(data, prefix, n) == 0;
    };
    if (starts("ply")) return ".ply";
    if (starts("glTF")) return ".glb";
    if (starts("{")) return ".gltf";
    if (starts("solid")) return ".stl";
    if (size >= 84) { // a binary STL: 80 bytes, a count, 50 bytes a triangle
        std::uint32_t count = 0;
        std::memcpy(&count, data + 80, 4);
        if (84 + std::uint64_t{50} * count == size) return ".stl";
    }
    return ".obj";
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    const std::string &path = animator::fuzz::write_input(data, size, extension_of(data, size));
    try {
        const animator::LoadedMesh loaded = animator::load_mesh(path);
        (void)animator::approximates_sphere(loaded.mesh); // what physics asks of every mesh next
    } catch (const animator::AssetError &) {
        // Refused with a message naming the file, as the malformed-file tests check.
    }
    return 0;
}
