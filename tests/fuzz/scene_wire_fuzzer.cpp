// libFuzzer harness of the decoder of the Lua scene reader's reply (plugins/io-lua/scene_wire):
// the bytes a child process sends after running an untrusted scene. That child may have been
// taken over by the scene, so the decoder must survive any bytes. The oracle beyond "no crash":
// a reply that decodes encodes back to the very same bytes.
#include "../../plugins/io-lua/scene_wire.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    const std::string bytes(reinterpret_cast<const char *>(data), size);
    lua_scene::SceneResult scene;
    std::string error;
    if (lua_scene::decode_reply(bytes, "fuzz.lua", scene, error)) {
        if (lua_scene::encode_result(scene) != bytes) std::abort();
    } else if (error.empty()) {
        std::abort();
    }
    return 0;
}
