#include "editor/output_job.hpp"

#include "io/document_io.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <stdexcept>
#include <thread>

extern "C" char **environ;

namespace fs = std::filesystem;

namespace animator {

namespace {

constexpr std::size_t kKeptLines = 6; // of stderr, and of stdout's other lines

std::string decimal(double x) {
    std::ostringstream s;
    s.precision(17);
    s << x;
    return s.str();
}

} // namespace

// [SECTION] the snapshot

Document snapshot_document(const Document &document, const AssetPaths &assets,
                           const fs::path &document_path) {
    Document copy = document;
    const auto &models = copy.models();
    for (int i = 0; i < static_cast<int>(models.size()); ++i) {
        Model m = models[static_cast<std::size_t>(i)];
        if (m.mesh.empty() || fs::path(m.mesh).is_absolute()) continue;
        const auto found = assets.resolve(ANI_ASSET_MESH, m.mesh, document_path);
        // Only a file found beside the document (the first place resolve() looks) moves: a mesh
        // from the asset folders is found there by the child too, and keeps its short id.
        const fs::path beside =
            document_path.empty() ? fs::path(m.mesh) : document_path.parent_path() / m.mesh;
        if (!found || *found != beside) continue;
        std::error_code ec;
        m.mesh = fs::absolute(beside, ec).lexically_normal().string();
        if (ec) continue;
        copy.set_model(i, m);
    }
    return copy;
}

JobSnapshot::JobSnapshot(PluginRegistry &plugins, const AssetPaths &assets,
                         const Document &document, const fs::path &document_path) {
    const char *tmp = std::getenv("TMPDIR");
    std::string pattern = (fs::path(tmp && *tmp ? tmp : "/tmp") / "animator-job-XXXXXX").string();
    if (!mkdtemp(pattern.data()))
        throw std::runtime_error(pattern.substr(0, pattern.size() - 6) +
                                 "...: cannot make a folder for the job (" + std::strerror(errno) +
                                 ")");
    folder_ = pattern;
    // The document's own name, so what the child says ("drop.ani: ...") reads as the user's file.
    const std::string stem = document_path.empty() ? "untitled" : document_path.stem().string();
    file_ = folder_ / (stem + ".ani");
    try {
        save_document(plugins, snapshot_document(document, assets, document_path), file_);
    } catch (...) {
        std::error_code ignored;
        fs::remove_all(folder_, ignored);
        throw;
    }
}

JobSnapshot::~JobSnapshot() {
    std::error_code ignored;
    fs::remove_all(folder_, ignored);
}

// [SECTION] the child process

fs::path OutputJob::self_executable() {
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    return ec ? fs::path("/proc/self/exe") : exe;
}

OutputJob::~OutputJob() {
    if (running()) cancel();
    close_pipes();
}

bool OutputJob::start(const fs::path &program, const std::vector<std::string> &args,
                      std::string *error) {
    if (running()) {
        if (error) *error = "a job is already running";
        return false;
    }
    close_pipes();
    out_buffer_.clear();
    err_buffer_.clear();
    said_.clear();
    errors_.clear();
    frames_done_ = frames_total_ = 0;
    exit_code_ = -1;
    int out[2] = {-1, -1}, err[2] = {-1, -1};
    if (pipe2(out, O_CLOEXEC) != 0 || pipe2(err, O_CLOEXEC) != 0) {
        if (error) *error = std::string("cannot make a pipe: ") + std::strerror(errno);
        for (int fd : {out[0], out[1], err[0], err[1]})
            if (fd >= 0) ::close(fd);
        return false;
    }
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
    posix_spawn_file_actions_adddup2(&actions, err[1], STDERR_FILENO);
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGMASK |
                                              POSIX_SPAWN_SETSIGDEF);
    posix_spawnattr_setpgroup(&attributes, 0); // a group of its own, led by the child
    // The signals a cancel or a pipe uses act as they should in the child, whatever the
    // editor does with them.
    sigset_t none, defaults;
    sigemptyset(&none);
    sigemptyset(&defaults);
    for (int sig : {SIGTERM, SIGINT, SIGHUP, SIGPIPE, SIGCHLD}) sigaddset(&defaults, sig);
    posix_spawnattr_setsigmask(&attributes, &none);
    posix_spawnattr_setsigdefault(&attributes, &defaults);

    std::vector<std::string> storage = args;
    storage.insert(storage.begin(), program.string());
    std::vector<char *> argv;
    for (std::string &a : storage) argv.push_back(a.data());
    argv.push_back(nullptr);
    const int spawned =
        posix_spawn(&pid_, program.c_str(), &actions, &attributes, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attributes);
    ::close(out[1]);
    ::close(err[1]);
    if (spawned != 0) {
        ::close(out[0]);
        ::close(err[0]);
        pid_ = -1;
        if (error) *error = program.string() + ": cannot start (" + std::strerror(spawned) + ")";
        return false;
    }
    out_fd_ = out[0];
    err_fd_ = err[0];
    fcntl(out_fd_, F_SETFL, fcntl(out_fd_, F_GETFL) | O_NONBLOCK);
    fcntl(err_fd_, F_SETFL, fcntl(err_fd_, F_GETFL) | O_NONBLOCK);
    state_ = State::Running;
    started_ = std::chrono::steady_clock::now();
    return true;
}

bool OutputJob::poll() {
    if (!running()) return false;
    read_pipes();
    int status = 0;
    const pid_t r = waitpid(pid_, &status, WNOHANG);
    if (r == pid_) {
        read_pipes(); // what it wrote just before it ended
        finished(status);
    }
    return running();
}

void OutputJob::cancel() {
    if (!running()) return;
    kill(-pid_, SIGTERM);
    int status = 0;
    const auto limit = std::chrono::steady_clock::now() + std::chrono::seconds(3);
    pid_t r = 0;
    while ((r = waitpid(pid_, &status, WNOHANG)) == 0 && std::chrono::steady_clock::now() < limit)
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    if (r == 0) {
        kill(-pid_, SIGKILL);
        while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
        }
    }
    read_pipes();
    finished(status);
    state_ = State::Cancelled;
}

double OutputJob::elapsed_seconds() const {
    if (state_ == State::Idle) return 0.0;
    const auto end = running() ? std::chrono::steady_clock::now() : ended_;
    return std::chrono::duration<double>(end - started_).count();
}

std::string OutputJob::error_text() const {
    std::string text;
    for (const std::string &line : errors_) text += (text.empty() ? "" : "\n") + line;
    return text;
}

void OutputJob::read_pipes() {
    char chunk[4096];
    for (int fd : {out_fd_, err_fd_}) {
        if (fd < 0) continue;
        std::string &buffer = fd == out_fd_ ? out_buffer_ : err_buffer_;
        ssize_t n = 0;
        while ((n = ::read(fd, chunk, sizeof chunk)) > 0)
            buffer.append(chunk, static_cast<std::size_t>(n));
        take_lines(buffer, fd == out_fd_, false);
    }
}

void OutputJob::take_lines(std::string &buffer, bool out, bool flush) {
    std::size_t start = 0, end = 0;
    auto keep = [&](std::string line) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        // A progress bar on a terminal ends its updates with '\r': only its last state counts.
        if (const auto cr = line.rfind('\r'); cr != std::string::npos) line.erase(0, cr + 1);
        if (line.empty()) return;
        if (out && parse_frame_progress(line, frames_done_, frames_total_)) return;
        auto &lines = out ? said_ : errors_;
        lines.push_back(line);
        if (lines.size() > kKeptLines) lines.erase(lines.begin());
    };
    while ((end = buffer.find('\n', start)) != std::string::npos) {
        keep(buffer.substr(start, end - start));
        start = end + 1;
    }
    buffer.erase(0, start);
    if (flush && !buffer.empty()) {
        keep(buffer);
        buffer.clear();
    }
}

void OutputJob::finished(int status) {
    take_lines(out_buffer_, true, true);
    take_lines(err_buffer_, false, true);
    close_pipes();
    ended_ = std::chrono::steady_clock::now();
    if (WIFEXITED(status)) {
        exit_code_ = WEXITSTATUS(status);
        state_ = exit_code_ == 0 ? State::Succeeded : State::Failed;
    } else {
        exit_code_ = -1;
        state_ = State::Failed;
        if (WIFSIGNALED(status) && errors_.empty())
            errors_.push_back(std::string("stopped by signal ") + strsignal(WTERMSIG(status)));
    }
    pid_ = -1;
}

void OutputJob::close_pipes() {
    for (int *fd : {&out_fd_, &err_fd_})
        if (*fd >= 0) {
            ::close(*fd);
            *fd = -1;
        }
}

// [SECTION] the commands

bool parse_frame_progress(const std::string &line, int &done, int &total) {
    int k = 0, n = 0;
    char rest = 0;
    if (std::sscanf(line.c_str(), "frame %d of %d%c", &k, &n, &rest) != 2 || k < 0 || n < k)
        return false;
    done = k;
    total = n;
    return true;
}

std::vector<std::string> render_arguments(const RenderRequest &r, const fs::path &snapshot) {
    std::vector<std::string> args = {
        "render",    snapshot.string(),
        "--out",     r.out.string(),
        "--size",    std::to_string(r.width) + "x" + std::to_string(r.height),
        "--fps",     decimal(r.fps),
        "--from",    decimal(r.from),
        "--to",      decimal(r.to),
        "--progress"};
    if (!r.video.empty()) {
        args.emplace_back("--video");
        args.push_back(r.video.string());
    }
    return args;
}

std::vector<std::string> trace_arguments(const fs::path &csv, const fs::path &snapshot) {
    return {"bake", snapshot.string(), "--trace", csv.string()};
}

std::vector<std::string> soundtrack_arguments(const fs::path &wav, const fs::path &snapshot) {
    return {"soundtrack", snapshot.string(), "--out", wav.string()};
}

std::vector<std::string> gltf_arguments(const fs::path &gltf, const fs::path &snapshot) {
    return {"export", snapshot.string(), "--to", gltf.string()};
}

std::optional<fs::path> find_ffmpeg() {
    const char *path = std::getenv("PATH");
    std::istringstream folders(path ? path : "");
    std::string folder;
    while (std::getline(folders, folder, ':')) {
        const fs::path candidate = fs::path(folder.empty() ? "." : folder) / "ffmpeg";
        std::error_code ec;
        if (::access(candidate.c_str(), X_OK) == 0 && !fs::is_directory(candidate, ec))
            return candidate;
    }
    return std::nullopt;
}

} // namespace animator
