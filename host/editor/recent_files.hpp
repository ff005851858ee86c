// Open Recent: the last files opened or saved, newest first, at most 10, kept across runs in
// $XDG_STATE_HOME/animator/recent (~/.local/state/animator/recent without it), one absolute path
// a line, written atomically (a temporary file beside it, flushed, renamed over it).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace animator {

constexpr std::size_t kRecentFilesKept = 10;

// $XDG_STATE_HOME/animator/recent (an absolute XDG_STATE_HOME only), else
// $HOME/.local/state/animator/recent; empty without either.
std::filesystem::path recent_files_path();

class RecentFiles {
  public:
    explicit RecentFiles(std::filesystem::path file) : file_(std::move(file)) {}

    const std::filesystem::path &file() const { return file_; }
    const std::vector<std::filesystem::path> &paths() const { return paths_; }

    // Reads the list. A missing file is an empty list; an unreadable one is too, with why in
    // `error`. Blank lines and relative paths are skipped; at most kRecentFilesKept are kept.
    bool load(std::string *error = nullptr);
    // `path` (made absolute) goes first, once; the oldest beyond kRecentFilesKept drop off.
    void add(const std::filesystem::path &path);
    void remove(const std::filesystem::path &path);
    void clear() { paths_.clear(); }
    // Writes the list atomically, making the folder (0700) first. False, with why in `error`,
    // and the previous file intact, when it cannot.
    bool save(std::string *error = nullptr) const;

  private:
    std::filesystem::path file_;
    std::vector<std::filesystem::path> paths_;
};

} // namespace animator
