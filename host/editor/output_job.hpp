// The editor's Render and Export run the command line (`animator render`, `bake --trace`,
// `soundtrack`) as a child process on a snapshot of the document as it is on screen, unsaved
// edits included, so the window keeps drawing while a long render goes on, and a cancel is a
// signal to the child, not a flag a renderer must look at. No ImGui here: the dialogs
// (output_dialogs.hpp) show what a job says, and the tests run one without a window.
#pragma once

#include "assets/asset_paths.hpp"
#include "document/document.hpp"
#include "plugin/registry.hpp"
#include "render/png_frame_writer.hpp" // render_frame_count

#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace animator {

// A private folder (under $TMPDIR, else /tmp) holding `document` as an .ani the child reads,
// removed with everything in it when the snapshot goes. Meshes named by a path relative to the
// open document (`document_path`, empty when untitled) are written as the absolute paths they
// resolve to, so the child, reading from elsewhere, finds the same files; meshes, textures and
// sounds found under the asset folders keep their ids (the child has the same folders).
class JobSnapshot {
  public:
    // Throws std::runtime_error naming the folder or file it could not write.
    JobSnapshot(PluginRegistry &plugins, const AssetPaths &assets, const Document &document,
                const std::filesystem::path &document_path);
    ~JobSnapshot();
    JobSnapshot(const JobSnapshot &) = delete;
    JobSnapshot &operator=(const JobSnapshot &) = delete;
    const std::filesystem::path &file() const { return file_; }

  private:
    std::filesystem::path folder_, file_;
};

// The document as the child should read it: mesh ids that resolve beside `document_path`
// replaced by that absolute path (a pure function, tested apart).
Document snapshot_document(const Document &document, const AssetPaths &assets,
                           const std::filesystem::path &document_path);

// One run of a program: started with posix_spawn (no shell), in a process group of its own (so
// a cancel also stops what it starts, ffmpeg), its stdout and stderr read through pipes without
// blocking. stdout lines "frame K of N" (`animator render --progress`) are its progress.
class OutputJob {
  public:
    enum class State { Idle, Running, Succeeded, Failed, Cancelled };

    OutputJob() = default;
    // A job still running is cancelled (the editor closing during a render stops it).
    ~OutputJob();
    OutputJob(const OutputJob &) = delete;
    OutputJob &operator=(const OutputJob &) = delete;

    // The `animator` executable that is running (/proc/self/exe): the editor runs itself.
    static std::filesystem::path self_executable();

    // Starts `program args...`. False (with why in `error`) when it could not start.
    bool start(const std::filesystem::path &program, const std::vector<std::string> &args,
               std::string *error = nullptr);
    // Reads what the child wrote since the last call and, when it has ended, reaps it. Never
    // blocks. Returns true while it runs.
    bool poll();
    // SIGTERM to the child's group, then waits for it (SIGKILL after 3 s): no zombie. What it
    // wrote so far stays as it is.
    void cancel();

    State state() const { return state_; }
    bool running() const { return state_ == State::Running; }
    // The last "frame K of N" line: K frames written of N (both 0 before the first).
    int frames_done() const { return frames_done_; }
    int frames_total() const { return frames_total_; }
    double elapsed_seconds() const;
    // Its stdout lines that were not progress ("wrote ..."), and the last lines of its stderr
    // (the error message when it failed), each at most a few lines.
    const std::vector<std::string> &said() const { return said_; }
    std::string error_text() const;
    int exit_code() const { return exit_code_; }
    pid_t pid() const { return pid_; }

  private:
    void read_pipes();
    void take_lines(std::string &buffer, bool out, bool flush);
    void finished(int status);
    void close_pipes();

    State state_ = State::Idle;
    pid_t pid_ = -1;
    int out_fd_ = -1, err_fd_ = -1;
    std::string out_buffer_, err_buffer_;
    std::vector<std::string> said_, errors_;
    int frames_done_ = 0, frames_total_ = 0, exit_code_ = -1;
    std::chrono::steady_clock::time_point started_, ended_;
};

// "frame 12 of 150" into 12 and 150; false for any other line.
bool parse_frame_progress(const std::string &line, int &done, int &total);

// What the Render dialog asks for.
struct RenderRequest {
    std::filesystem::path out;   // the folder of frame_00000.png, ...
    std::filesystem::path video; // empty: frames only
    int width = 1280, height = 720;
    double fps = 30.0, from = 0.0, to = 0.0;
};
// `render SNAPSHOT --out ... --progress ...`: the arguments for OutputJob::start.
std::vector<std::string> render_arguments(const RenderRequest &request,
                                          const std::filesystem::path &snapshot);
// `bake SNAPSHOT --trace CSV`, `soundtrack SNAPSHOT --out WAV` and `export SNAPSHOT --to GLB`.
std::vector<std::string> trace_arguments(const std::filesystem::path &csv,
                                         const std::filesystem::path &snapshot);
std::vector<std::string> soundtrack_arguments(const std::filesystem::path &wav,
                                              const std::filesystem::path &snapshot);
std::vector<std::string> gltf_arguments(const std::filesystem::path &gltf,
                                        const std::filesystem::path &snapshot);

// ffmpeg on PATH (what `animator render --video` needs), or nothing.
std::optional<std::filesystem::path> find_ffmpeg();

} // namespace animator
