#include "fuzz_host.hpp"

#include "assets/asset_paths.hpp"

#include <cstring>

namespace animator::fuzz {

namespace {

const AssetPaths &asset_paths() {
    // The roots the malformed-file tests resolve names against, then the example assets; the
    // extension resolves a mesh relative to the document too, as the real host does.
    static const AssetPaths paths(
        {ANIMATOR_SOURCE_DIR "/tests/data/assets", ANIMATOR_SOURCE_DIR "/assets"});
    return paths;
}

void quiet_log(const ani_host *, ani_log_level, const char *, const char *) {}

const void *get_extension(const ani_host *, const char *id) {
    if (id && std::strcmp(id, ANI_EXT_ASSETS) == 0) return asset_paths().extension();
    return nullptr;
}

} // namespace

const ani_host *fuzz_host() {
    static const ani_host host = {
        sizeof(ani_host), {ANI_ABI_MAJOR, ANI_ABI_MINOR, 0},
        "animator-fuzz",  {0, 1, 0},
        nullptr,          quiet_log,
        get_extension,
    };
    return &host;
}

} // namespace animator::fuzz
