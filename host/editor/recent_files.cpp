#include "editor/recent_files.hpp"

#include "editor/state_folder.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>

namespace fs = std::filesystem;

namespace animator {

namespace {

fs::path absolute_path(const fs::path &path) {
    std::error_code ec;
    fs::path full = fs::absolute(path, ec);
    return (ec ? path : full).lexically_normal();
}

} // namespace

fs::path recent_files_path() { return state_path("recent"); }

bool RecentFiles::load(std::string *error) {
    paths_.clear();
    if (file_.empty()) return true;
    std::error_code ec;
    if (!fs::exists(file_, ec)) return true;
    std::ifstream in(file_);
    if (!in) {
        if (error) *error = "cannot read the recent files list " + file_.string() + ": " + std::strerror(errno);
        return false;
    }
    std::string line;
    while (std::getline(in, line) && paths_.size() < kRecentFilesKept) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        const fs::path p(line);
        if (line.empty() || !p.is_absolute()) continue;
        if (std::find(paths_.begin(), paths_.end(), p) == paths_.end()) paths_.push_back(p);
    }
    return true;
}

void RecentFiles::add(const fs::path &path) {
    const fs::path p = absolute_path(path);
    remove(p);
    paths_.insert(paths_.begin(), p);
    if (paths_.size() > kRecentFilesKept) paths_.resize(kRecentFilesKept);
}

void RecentFiles::remove(const fs::path &path) {
    const fs::path p = absolute_path(path);
    paths_.erase(std::remove(paths_.begin(), paths_.end(), p), paths_.end());
}

bool RecentFiles::save(std::string *error) const {
    const auto fail = [&](const std::string &why) {
        if (error) *error = "cannot write the recent files list " + file_.string() + ": " + why;
        return false;
    };
    if (file_.empty()) return fail("no $XDG_STATE_HOME or $HOME to keep it in");
    std::string text;
    for (const fs::path &p : paths_) text += p.string() + "\n";
    std::string why;
    if (!write_state_file(file_, text, &why)) return fail(why);
    return true;
}

} // namespace animator
