#include "editor/state_folder.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

namespace fs = std::filesystem;

namespace animator {

namespace {

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

std::filesystem::path state_path(const char *name) {
    const char *state = std::getenv("XDG_STATE_HOME");
    if (state && *state == '/') return std::filesystem::path(state) / "animator" / name;
    const char *home = std::getenv("HOME");
    if (home && *home) return std::filesystem::path(home) / ".local" / "state" / "animator" / name;
    return {};
}

bool write_state_file(const fs::path &file, const std::string &text, std::string *why) {
    const auto fail = [&](const std::string &reason) {
        if (why) *why = reason;
        return false;
    };
    const fs::path folder = file.parent_path();
    std::error_code ec;
    if (fs::create_directories(folder, ec) && !ec) fs::permissions(folder, fs::perms::owner_all, ec);
    if (!fs::is_directory(folder)) return fail("cannot make the folder " + folder.string());
    const fs::path temp = folder / (file.filename().string() + ".tmp-" + std::to_string(::getpid()));
    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
    if (fd < 0) return fail(std::strerror(errno));
    const bool written = write_all(fd, text) && ::fsync(fd) == 0;
    const int saved_errno = errno;
    ::close(fd);
    if (!written || ::rename(temp.c_str(), file.c_str()) != 0) {
        const std::string reason = std::strerror(written ? errno : saved_errno);
        ::unlink(temp.c_str());
        return fail(reason);
    }
    const int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dir >= 0) {
        ::fsync(dir);
        ::close(dir);
    }
    return true;
}

} // namespace animator
