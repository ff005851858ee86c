#include "editor/state_folder.hpp"

#include <cstdlib>

namespace animator {

std::filesystem::path state_path(const char *name) {
    const char *state = std::getenv("XDG_STATE_HOME");
    if (state && *state == '/') return std::filesystem::path(state) / "animator" / name;
    const char *home = std::getenv("HOME");
    if (home && *home) return std::filesystem::path(home) / ".local" / "state" / "animator" / name;
    return {};
}

} // namespace animator
