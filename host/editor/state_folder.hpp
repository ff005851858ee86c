// Where the editor keeps what it remembers between runs (the recent files, the View settings,
// autosaved documents): $XDG_STATE_HOME/animator (the XDG Base Directory specification's state
// folder), else ~/.local/state/animator.
#pragma once

#include <filesystem>
#include <string>

namespace animator {

// `name` in that folder; empty without XDG_STATE_HOME (an absolute path) or HOME.
std::filesystem::path state_path(const char *name);

// Writes `text` to `file` atomically: its folder made first (0700), a temporary file beside it
// written and flushed to disk, renamed over it, so a failure midway leaves the old file whole.
// False, with why (strerror's words) in `why`, when it cannot.
bool write_state_file(const std::filesystem::path &file, const std::string &text, std::string *why);

} // namespace animator
