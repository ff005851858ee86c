#include "editor/recent_files.hpp"

#include "editor/state_folder.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
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

bool write_all(int fd, const std::string &text) {
    size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        done += static_cast<size_t>(n);
    }
    return true;
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
    const fs::path folder = file_.parent_path();
    std::error_code ec;
    if (fs::create_directories(folder, ec) && !ec) fs::permissions(folder, fs::perms::owner_all, ec);
    if (!fs::is_directory(folder)) return fail("cannot make the folder " + folder.string());
    std::string text;
    for (const fs::path &p : paths_) text += p.string() + "\n";
    const fs::path temp = folder / (file_.filename().string() + ".tmp-" + std::to_string(::getpid()));
    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
    if (fd < 0) return fail(std::strerror(errno));
    const bool written = write_all(fd, text) && ::fsync(fd) == 0;
    const int saved_errno = errno;
    ::close(fd);
    if (!written || ::rename(temp.c_str(), file_.c_str()) != 0) {
        const std::string why = std::strerror(written ? errno : saved_errno);
        ::unlink(temp.c_str());
        return fail(why);
    }
    const int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dir >= 0) {
        ::fsync(dir);
        ::close(dir);
    }
    return true;
}

} // namespace animator
