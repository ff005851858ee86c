// The editor's state without a window: the document being edited and where it came from, its
// undo history, the timeline and its bake, the current time and playback, the selection, the
// mode, and a mouse drag in progress. The window (editor_app.hpp) turns events into calls here
// and draws what this says; everything a user can do is testable without a display.
#pragma once

#include "document/history.hpp"
#include "editor/free_view.hpp"
#include "editor/gizmo.hpp"
#include "editor/joint_clamp.hpp"
#include "editor/manipulation.hpp"
#include "editor/model_fields.hpp"
#include "editor/motion_paths.hpp"
#include "io/environment.hpp"
#include "timeline/timeline.hpp"

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace animator {

class EditorSession {
  public:
    explicit EditorSession(Environment &env);

    // Opens a .lua scene or an .ani animation. On failure the current document stays, and the
    // message (naming the file, and the line where the format knows it) goes to `error`.
    bool open(const std::filesystem::path &path, std::string &error);
    // Autosave's recovery (recovery.hpp): opens the .ani `recovery` as unsaved changes to the
    // document at `original` (empty: untitled), which keeps its path for the next export (and
    // finds its meshes from there). On failure as open().
    bool recover(const std::filesystem::path &recovery, const std::filesystem::path &original, std::string &error);
    // The demo scene shipped with the program (assets/scenes/simple.lua).
    static std::filesystem::path demo_path(const AssetPaths &assets);

    const Document &document() const { return doc_; }
    const std::filesystem::path &path() const { return path_; }
    const Timeline &timeline() const { return *timeline_; }
    const std::vector<std::shared_ptr<const Mesh>> &meshes() const { return meshes_; }
    // Changes on every change of the document, so a view knows when to look again.
    std::uint64_t version() const { return version_; }
    // Warnings from opening (a mesh that could not be found...), for the window to show.
    const std::vector<std::string> &warnings() const { return warnings_; }

    // The current time, in whole milliseconds as the seed's Time slider, within [0, max time].
    std::int64_t time_ms() const { return time_ms_; }
    double time() const { return static_cast<double>(time_ms_) / 1000.0; }
    void set_time_ms(std::int64_t ms);
    // Index of the keyframe at the current time, or -1.
    int keyframe_here() const { return doc_.find_keyframe(time_ms_); }
    double max_time() const { return static_cast<double>(doc_.settings().max_time_ms) / 1000.0; }
    // The arrow keys: Left/Right step `frames` frames (time_steps.hpp), Up/Down jump to the
    // previous/next keyframe. Both pause playback, as the Time slider does; neither is an edit.
    void step_frames(int frames);
    void jump_keyframe(int direction);

    // Bakes on towards the max time for about `budget` seconds of wall time, in slices, so the
    // window stays responsive. Returns true while more remains to bake.
    bool bake_some(double budget);
    bool baking() const { return !bake_error_.empty() ? false : timeline_->baked_until() < max_time(); }
    double bake_progress() const { return max_time() > 0 ? timeline_->baked_until() / max_time() : 1.0; }
    // Why the last bake failed (the backend's message), or "".
    const std::string &bake_error() const { return bake_error_; }

    // Playback in real time from the current time (`wall` is a clock in seconds). While the bake
    // has not reached the time to show, playback waits for it; at the max time it stops.
    bool playing() const { return playing_; }
    void toggle_play(double wall);
    void pause() { playing_ = false; }
    void tick(double wall);

    // Selection: a click on model `model` (-1: empty space); with `add` (CTRL) it toggles the
    // model in the selection, else selects it alone. The Model Interface edits every selected
    // model and shows the last one selected's values (set_field()).
    void click(int model, bool add);
    const std::set<int> &selection() const { return selection_; }
    int last_selected() const { return last_selected_; }

    // Visibility, the Outliner's toggle: a view of the session like the free view, not an edit
    // (not saved, no undo, no " *"). A hidden model, and every model under it in the scene tree,
    // is neither drawn nor picked nor framed (Home, F), but still simulated: the bake and the
    // export are those of the document. Hiding a model deselects what it hides.
    bool hidden(int model) const { return hidden_.count(model) > 0; }
    bool shown(int model) const;
    void set_hidden(int model, bool hidden);
    // Every model not shown (hidden, or under a hidden model), for the view to leave out.
    std::set<int> hidden_models() const;

    // The Model Interface's change of one field (model_fields.hpp) to every model in `models`
    // (the selection): one undoable edit, each model keeping its other properties. True when
    // nothing needed changing; false (with why in `error`) and no change when it cannot.
    bool set_field(const std::set<int> &models, ModelField field, const Model &from, std::string *error = nullptr);
    // The Outliner's rename, one undoable edit. Surrounding spaces are dropped; an empty name or
    // another model's is refused with a message that says so, and nothing changes.
    bool rename_model(int index, const std::string &name, std::string *error = nullptr);

    // Models (model_edits.hpp, docs/manual.md "Adding, duplicating and deleting models"), each
    // one undoable edit of the whole document; `message` says what happened (for the status
    // line) or why nothing did. Not during a drag. Add: a model of the mesh `id` on the asset
    // path, or of a mesh file (OBJ, PLY, STL, glTF; named relative to the document when under
    // its folder, else absolutely), named after it (unique, Blender's "cube.001"), with the
    // default material, keyed at t = 0 where the view looks (the free view's pivot, else the
    // camera's view at the scene's depth), and selected. Duplicate: the selected models and what
    // hangs under them, each copy beside its original (copy_distance() along +x at every key),
    // the copies selected. Delete: the selected models and every model under them.
    bool add_model_from_asset(const std::string &id, std::string &message);
    bool add_model_from_file(const std::filesystem::path &file, std::string &message);
    bool duplicate_selected(std::string &message);
    bool delete_selected(std::string &message);
    // What delete_selected() would remove: the selection and everything under it.
    std::set<int> models_to_delete() const;

    EditMode mode() const { return mode_; }
    void set_mode(EditMode mode) { mode_ = mode; }

    // A drag with `button` over a viewport `viewport_height` pixels tall: the camera in Camera
    // mode, else every selected model. The preview shows in frame(); end_drag() makes it one
    // undoable edit, of the keyframe at the current time, or of a new keyframe there.
    void begin_drag(DragButton button, int viewport_height);
    void update_drag(glm::dvec2 delta);
    void end_drag();
    void cancel_drag() { drag_.reset(); }
    // While models are turned: which of them their joint range stops (joint_clamp.hpp), for a
    // tooltip; "" when none is. take_joint_note(): the same for the drag that ended last, once.
    std::string joint_note() const;
    std::string take_joint_note() { return std::exchange(ended_joint_note_, std::string()); }
    bool dragging() const { return drag_.has_value(); }
    glm::dvec2 drag_delta() const { return drag_ ? drag_->delta : glm::dvec2(0.0); } // pixels
    // The transform gizmo (gizmo.hpp) in a view of the shown frame `width` x `height` pixels:
    // at the last selected model as the frame shows it (following a drag), none in Camera mode,
    // with nothing selected, or while playing.
    GizmoView gizmo_view(int width, int height) const;
    std::optional<Gizmo> gizmo(const GizmoView &view) const;
    // A left press at `cursor` (the view's pixels): on a handle, a drag of it begins and this is
    // true; update_drag() takes the cursor's offset from `cursor`, and the drag previews, cancels
    // and ends (one undoable edit) as the other drags do. CTRL (set_snap) snaps it.
    bool begin_gizmo_drag(glm::dvec2 cursor, const GizmoView &view);
    GizmoHandle gizmo_handle() const { return drag_ && drag_->gizmo ? drag_->gizmo->handle : GizmoHandle::None; }
    void set_snap(bool on);
    // A model's state at the current time as a transformation starts from it: its key here,
    // else its interpolated or simulated state (with a drag in progress applied).
    ModelState state_at_time(int model) const;
    // Keys these models' states at the current time (a new keyframe if there is none), one
    // undoable edit: the Transform fields' change. False (why in `error`) and no change if refused.
    bool key_states(const std::vector<std::pair<int, ModelState>> &states, std::string *error = nullptr);
    // The scroll wheel in Camera mode: moves the camera along its view, one undoable edit.
    void scroll(double notches);

    // What to draw: every model and the camera at the current time (within what is baked), with
    // a drag in progress applied.
    Frame frame() const;

    // The free view (free_view.hpp): looking around apart from the animated camera. None of
    // it is an edit: no undo entry, no keyframe, nothing exported. Turned on the first time, it
    // starts where the animated camera is; later it comes back where it was left.
    bool free_view() const { return free_view_on_; }
    void set_free_view(bool on);
    const FreeView &view() const { return view_; }
    void set_view(const FreeView &view);
    // Home (every model) and F (the selected ones; false when none is): the free view turns
    // on and fits their bounding spheres in a viewport of this aspect (width / height).
    bool frame_models(bool selected_only, double aspect);
    // Every shown model's bounding sphere in the world at the current time (empties have none).
    std::vector<Sphere> model_spheres(bool selected_only) const;
    // What the window draws and picks in: frame(), seen through the free view when it is on.
    Frame shown_frame() const;

    // Applies an edit, records it for undo and re-bakes from the earliest time it affects.
    // Returns false (with the reason in `error`) and changes nothing when it cannot be applied.
    bool perform(std::unique_ptr<Edit> edit, std::string *error = nullptr);
    bool set_settings(const Settings &settings, std::string *error = nullptr);
    bool set_model(int index, const Model &model, std::string *error = nullptr);
    bool delete_keyframe(std::int64_t time_ms, std::string *error = nullptr);

    // Pairs of models the backend found overlapping in what is baked (each once; the view flags
    // them), and the fix (overlap_fix.hpp): lifts one of pair `index` out of the other the
    // shortest way, one undoable edit (of the whole document, so Undo takes it back at any time).
    const std::vector<ani_overlap> &overlaps() const { return timeline_->overlaps(); }
    std::set<int> overlapping_models() const;
    bool lift_out(std::size_t index, std::string *error = nullptr);

    // Motion paths (motion_paths.hpp), none of it an edit: with paths on (p), the selected
    // models show theirs, and a model pinned on shows its own always. While models are dragged
    // their paths follow the drag: the dragged document is baked on its own (preview_some(),
    // between frames, never blocking the drag), and the paths show as far as it has baked.
    bool paths_on() const { return paths_on_; }
    void set_paths_on(bool on) { paths_on_ = on; }
    bool path_pinned(int model) const { return pinned_paths_.count(model) > 0; }
    void pin_path(int model, bool on);
    std::vector<int> path_models() const;
    std::vector<MotionPath> motion_paths() const;
    // Bakes the drag in progress on for about `budget` seconds; true while more remains.
    bool preview_some(double budget);
    // How far the drag's own bake has gone (seconds; -1 without one).
    double preview_baked_until() const { return preview_ ? preview_->baked_until() : -1.0; }
    // Changes each time the drag's document changes.
    std::uint64_t preview_version() const { return preview_version_; }
    // Undo and redo at the current keyframe (its own stack, then the document's).
    bool undo();
    bool redo();
    bool can_undo() const { return history_.can_undo(history_key()); }
    bool can_redo() const { return history_.can_redo(history_key()); }

    // Swaps the physics backend while the program runs (not an edit of the document: the file
    // keeps its own choice). A backend that fails leaves the previous one and says why.
    bool use_backend(const std::string &id, std::string &error);
    std::string backend() const { return timeline_->backend_id(); }

    struct ExportResult {
        bool ok = false;
        std::filesystem::path path;
        std::string message; // what happened, for the status line
    };
    // Saves to the opened .ani, else to animations/new.ani under the working folder; never
    // over a file the user did not open (a fresh name is chosen and said). A failed save leaves
    // the old file and says why.
    ExportResult export_animation();
    // The File menu (file_menu.hpp). An .ani this session writes to (opened or saved as): Save
    // (CTRL+S) exports there; without one (a .lua scene, New) Save asks where, as Save As.
    bool saves_to_path() const { return export_to_path_; }
    // Save As: writes the animation to the .ani `target` (atomically, as export does); from
    // then on the document is that file (title, Save, autosave). A failure changes nothing.
    ExportResult save_as(const std::filesystem::path &target);
    // New: the .lua scene `scene` as a new, untitled animation (Save asks where). On failure
    // the current document stays, as open().
    bool new_from_scene(const std::filesystem::path &scene, std::string &error);
    bool dirty() const { return dirty_; }
    // "animator - drop.ani *": the file, and a mark for unsaved changes.
    std::string title() const;

    // Keys familiar from Blender and Maya (docs/manual.md, Keys), each returning what the status
    // line says. I (Blender's Insert Keyframe, Maya's S): keys the selected models at the
    // current time where they are now (keyed, interpolated or simulated; the bake goes on to
    // that time first), or the camera when nothing is selected: one undoable
    // edit. ALT+I: deletes the selected models' (or the camera's) keys at the current time.
    std::string insert_keys(bool *ok = nullptr);
    std::string delete_keys_here(bool *ok = nullptr);
    // A (select all shown models), ALT+A (select none); H (hide the selected), ALT+H (show all).
    // Views, not edits.
    void select_all();
    void select_none() { click(-1, false); }
    int hide_selected();
    int show_all();

  private:
    struct Drag {
        DragButton button;
        int viewport_height;
        glm::dvec2 delta{0.0};
        std::vector<std::pair<int, ModelState>> models; // at the start
        CameraState camera;                              // at the start
        double metres_per_pixel;
        struct OnGizmo {
            Gizmo gizmo;
            GizmoView view;
            GizmoHandle handle = GizmoHandle::None;
            glm::dvec2 start{0.0};
            bool snap = false;
            GizmoChange change;               // for the drag so far
            std::vector<glm::dmat3> parents; // each dragged model's parent (world, linear)
        };
        std::optional<OnGizmo> gizmo; // a gizmo handle's drag, else a button's (drag_model)
    };
    // Model `i` of the drag, as the drag so far leaves it.
    ModelState dragged_state(const Drag &d, size_t i) const;
    JointClamp dragged_clamp(const Drag &d, size_t i) const; // and which angles a joint held
    void update_gizmo_change();
    std::int64_t history_key() const;
    // open(): reads `file` as the document at `path`.
    bool load(const std::filesystem::path &file, const std::filesystem::path &path, std::string &error);
    void changed();
    // After undo or redo: the timeline takes the document back.
    void follow_document();
    // After an edit, an undo or a redo that changed the list of models (its names before are
    // `names`): the meshes, the selection, the hidden and pinned models follow the models by
    // name (unique in a document), and the timeline takes the new meshes.
    void follow_models(const std::vector<std::string> &names);
    std::vector<std::string> model_names() const;
    // The mesh of id `id` (as the document names it), loaded once; null with a warning in
    // `error` when it cannot be found or read.
    std::shared_ptr<const Mesh> mesh_of(const std::string &id, std::string *error);
    bool add_model(const std::string &mesh, std::string &message);

    ModelState state_now(int model, const Frame &frame) const;
    std::unique_ptr<Edit> transform_edit(const std::vector<std::pair<int, ModelState>> &models,
                                         const std::optional<CameraState> &camera) const;
    double view_depth(const Frame &frame) const;

    Environment &env_;
    Document doc_, saved_;
    std::filesystem::path path_;   // the opened file, or the last one exported to
    bool export_to_path_ = false;  // path_ is an .ani this session may write
    std::unique_ptr<Timeline> timeline_;
    std::vector<std::shared_ptr<const Mesh>> meshes_;
    std::map<std::string, std::shared_ptr<const Mesh>> mesh_cache_; // by id, for Add and undo
    std::vector<std::string> warnings_;
    EditHistory history_;
    std::uint64_t version_ = 0;
    bool dirty_ = false;

    std::int64_t time_ms_ = 0;
    bool playing_ = false;
    double play_from_ = 0.0, play_wall_ = 0.0;
    double chunk_ = 0.25; // seconds of animation per bake slice, adapted to the budget
    std::string bake_error_;

    std::set<int> selection_;
    int last_selected_ = -1;
    std::set<int> hidden_; // models whose own visibility is off
    EditMode mode_ = EditMode::Camera;
    std::optional<Drag> drag_;
    std::string ended_joint_note_;
    bool free_view_on_ = false, view_started_ = false;
    bool paths_on_ = false;
    std::set<int> pinned_paths_;
    // The document with the drag in progress applied, and its own timeline (motion paths).
    std::unique_ptr<Timeline> preview_;
    std::optional<Document> preview_doc_;
    bool preview_stale_ = false;
    std::uint64_t preview_version_ = 0;
    std::optional<Document> dragged_document() const;
    FreeView view_;
};

} // namespace animator
