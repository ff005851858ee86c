// Where the editor keeps what it remembers between runs (the recent files, the View settings,
// autosaved documents): $XDG_STATE_HOME/animator (the XDG Base Directory specification's state
// folder), else ~/.local/state/animator.
#pragma once

#include <filesystem>

namespace animator {

// `name` in that folder; empty without XDG_STATE_HOME (an absolute path) or HOME.
std::filesystem::path state_path(const char *name);

} // namespace animator
