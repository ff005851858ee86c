// libFuzzer harness of mesh loading (host/assets/mesh.cpp): each input is written to a .obj
// file and loaded as the renderer and the physics bake load a model's mesh. assimp, which
// parses the file, is Debian's shared library and not instrumented: ASan still sees its heap
// (malloc is intercepted process-wide) but not its reads and writes, and libFuzzer is guided
// only by what our code does with assimp's result.
#include "assets/mesh.hpp"
#include "input_file.hpp"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    const std::string &path = animator::fuzz::write_input(data, size, ".obj");
    try {
        const animator::LoadedMesh loaded = animator::load_mesh(path);
        (void)animator::approximates_sphere(loaded.mesh); // what physics asks of every mesh next
    } catch (const animator::AssetError &) {
        // Refused with a message naming the file, as the malformed-file tests check.
    }
    return 0;
}
