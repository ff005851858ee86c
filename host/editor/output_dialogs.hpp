// The Render and Export dialogs (docs/manual.md "Rendering and exporting from the editor"):
// each asks where and what, then runs the command line on a snapshot of the document as it is
// (output_job.hpp) while the editor keeps drawing, shows its progress with a Cancel (ESC too),
// and says on the status line what was written, or the child's error. Owned by Panels; opened by
// CTRL+F12 and CTRL+SHIFT+E (and the File menu, which also opens Export with glTF ticked).
#pragma once

#include "editor/editor_session.hpp"
#include "editor/output_job.hpp"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace animator {

class OutputDialogs {
  public:
    // `say` puts a line on the status line (an error when the flag is set).
    OutputDialogs(Environment &env, std::function<void(const std::string &, bool)> say)
        : env_(env), say_(std::move(say)) {}
    // A job still running is cancelled (the editor is closing), and that is said on stdout.
    ~OutputDialogs();
    OutputDialogs(const OutputDialogs &) = delete;
    OutputDialogs &operator=(const OutputDialogs &) = delete;

    void open_render() { open_ = Kind::Render; }
    void open_export() { open_ = Kind::Export; }
    // The Export dialog with only glTF ticked (File > Export glTF...).
    void open_gltf_export() {
        open_ = Kind::Export;
        trace_ = soundtrack_ = false;
        gltf_ = true;
    }
    // Draws the open dialog, if any, and follows a running job (call once a frame).
    void draw(EditorSession &session);
    // A job runs: the editor must keep drawing frames (it polls instead of sleeping).
    bool busy() const { return job_.running(); }

  private:
    enum class Kind { None, Render, Export };
    struct Step {
        std::string what;                   // "the trace", for messages
        std::filesystem::path path;         // what it writes
        std::vector<std::string> arguments; // for `animator`
    };

    void render_form(EditorSession &session);
    void export_form(EditorSession &session);
    void progress();
    // Starts the steps with a fresh snapshot of the document; false (said) when it cannot.
    bool start(EditorSession &session, Kind kind, std::vector<Step> steps);
    bool start_next_step();
    void follow_job();
    void cancel();
    void end(const std::string &message, bool error);
    // The child's message with the snapshot's path replaced by the document's.
    std::string child_error() const;

    Environment &env_;
    std::function<void(const std::string &, bool)> say_;
    Kind open_ = Kind::None; // asked to open (the next frame opens the popup)
    Kind running_ = Kind::None;
    bool close_popup_ = false; // a job ended: its dialog closes (the status line says the rest)
    std::filesystem::path document_path_; // the document the open dialog was filled from

    // The Render dialog's fields.
    bool video_ = false;
    int size_[2] = {1280, 720};
    double fps_ = 30.0, from_ = 0.0, to_ = 0.0;
    std::string out_, video_path_;
    // The Export dialog's.
    bool trace_ = true, soundtrack_ = true, gltf_ = false;
    std::string trace_path_, soundtrack_path_, gltf_path_;

    std::unique_ptr<JobSnapshot> snapshot_;
    std::filesystem::path snapshot_for_; // the document path the snapshot stands for
    std::vector<Step> steps_;            // the export's steps still to run after the current one
    Step step_;                          // the one running
    std::vector<std::filesystem::path> written_;
    OutputJob job_;
    RenderRequest request_;
};

} // namespace animator
