// The editor's Dear ImGui windows (seed, "The Animator Interface" and "The Model Interface", and
// the Outliner at the Animator Interface's end): what they show comes from the session, and every
// change they make goes back through it as an undoable edit (but the Outliner's visibility, a
// view). Sliders and colour editors edit a draft and commit once, when let go, so a drag of a
// slider is one edit; with several models selected the field changed goes to all of them.
#pragma once

#include "editor/dope_sheet.hpp"
#include "editor/editor_session.hpp"
#include "editor/file_menu.hpp"
#include "editor/model_commands.hpp"
#include "editor/output_dialogs.hpp"
#include "editor/transform_panel.hpp"
#include "editor/view_layout.hpp"
#include "editor/view_settings.hpp"

#include <functional>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace animator {

class Panels {
  public:
    explicit Panels(Environment &env)
        : env_(env), files_([this](const std::string &m, bool error) { say(m, error); },
                            [this](const std::string &title, const std::string &m) { show_error(title, m); }),
          output_(env, [this](const std::string &m, bool error) { say(m, error); }) {}

    // Draws the Animator Interface (left), the Timeline (along the bottom, dope_sheet.hpp)
    // and, with a model selected, the Model Interface (right), in a window `width` x `height`
    // (screen coordinates).
    void draw(EditorSession &session, float width, float height, double wall);

    // A line for the status bar: the last thing that happened or went wrong.
    void say(const std::string &message, bool error = false);
    const std::string &message() const { return message_; }
    // The editor's frame rate for the status line (status_line.hpp's FrameRate::text()).
    void set_frame_rate(const std::string &text) { frame_rate_ = text; }

    // Undo and redo, from a key or a button: the status line says what happened, so a message
    // from an earlier action ("nothing to undo here") never outlives the next one.
    void undo(EditorSession &session);
    void redo(EditorSession &session);
    // The Timeline's keys: DELETE (true when keys were selected there, so the key was its),
    // CTRL+C, CTRL+V; the status line says what happened. ESC stops a drag in it.
    bool delete_keys(EditorSession &session);
    void copy_keys(EditorSession &session);
    void paste_keys(EditorSession &session);
    void cancel_timeline_drag() { dope_sheet_.cancel_drag(); }
    // Where the panels were drawn this frame, for the view to take the space they leave.
    const std::vector<PanelPlace> &places() const { return places_; }
    // The F1 overlay of every key and mouse action (help.hpp).
    void toggle_help() { help_open_ = !help_open_; }
    bool help_open() const { return help_open_; }
    void close_help() { help_open_ = false; }
    // A modal dialog is open: the editor's shortcuts wait until it is answered.
    bool dialog_open() const { return dialog_open_; }
    // Render (CTRL+F12) and Export (CTRL+SHIFT+E), output_dialogs.hpp; while one runs the
    // editor keeps drawing frames (output_busy()).
    void open_render() { output_.open_render(); }
    void open_export() { output_.open_export(); }
    bool output_busy() const { return output_.busy(); }
    // The Outliner's name field for model `model` (a double-click on its row, or F2).
    void start_rename(int model);
    // SHIFT+A, SHIFT+D and DELETE with no keys selected in the Timeline (model_commands.hpp).
    void ask_add_model() { models_.ask_add(); }
    void duplicate_models(EditorSession &session);
    void ask_delete_models(const EditorSession &session);

    // The File menu (the Animator Interface's menu bar) and its keys.
    FileMenu &files() { return files_; }
    // The View menu's settings (anti-aliasing, shadows, reflections), loaded at the start and saved on change.
    const ViewSettings &view_settings() const { return view_; }
    void load_view_settings();
    // Set by the window when the user asks to quit with unsaved changes; the panel asks.
    void ask_to_quit() { quit_asked_ = true; }
    // True once the user has confirmed quitting (or exported first).
    bool quit_confirmed() const { return quit_confirmed_; }
    // A dialog with an error the user must see (a file that failed to open).
    void show_error(const std::string &title, const std::string &message);
    // At a start with an autosave to recover (recovery.hpp): "Recover unsaved work from
    // `when`?", Recover (Enter) or Discard (Esc). The answer is taken once: true to recover.
    void ask_to_recover(const std::string &when, const std::string &detail);
    std::optional<bool> take_recover_answer();

  private:
    void animator_panel(EditorSession &session, float height, double wall);
    void model_panel(EditorSession &session, float width, float height, float bottom);
    void timeline(EditorSession &session, float width, float height);
    void say(const DopeSheet::Result &r) { say(r.message, !r.ok); }
    void interpolation(EditorSession &session);
    void outliner(EditorSession &session);
    void outliner_row(EditorSession &session, int model, const std::vector<std::vector<int>> &children,
                      const std::set<int> &hidden, const std::set<int> &reveal);
    void physics_backend(EditorSession &session);
    void overlaps(EditorSession &session);
    void dialogs(EditorSession &session);
    void commit(bool ok, const std::string &error);
    void cel_outline(Settings &s, EditorSession &session);
    // The scene's lights and ambient colour (Settings::lights), a window of the Animator
    // Interface opened from its menu bar (its panel has no room left at 1280x720).
    void lights_window(EditorSession &session);
    void view_menu();

    Environment &env_;
    std::optional<Settings> settings_draft_;
    std::optional<Model> model_draft_;
    TransformPanel transform_panel_; // the Model Interface's last section
    int model_draft_index_ = -1;
    std::uint64_t draft_version_ = 0;
    std::optional<Settings> confirm_settings_; // a shorter max time, waiting for confirmation
    std::string message_;
    bool message_error_ = false;
    std::string frame_rate_ = "idle";
    bool dialog_open_ = false;
    std::vector<PanelPlace> places_;
    bool quit_asked_ = false, quit_confirmed_ = false;
    bool help_open_ = false;
    bool lights_open_ = false;
    ViewSettings view_;
    std::string error_title_, error_text_;
    bool error_pending_ = false;
    bool recover_asked_ = false;
    std::string recover_when_, recover_detail_;
    std::optional<bool> recover_answer_;
    float placed_at_width_ = 0.0f; // the window width the Model Interface was placed for
    float placed_at_bottom_ = 0.0f; // and the bottom it was kept above (the Timeline's top)
    DopeSheet dope_sheet_;
    FileMenu files_;
    ModelCommands models_;
    // The Outliner: the model being renamed (-1: none), its field, and whether the field has
    // been active yet (it takes the keyboard the frame after it appears).
    int renaming_ = -1;
    std::string rename_text_;
    int rename_frames_ = 0;
    bool rename_active_ = false;
    int outliner_seen_ = -1; // the last selected model the Outliner has shown
    bool outliner_clicked_ = false; // the selection changed by a click on a row
    OutputDialogs output_; // last: it may still say something as the panels go
};

} // namespace animator
